#pragma once

#include "mocap/base/error.h"
#include "mocap/layout/layout_frames.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/model/marker_pairs.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// A request that names something its takes do not have: a marker pattern nothing matches, a key
/// pose outside its take or given twice. The caller's words were wrong, not the data (the CLI
/// answers it as a usage error naming the option, the panel beside the field).
class LayoutRequestError : public InvalidArgument
{
public:
  enum class Field { Markers, Exclude, KeyPoses };
  LayoutRequestError(Field field, const std::string& message) : InvalidArgument(message), m_field(field) {}
  [[nodiscard]] Field field() const { return m_field; }

private:
  Field m_field;
};

/// One key pose as a user names it: a frame number as take `take` (0-based) counts them.
struct KeyPose
{
  std::size_t take = 0;
  long long frame = 0;
};

/// Key poses written as the CLI and the panel take them: "auto" (or blank) for none given, else
/// comma-separated frame numbers as the first take counts them, or TAKE:FRAME with TAKE from 1.
/// Throws LayoutRequestError(KeyPoses) for anything else. O(length).
[[nodiscard]] std::vector<KeyPose> parseKeyPoses(std::string_view text);

/// Everything a marker layout plan is made from, beside the takes themselves: what `mocap pfa`
/// reads from its options and the studio's Layout planning panel from its form.
struct LayoutRequest
{
  /// Head reference markers: head motion is removed with them and they are never planned over.
  std::vector<std::string> stabilizeLabels;
  /// Globs (`*`, `?`) over the first take's labels choosing the planned markers; empty: every
  /// marker but the reference markers and unlabelled points (defaultPlannedLabels).
  std::vector<std::string> markerPatterns;
  /// Globs of markers left out of the plan.
  std::vector<std::string> excludePatterns;
  /// Key poses of the blendshape basis; empty: chosen automatically (extreme frames).
  std::vector<KeyPose> keyPoses;
  /// A marker-set or pairs file with the mirror pairs; empty: pairs detected on the neutral frame.
  std::string pairsFile;
  /// Method, PFA parameters, random baseline count.
  LayoutPlanOptions plan;
};

/// A finished plan with what it was planned on.
struct LayoutResult
{
  LayoutFrames frames;
  MarkerSymmetry symmetry;
  std::optional<PairDetection> detection;  ///< set when the pairs were detected, not read
  std::vector<std::string> stabilizeLabels;
  LayoutPlan plan;

  /// The labels of planned markers (indices into frames.labels, as ScoredLayout::markers), in that
  /// order. O(#markers).
  [[nodiscard]] std::vector<std::string> labelsOf(const std::vector<Eigen::Index>& markers) const;
  /// The layout the plan's method chose with `markerCount` markers, or nullptr. O(#sizes).
  [[nodiscard]] const ScoredLayout* layout(Eigen::Index markerCount) const;
  /// What a capture with `layout` records: its markers plus the head reference markers; with
  /// nullptr, every planned marker plus the reference markers. O(#markers).
  [[nodiscard]] std::vector<std::string> captureLabels(const ScoredLayout* layout) const;
};

/// The one marker layout planning (Wellein et al. 2007) that `mocap pfa` and the studio both run:
/// resolves the planned markers from the patterns, collects the frames (collectLayoutFrames, head
/// motion removed), takes the key poses and the mirror pairs (from the file, or detectLayoutPairs
/// with the same key poses), and plans (planMarkerLayout). The first take names the markers and
/// numbers the frames. Cost: collectLayoutFrames + planMarkerLayout.
/// Throws LayoutRequestError for a pattern that matches no marker or a bad key pose, and as the
/// functions it calls (InvalidArgument, FormatError, IoError).
[[nodiscard]] LayoutResult planLayout(const std::vector<Take>& takes, const LayoutRequest& request,
                                      const RunControl& control = {});

/// The labels among `labels` that match any of the glob `patterns`, in `labels` order.
/// Throws LayoutRequestError(field) naming a pattern that matches nothing.
/// O(#labels · #patterns · length).
[[nodiscard]] std::vector<std::string> labelsMatching(const std::vector<std::string>& labels,
                                                      const std::vector<std::string>& patterns,
                                                      LayoutRequestError::Field field);

} // namespace mocap
