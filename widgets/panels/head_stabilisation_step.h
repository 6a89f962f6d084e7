#pragma once

#include "panels/cleaning_step.h"

class QLineEdit;
class QSpinBox;

namespace mocap::ui {

class TakeDocument;

/// Head stabilisation (mocap::estimateHeadMotion + removeHeadMotion) as a cleaning step: the
/// head-mounted reference markers (default: labels starting "root"/"head", or the selection) and
/// the reference frame. Apply moves every marker into the head frame as one undoable edit, so
/// neighbour-based fills and smoothing then see facial motion only.
class HeadStabilisationStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit HeadStabilisationStep(TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;
  /// Replaces the reference markers by these labels (comma separated).
  void setReferenceLabels(const QString& labels);

private:
  void guessReference();
  void useSelection();

  TakeDocument& m_document;
  QLineEdit* m_labels = nullptr;
  QSpinBox* m_frame = nullptr;
};

} // namespace mocap::ui
