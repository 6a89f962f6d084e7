#pragma once

#include "panels/cleaning_step.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QSpinBox;

namespace mocap::ui {

/// Gap filling (mocap::fillGaps): method, neighbours, the longest gap to fill (in seconds and
/// frames of the take's rate), extrapolation at the ends and the least a marker must be seen.
/// The defaults are mocap::FillOptions', which never invent much: half a second, interior gaps,
/// markers seen in a fifth of the take. With a frame range selected on the curves, only gaps
/// overlapping it are filled, so technicians can choose the method gap by gap. Gaps left open are
/// counted by cause in the summary and listed with why (click one to go there).
class GapFillStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit GapFillStep(class TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;
  void showResult(const StepResult& result) override;
  void addToPreset(CleanOptions& options) const override;
  /// "11 gaps filled, 180 samples; 20 left open: M1, frames 5–90 (86): over the 0.5 s limit; …".
  [[nodiscard]] QString appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const override;
  bool loadPreset(const CleanOptions& options) override;

  /// The longest gap to fill in seconds; 0 = unlimited. Shown in frames too.
  [[nodiscard]] double maxGapSeconds() const { return m_maxGapSeconds; }
  void setMaxGapSeconds(double seconds);

  /// The parameters, without the selection (a preset is for any take): also the safety rules
  /// (longest gap, extrapolation, least seen) the Gaps dock obeys.
  [[nodiscard]] FillOptions currentOptions() const;

private:
  [[nodiscard]] double frameRate() const;
  void showMaxGap();

  TakeDocument& m_document;
  QComboBox* m_method = nullptr;
  QSpinBox* m_neighbours = nullptr;
  QDoubleSpinBox* m_maxGapSecondsBox = nullptr;
  QSpinBox* m_maxGapFrames = nullptr;
  QCheckBox* m_extrapolate = nullptr;
  QSpinBox* m_minValid = nullptr;
  QListWidget* m_open = nullptr;
  double m_maxGapSeconds = 0.5;
};

} // namespace mocap::ui
