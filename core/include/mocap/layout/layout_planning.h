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

struct LayoutPlanOptions
{
  SelectionMethod method = SelectionMethod::Pfa;  ///< the method whose sets the plan recommends
  PfaOptions pfa;
  bool compare = true;                  ///< also score the other method and random sets at every size
  int randomSubsets = 20;               ///< random sets per size for the baseline mean
  Eigen::Index keyPoseCount = 10;       ///< automatic key poses (extreme frames)
  std::vector<Eigen::Index> keyFrames;  ///< rows of LayoutFrames::frames as key poses; empty: automatic
  SubsetErrorOptions errors;            ///< the reconstruction model and the greedy objective
};

/// One scored marker set.
struct ScoredLayout
{
  std::vector<Eigen::Index> markers;  ///< sorted indices into LayoutFrames::labels
  Eigen::Index k = 0;                 ///< PFA: the cluster count that produced it; 0 otherwise
  std::vector<double> unitFrequency;  ///< PFA: as PfaSelection
  double stability = 0.0;             ///< PFA: as PfaSelection
  double blendshapeError = 0.0;       ///< SubsetErrors::blendshapeError
  double reconstructionRmse = 0.0;    ///< SubsetErrors::reconstructionRmse, mm
};

/// One point of the error-vs-marker-count curve (Wellein et al. 2007 Fig. 2).
struct LayoutSize
{
  Eigen::Index markerCount = 0;
  std::optional<ScoredLayout> pfa;
  std::optional<ScoredLayout> greedy;
  int randomCount = 0;                 ///< random sets scored
  double randomBlendshapeError = 0.0;  ///< means over the random sets
  double randomReconstructionRmse = 0.0;

  /// The layout `method` chose at this size, or nullptr. O(1).
  [[nodiscard]] const ScoredLayout* layout(SelectionMethod method) const;
};

struct LayoutPlan
{
  SelectionMethod method = SelectionMethod::Pfa;
  std::vector<LayoutSize> sizes;       ///< ascending marker count; sizes no method reached are left out
  std::vector<PfaSelection> pfaSweep;  ///< the PFA result of every k (empty when PFA did not run)
  Eigen::Index pcaComponents = 0;
  double explainedVariance = 0.0;
  BlendshapeBasis basis;             ///< neutral and key-pose rows of the frames
  double motionRms = 0.0;            ///< SubsetErrors::motionRms
  Eigen::Index recommendedSize = 0;  ///< marker count at the knee of `method`'s curve; 0 if none
  std::string recommendationRule;    ///< how it was chosen, in words
  bool cancelled = false;

  /// The entry for `markerCount`, or nullptr. O(#sizes).
  [[nodiscard]] const LayoutSize* size(Eigen::Index markerCount) const;
};

/// The whole issue: PFA sweep over k (when the method is PFA or compare is on), each size's PFA set
/// being the k with the smallest training residual among those giving that size; greedy and random
/// sets (mean of randomSubsets) at every size (when the method is greedy or compare is on); both
/// errors of every set on the test frames against the full set (blendshape basis from the full set
/// with automatic or given key poses); the knee of the chosen method's curve (with the full set as
/// its last point). Progress covers the whole run; on cancellation the PFA selections done so far
/// are returned, without sizes, and cancelled = true.
/// Cost: sweepPfa + selectGreedy over all sizes + #sizes · (randomSubsets + 2) subset scorings,
/// each stage in parallel.
/// Throws InvalidArgument as sweepPfa and SubsetErrors, and for a key frame out of range.
[[nodiscard]] LayoutPlan planMarkerLayout(const LayoutFrames& frames, const MarkerSymmetry& symmetry,
                                          const LayoutPlanOptions& options = {},
                                          const JobControl& control = {});

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
                                      const JobControl& control = {});

/// The labels among `labels` that match any of the glob `patterns`, in `labels` order.
/// Throws LayoutRequestError(field) naming a pattern that matches nothing.
/// O(#labels · #patterns · length).
[[nodiscard]] std::vector<std::string> labelsMatching(const std::vector<std::string>& labels,
                                                      const std::vector<std::string>& patterns,
                                                      LayoutRequestError::Field field);

} // namespace mocap
