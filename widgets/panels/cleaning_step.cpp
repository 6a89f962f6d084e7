#include "panels/cleaning_step.h"

#include <QComboBox>
#include <QCoreApplication>

#include <algorithm>

namespace mocap::ui {

PatchCounts countPatches(const std::vector<SamplePatch>& patches)
{
  PatchCounts counts;
  std::vector<Eigen::Index> markers;
  for (const SamplePatch& patch : patches) {
    counts.samples += static_cast<int>(patch.size());
    markers.push_back(patch.marker);
  }
  std::sort(markers.begin(), markers.end());
  counts.markers = static_cast<int>(std::unique(markers.begin(), markers.end()) - markers.begin());
  return counts;
}

void tipFollowsCurrentItem(QComboBox& combo)
{
  const auto show = [&combo] { combo.setToolTip(combo.currentData(Qt::ToolTipRole).toString()); };
  show();
  QObject::connect(&combo, qOverload<int>(&QComboBox::currentIndexChanged), &combo, show);
}

QString samplesOnMarkers(const PatchCounts& counts, const QString& one, const QString& many)
{
  return (counts.samples == 1 ? one : many.arg(counts.samples)) +
         (counts.markers == 1 ? QCoreApplication::translate("CleaningStep", " on 1 marker")
                              : QCoreApplication::translate("CleaningStep", " on %1 markers").arg(counts.markers));
}

QString CleaningStep::appliedSummary(const std::vector<SamplePatch>& applied, const StepResult& result) const
{
  (void)result;
  return samplesOnMarkers(countPatches(applied), QCoreApplication::translate("CleaningStep", "1 sample changed"),
                          QCoreApplication::translate("CleaningStep", "%1 samples changed"));
}

} // namespace mocap::ui
