#pragma once

#include "panels/cleaning_step.h"

#include "mocap/base/length_unit.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace mocap::ui {

class ViewState;

/// Smoothing (mocap::smoothTake): method and the parameters that method uses — B-spline degree
/// and knot spacing, Butterworth cutoff, smoothing-spline degree, Savitzky–Golay window. The
/// summary says how far the samples would move: RMS and largest change of position, in the
/// display unit, and where the largest is.
class SmoothingStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit SmoothingStep(QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;
  /// Unit of the change the summary reports (the take keeps its own units).
  void setDisplayUnit(LengthUnit unit) { m_displayUnit = unit; }
  /// Follows `state`'s display unit from now on.
  void observe(const ViewState& state);
  void addToPreset(CleanOptions& options) const override;
  /// "12 400 samples smoothed on 37 markers".
  [[nodiscard]] QString appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const override;
  bool loadPreset(const CleanOptions& options) override;

private:
  [[nodiscard]] SmoothOptions currentOptions() const;
  void updateEnabled();

  QComboBox* m_method = nullptr;
  QSpinBox* m_degree = nullptr;
  QDoubleSpinBox* m_knotSpacing = nullptr;
  QDoubleSpinBox* m_cutoff = nullptr;
  QSpinBox* m_window = nullptr;
  LengthUnit m_displayUnit = LengthUnit::Millimetre;
};

} // namespace mocap::ui
