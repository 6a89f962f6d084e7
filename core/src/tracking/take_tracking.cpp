#include "mocap/tracking/take_tracking.h"

#include "mocap/base/error.h"
#include "mocap/model/marker_points.h"
#include "mocap/tracking/fragment_joining.h"

#include <algorithm>
#include <cmath>

namespace mocap {

namespace {

MarkerSet inUnits(MarkerSet set, LengthUnit units)
{
  set.neutral *= millimetresPer(set.units) / millimetresPer(units);
  set.units = units;
  return set;
}

std::vector<Fragment> fragmentsToLabel(const Take& take, const std::vector<Eigen::Index>& unlabelled,
                                       const TrackOptions& options, TrackReport& report, const JobControl& job)
{
  if (!options.retrack)
    return fragmentsOfMarkers(take, unlabelled);
  TrackerOptions tracker = options.tracker;
  if (tracker.maxSpeed == 0.0) {
    // Measure the spacing on every marker (model outputs are no positions): a few unlabelled
    // points alone do not show it.
    const double gate = automaticGate(pointCloudFromTake(take, markerPoints(take)));
    tracker.maxSpeed = std::isfinite(gate) ? gate : 0.0;
  }
  TrackingResult tracked = trackPoints(pointCloudFromTake(take, unlabelled), tracker, job);
  report.gate = tracked.gate;
  return std::move(tracked.fragments);
}

// Labels `fragments` into `output` (the set's labels first) and appends the rest.
void labelAndAppend(Take& output, const std::vector<Fragment>& fragments, const MarkerSet* set,
                    const TrackOptions& options, TrackReport& report)
{
  report.fragments = static_cast<Eigen::Index>(fragments.size());
  std::vector<Eigen::Index> left;
  if (set) {
    const LabellingResult result = labelFragments(output, fragments, *set, options.labelling);
    report.anchorFrame = result.anchorFrame;
    report.scale = result.scale;
    for (std::size_t k = 0; k < fragments.size(); ++k) {
      const bool labelled = result.labelOf[k] >= 0;
      (labelled ? report.labelledFragments : report.unlabelledFragments) += 1;
      (labelled ? report.labelledSamples : report.unlabelledSamples) += fragments[k].length();
      if (!labelled)
        left.push_back(static_cast<Eigen::Index>(k));
    }
  } else {
    for (std::size_t k = 0; k < fragments.size(); ++k) {
      left.push_back(static_cast<Eigen::Index>(k));
      report.unlabelledSamples += fragments[k].length();
    }
    report.unlabelledFragments = report.fragments;
  }
  (void)appendFragments(output, fragments, left);
}

} // namespace

Take trackTake(const Take& take, const MarkerSet* set, const TrackOptions& options, TrackReport* reportOut,
               const JobControl& job)
{
  job.checkpoint(0.0);
  TrackReport report;
  std::vector<Eigen::Index> labelled;
  std::vector<Eigen::Index> unlabelled;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    (isUnlabelledLabel(take.label(m)) ? unlabelled : labelled).push_back(m);
  report.labelledMarkers = static_cast<Eigen::Index>(labelled.size());
  report.unlabelledMarkers = static_cast<Eigen::Index>(unlabelled.size());

  std::optional<MarkerSet> own;
  if (set) {
    own = inUnits(*set, take.units());
  } else if (std::any_of(labelled.begin(), labelled.end(), [&](Eigen::Index m) { return take.valid().col(m).any(); })) {
    own = markerSetFromTake(take);
  }
  report.labelled = own.has_value();

  std::vector<std::string> labels = own ? own->labels : std::vector<std::string>{};
  std::vector<std::pair<Eigen::Index, Eigen::Index>> copies;  // (input marker, output marker)
  for (const Eigen::Index m : labelled) {
    const auto it = std::find(labels.begin(), labels.end(), take.label(m));
    if (it == labels.end()) {
      labels.push_back(take.label(m));
      copies.emplace_back(m, static_cast<Eigen::Index>(labels.size()) - 1);
    } else {
      copies.emplace_back(m, static_cast<Eigen::Index>(it - labels.begin()));
    }
  }
  Take output(labels, take.frameCount(), take.frameRate());
  output.setFirstFrame(take.firstFrame());
  output.setUnits(take.units());
  output.analog() = take.analog();
  output.events() = take.events();
  output.parameters() = take.parameters();
  for (const auto& [from, to] : copies)
    copyMarker(take, from, output, to);

  const std::vector<Fragment> fragments = fragmentsToLabel(take, unlabelled, options, report, job.part(0.0, 0.7));
  job.checkpoint(0.7);
  labelAndAppend(output, fragments, own ? &*own : nullptr, options, report);
  if (reportOut)
    *reportOut = report;
  return output;
}

Take trackPointCloud(const PointCloud& cloud, const MarkerSet* set, const TrackOptions& options, TrackReport* reportOut)
{
  TrackReport report;
  TrackingResult tracked = trackPoints(cloud, options.tracker);
  report.gate = tracked.gate;
  report.labelled = set != nullptr;
  Take output(set ? set->labels : std::vector<std::string>{}, cloud.frameCount(), cloud.frameRate);
  if (set)
    output.setUnits(set->units);
  labelAndAppend(output, tracked.fragments, set, options, report);
  if (reportOut)
    *reportOut = report;
  return output;
}

} // namespace mocap
