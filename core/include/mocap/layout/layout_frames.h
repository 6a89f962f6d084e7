#pragma once

#include "mocap/model/take.h"

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace mocap {

struct LayoutFramesOptions
{
  /// Labels of the markers to plan a layout for; empty: defaultPlannedLabels(first take, stabilizeLabels).
  std::vector<std::string> markers;
  /// Head-mounted reference markers: when given, each take's head motion is removed with them
  /// (head_stabilization.h) before anything else, and they are never planned over.
  std::vector<std::string> stabilizeLabels;
  /// Each take is cut into consecutive blocks of this many seconds, and every holdoutEvery-th
  /// block (the last of each group) is held apart for testing: blocks rather than single frames,
  /// so test frames are not near-copies of training frames, and short ones, so the test frames
  /// show the same repertoire of expressions as the training frames.
  double blockSeconds = 1.0;
  int holdoutEvery = 5;
};

/// The frames a layout is planned on (Wellein et al. 2007 §1: rigid head motion removed first):
/// every frame of every take in which all planned markers are valid, in millimetres, one row of
/// 3·#markers values (x, y, z of marker 0, then marker 1, …), split into training and test rows.
struct LayoutFrames
{
  std::vector<std::string> labels;  ///< the planned markers
  Eigen::MatrixXd frames;           ///< #frames × 3·#markers
  std::vector<Eigen::Index> training;
  std::vector<Eigen::Index> test;
  std::vector<std::pair<std::size_t, Eigen::Index>> origin;  ///< (take, frame index) of each row
  Eigen::Index droppedFrames = 0;  ///< frames skipped because a planned marker was missing
  bool stabilized = false;

  [[nodiscard]] Eigen::Index markerCount() const { return static_cast<Eigen::Index>(labels.size()); }
  /// The row holding frame `frame` (0-based) of take `take`, or −1 when that frame was dropped.
  /// O(log #frames).
  [[nodiscard]] Eigen::Index rowOf(std::size_t take, Eigen::Index frame) const;
};

/// The markers a layout is planned over unless told otherwise: every marker point of `take`
/// (markerLabels: no model outputs) in take order except `excluded` (e.g. the head reference markers) and unlabelled points (isUnlabelledLabel:
/// fragments the tracker could not name, valid in too few frames to plan with).
/// O(#markers · #excluded).
[[nodiscard]] std::vector<std::string> defaultPlannedLabels(const Take& take,
                                                            const std::vector<std::string>& excluded);

/// Gathers LayoutFrames from takes sharing the planned markers (matched by label; other markers
/// may differ). Per take: copy, convert to mm, remove head motion when reference markers are given,
/// keep the frames where every planned marker is valid. With several takes, each later take is
/// rigidly aligned (Kabsch on its mean shape) to the first one's, so sessions share one head frame.
/// Not a paper equation (data preparation for §2). O(#frames · #markers) per take.
/// Throws InvalidArgument for no takes, fewer than two planned markers, an unknown or repeated
/// label, blockSeconds ≤ 0 or holdoutEvery < 2, a non-finite valid sample, fewer training frames than
/// 3·#markers + 1 (the PCA and the reconstruction model need more frames than features) or no test frame.
[[nodiscard]] LayoutFrames collectLayoutFrames(const std::vector<Take>& takes,
                                               const LayoutFramesOptions& options);

} // namespace mocap
