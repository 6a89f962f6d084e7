#pragma once

#include <QToolButton>

namespace mocap::ui {

class TakeDocument;

/// The status bar's "⚠ 3 warning(s)" (or "⚠ Incomplete: …") for the open take's reader
/// warnings, hidden when there are none; clicking it lists all of them (ReadWarningsDialog).
class ReadWarningsButton final : public QToolButton
{
  Q_OBJECT

public:
  explicit ReadWarningsButton(const TakeDocument& document, QWidget* parent = nullptr);

  /// Shows the open take's warnings; with `askToAcknowledge` (data is missing), opens the list
  /// at once.
  void showWarnings(bool askToAcknowledge);
  /// The dialog listing every warning (modal).
  void openList();

private:
  const TakeDocument& m_document;
};

} // namespace mocap::ui
