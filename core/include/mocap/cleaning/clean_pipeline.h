#pragma once

#include "mocap/base/job_control.h"

#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/cleaning/smoothing.h"
#include "mocap/cleaning/spike_detection.h"
#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// Which cleaning steps run, in the fixed order stabilize → spikes → fill → smooth.
/// A step whose options are empty is skipped. The fill defaults (FillOptions) leave gaps longer
/// than 0.5 s, edge gaps and rarely seen markers open; CleanReport::gaps says which and why.
struct CleanOptions
{
  std::vector<std::string> stabilizeLabels;  ///< head reference markers; empty: no stabilization
  bool keepStabilized = false;               ///< false: head motion is put back after cleaning
  std::optional<SpikeOptions> spikes = SpikeOptions{};
  std::optional<FillOptions> fill = FillOptions{};
  std::optional<SmoothOptions> smooth = SmoothOptions{};
};

/// What the pipeline did, for the `--report` JSON and the studio's review lists.
struct CleanReport
{
  std::vector<Eigen::Index> stabilizeMarkers;
  Eigen::Index unknownHeadPoses = 0;     ///< frames where the head pose had to be interpolated or was unknown
  std::optional<HeadMotion> headMotion;  ///< when stabilized (e.g. for the BVH root)
  std::vector<SpikeFlag> spikes;
  /// Samples the repair replaced (flags on a whole valid run or an invalid sample are not repaired).
  Eigen::Index repairedSamples = 0;
  std::vector<GapFillReport> gaps;
  Eigen::Index filledSamples = 0;
  Eigen::Index smoothedSamples = 0;
  /// Model outputs (marker_points.h) every step left untouched, ascending.
  std::vector<Eigen::Index> modelOutputs;
};

/// Runs the steps on `take` in place, on its marker points only: model outputs keep every byte. Throws InvalidArgument for an unknown stabilization label.
/// Reports progress through `job` (spikes, fill and smooth each their part) and throws
/// JobCancelled at the next checkpoint once cancelled, leaving the take part-cleaned: a caller
/// that must not keep that works on a copy.
/// Cost: the sum of the steps (each O(#frames · #markers) up to its neighbour search).
CleanReport cleanTake(Take& take, const CleanOptions& options, const JobControl& job = {});

} // namespace mocap
