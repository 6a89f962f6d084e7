#pragma once

#include "panels/cleaning_step.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QListWidget;

namespace mocap::ui {

class TakeDocument;

/// Bad-point detection (mocap::detectSpikes) and replacement: method, factor (paper) or
/// threshold (robust), whether to look again until nothing new, and the list of flags to step through; unchecking a flag keeps that
/// sample as it is when applying.
class SpikeStep final : public CleaningStep
{
  Q_OBJECT

public:
  explicit SpikeStep(TakeDocument& document, QWidget* parent = nullptr);

  [[nodiscard]] QString title() const override;
  [[nodiscard]] StepJob job() const override;
  [[nodiscard]] std::vector<SamplePatch> patchesToApply(const Take& take, const StepResult& result) const override;
  void showResult(const StepResult& result) override;
  /// Remembers the repaired samples, so the next detection says which flags sit beside them.
  void applied(const std::vector<SamplePatch>& patches) override;
  /// "415 samples repaired on 37 markers".
  [[nodiscard]] QString appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const override;
  void addToPreset(CleanOptions& options) const override;
  bool loadPreset(const CleanOptions& options) override;

private:
  [[nodiscard]] SpikeOptions currentOptions() const;

  std::vector<SamplePatch> m_repairs;  // the last Apply's, while the take still holds them
  TakeDocument& m_document;
  QComboBox* m_method = nullptr;
  QDoubleSpinBox* m_factor = nullptr;
  QDoubleSpinBox* m_threshold = nullptr;
  QCheckBox* m_settle = nullptr;
  QListWidget* m_flags = nullptr;
};

} // namespace mocap::ui
