#pragma once

#include <QToolButton>

namespace mocap::ui {

class TakeDocument;

/// The status bar's "⚠ 3 warning(s)" (or "⚠ Incomplete: …", "⚠ Wrong data: …") for the open
/// take's reader warnings, hidden when there are none; clicking it lists all of them
/// (ReadWarningsDialog), where data loss can be acknowledged (an undoable step on the take).
class ReadWarningsButton final : public QToolButton
{
  Q_OBJECT

public:
  explicit ReadWarningsButton(TakeDocument& document, QWidget* parent = nullptr);

  /// Shows the open take's warnings; with `askToAcknowledge` (data is missing or wrong), opens
  /// the list at once.
  void showWarnings(bool askToAcknowledge);
  /// The dialog listing every warning (modal).
  void openList();

private:
  TakeDocument& m_document;
};

} // namespace mocap::ui
