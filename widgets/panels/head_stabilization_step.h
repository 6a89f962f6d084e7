#pragma once

#include "panels/cleaning_step.h"

class QSpinBox;

namespace mocap::ui {

class ReferenceMarkersRow;
class TakeDocument;

/// Head stabilization (mocap::estimateHeadMotion + removeHeadMotion) as a cleaning step, with the
/// take's reference markers (TakeDocument::referenceMarkers, shown read only with a link to
/// their editor) and the reference frame. Apply moves every marker in every frame into the head
/// frame as one undoable edit, so neighbour-based fills and smoothing then see facial motion
/// only. It is a change of coordinates of the whole take: "selected markers only" and "selected
/// frame range only" do not apply to it (wholeTake()).
class HeadStabilizationStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit HeadStabilizationStep(TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] QString tabTitle() const override;
  [[nodiscard]] StepJob job() const override;
  [[nodiscard]] bool wholeTake() const override { return true; }
  // No addToPreset: the reference markers are the take's, not an option; File ▸ Save Cleaning
  // Preset… adds them only when asked to.

signals:
  /// The user asked to edit the reference markers (the main window opens the one editor).
  void editReferenceMarkersRequested();

private:
  TakeDocument& m_document;
  ReferenceMarkersRow* m_reference = nullptr;
  QSpinBox* m_frame = nullptr;
};

} // namespace mocap::ui
