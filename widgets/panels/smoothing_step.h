#pragma once

#include "panels/cleaning_step.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace mocap::ui {

/// Smoothing (mocap::smoothTake): method and the parameters that method uses — B-spline degree
/// and knot spacing, Butterworth cutoff, smoothing-spline degree, Savitzky–Golay window.
class SmoothingStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit SmoothingStep(QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;

private:
  void updateEnabled();

  QComboBox* m_method = nullptr;
  QSpinBox* m_degree = nullptr;
  QDoubleSpinBox* m_knotSpacing = nullptr;
  QDoubleSpinBox* m_cutoff = nullptr;
  QSpinBox* m_window = nullptr;
};

} // namespace mocap::ui
