#pragma once

#include "mocap/model/marker_set.h"
#include "mocap/base/job_control.h"
#include "mocap/model/point_cloud.h"
#include "mocap/tracking/point_tracker.h"
#include "mocap/tracking/template_labelling.h"

namespace mocap {

struct TrackOptions
{
  TrackerOptions tracker;
  LabellingOptions labelling;
  /// Re-track the unlabelled markers' samples as points (true), or take each valid run of an
  /// unlabelled marker as a fragment as the capture software delivered it (false).
  bool retrack = true;
};

struct TrackReport
{
  Eigen::Index labelledMarkers = 0;    ///< input markers kept by their label
  Eigen::Index unlabelledMarkers = 0;  ///< input markers treated as unlabelled points
  Eigen::Index fragments = 0;          ///< fragments given to the labeller
  Eigen::Index labelledFragments = 0;
  Eigen::Index unlabelledFragments = 0;
  Eigen::Index labelledSamples = 0;    ///< fragment samples that got a label
  Eigen::Index unlabelledSamples = 0;  ///< fragment samples left on Unlabeled markers
  double gate = 0.0;                   ///< tracking gate (0 when nothing was re-tracked)
  Eigen::Index anchorFrame = -1;
  double scale = 1.0;  ///< template-to-data scale
  bool labelled = false;  ///< a marker set (given or from the take's labelled markers) was used
};

/// Tracks and labels a take (paper §2): its unlabelled markers (isUnlabelledLabel) are re-tracked
/// into fragments (trackPoints; an automatic gate is measured on all the take's markers) or taken run by run, then labelled with `set` (labelFragments),
/// which also joins fragments into the gaps of the take's own labelled markers. With no `set`,
/// the take's labelled markers form it (markerSetFromTake); with neither, the fragments come back
/// unlabelled. The result has the set's labels first (with the take's samples of those labels),
/// then the take's other labelled markers, then fragments left unlabelled, packed
/// (appendFragments); rate, first frame, units, analog data, events and parameters are kept.
/// The set's units are converted to the take's. Throws InvalidArgument as the steps do.
/// O(tracking + labelling) (see trackPoints, labelFragments).
/// `job` is checked once a tracked frame and between the steps.
[[nodiscard]] Take trackTake(const Take& take, const MarkerSet* set, const TrackOptions& options = {},
                             TrackReport* report = nullptr, const JobControl& job = {});

/// The same for raw points (a CSV of points): tracked, then labelled with `set` when given.
[[nodiscard]] Take trackPointCloud(const PointCloud& cloud, const MarkerSet* set, const TrackOptions& options = {},
                                   TrackReport* report = nullptr);

} // namespace mocap
