#include "mocap/cleaning/clean_pipeline.h"

#include "mocap/base/error.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/sample_patch.h"

namespace mocap {

namespace {

Eigen::Index patchSamples(const std::vector<SamplePatch>& patches)
{
  Eigen::Index count = 0;
  for (const SamplePatch& p : patches)
    count += static_cast<Eigen::Index>(p.size());
  return count;
}

} // namespace

CleanReport cleanTake(Take& take, const CleanOptions& options, const JobControl& job)
{
  CleanReport report;
  job.checkpoint(0.0);
  report.modelOutputs = modelOutputPoints(take);
  if (!options.stabilizeLabels.empty()) {
    report.stabilizeMarkers = markerIndices(take, options.stabilizeLabels);
    report.headMotion = estimateHeadMotion(take, report.stabilizeMarkers);
    for (bool known : report.headMotion->known)
      report.unknownHeadPoses += known ? 0 : 1;
    removeHeadMotion(take, *report.headMotion);
  }
  if (options.spikes) {
    report.spikes = detectSpikes(take, *options.spikes, job.part(0.0, 0.3));
    std::vector<SamplePatch> repairs = replaceSpikes(take, report.spikes);
    report.repairedSamples = patchSamples(repairs);
    applyPatches(take, std::move(repairs));
  }
  if (options.fill) {
    job.checkpoint(0.3);
    FillResult filled = fillGaps(take, *options.fill, job.part(0.3, 0.6));
    report.filledSamples = patchSamples(filled.patches);
    report.gaps = std::move(filled.gaps);
    applyPatches(take, std::move(filled.patches));
  }
  if (options.smooth) {
    job.checkpoint(0.6);
    report.smoothedSamples = smoothTakeInPlace(take, *options.smooth, job.part(0.6, 1.0));
  }
  job.checkpoint(1.0);
  if (report.headMotion && !options.keepStabilized)
    restoreHeadMotion(take, *report.headMotion);
  return report;
}

} // namespace mocap
