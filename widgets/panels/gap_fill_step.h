#pragma once

#include "panels/cleaning_step.h"

class QComboBox;
class QSpinBox;

namespace mocap::ui {

/// Gap filling (mocap::fillGaps): method, neighbours and the longest gap to fill. With a frame
/// range selected on the curves, only gaps overlapping it are filled, so technicians can choose
/// the method gap by gap.
class GapFillStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit GapFillStep(class TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;

private:
  TakeDocument& m_document;
  QComboBox* m_method = nullptr;
  QSpinBox* m_neighbours = nullptr;
  QSpinBox* m_maxGap = nullptr;
};

} // namespace mocap::ui
