#pragma once

#include "mocap/tracking/swap_detection.h"

#include <QObject>
#include <QString>

#include <optional>
#include <vector>

class QWidget;

namespace mocap::ui {

class TakeDocument;

/// The Label menu's work on the whole take, each run on a worker (ui::runJob: progress, Cancel)
/// and pushed as one undoable step: re-track and label the unlabelled points, and find label
/// swaps and repair the ones the user accepts in the review dialog.
class LabellingActions final : public QObject
{
  Q_OBJECT

public:
  /// `dialogParent` parents the progress, review and error dialogs.
  LabellingActions(TakeDocument& document, QWidget& dialogParent, QObject* parent = nullptr);

  /// Label ▸ Track and Label; a run that labels nothing pushes nothing.
  void trackAndLabel();
  /// The label swaps in the take; nullopt when cancelled or failed (the failure is shown).
  std::optional<std::vector<LabelSwap>> findSwaps();
  /// Label ▸ Fix Swaps…: finds the swaps, lets the user review them, repairs the accepted ones.
  void reviewSwaps();

signals:
  /// What a run did or why it did nothing, for the status bar.
  void message(const QString& text, int timeoutMs);

private:
  TakeDocument& m_document;
  QWidget& m_dialogParent;
};

} // namespace mocap::ui
