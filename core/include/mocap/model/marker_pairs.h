#pragma once

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mocap {

/// The left/right mirror partner of each marker, so layouts stay symmetric (Wellein et al. 2007
/// §2: "if at least one feature belonging to a symmetrical marker pair is in the feature set, the
/// marker pair will be included"). Selection works on units: each pair is one unit of two
/// markers, every other marker a unit of its own.
class MarkerSymmetry
{
public:
  /// No pairs: every marker is a unit of its own. O(#markers).
  explicit MarkerSymmetry(Eigen::Index markerCount = 0);
  /// `pairs` of distinct marker indices. Throws InvalidArgument for an index out of range, a
  /// marker paired with itself or a marker in two pairs. O(#markers + #pairs).
  MarkerSymmetry(Eigen::Index markerCount, const std::vector<std::pair<Eigen::Index, Eigen::Index>>& pairs);

  [[nodiscard]] Eigen::Index markerCount() const { return static_cast<Eigen::Index>(m_mirror.size()); }
  /// The marker's partner, or the marker itself when it has none. O(1); throws InvalidArgument
  /// out of range (as does unitOf).
  [[nodiscard]] Eigen::Index mirror(Eigen::Index marker) const;
  /// Every pair once, (smaller index, larger index), in order of the smaller index. O(#markers).
  [[nodiscard]] std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs() const;
  /// Units in order of their first marker; a unit is {a, b} for a pair (a < b) or {m}.
  [[nodiscard]] const std::vector<std::vector<Eigen::Index>>& units() const { return m_units; }
  /// Index into units() of the marker's unit. O(1).
  [[nodiscard]] Eigen::Index unitOf(Eigen::Index marker) const;
  /// `markers` plus the mirror of each, sorted, without repeats. O(n log n).
  [[nodiscard]] std::vector<Eigen::Index> symmetricClosure(const std::vector<Eigen::Index>& markers) const;

private:
  void buildUnits();

  std::vector<Eigen::Index> m_mirror;
  std::vector<std::vector<Eigen::Index>> m_units;
  std::vector<Eigen::Index> m_unitOf;
};

/// Pairs from text: one pair per line, two labels separated by blanks, tabs or a comma; `#`
/// starts a comment; blank lines are skipped. Throws FormatError(sourceName, "line N: ...") for a
/// line without exactly two labels, a label not in `labels`, a marker paired with itself or a
/// marker in two pairs. O(text size + #labels).
[[nodiscard]] MarkerSymmetry parseMarkerPairs(std::string_view text, const std::vector<std::string>& labels,
                                              const std::string& sourceName);

/// Labels that would name the mirror partner of `label` by common conventions: one side letter
/// swapped at a word boundary ("Leye_Up"↔"Reye_Up", "Chin_L1"↔"Chin_R1", "Mouth_UpL1"↔
/// "Mouth_UpR1") or "Left"↔"Right" in any case. O(length²).
[[nodiscard]] std::vector<std::string> mirroredLabelCandidates(std::string_view label);

struct PairDetectionOptions
{
  /// Largest mirror mismatch ‖mirror(a) − b‖ of a geometric pair, and twice the largest distance
  /// of a midline marker from the plane, in the positions' units; 0 picks 0.5 × the median
  /// distance between nearest markers.
  double tolerance = 0.0;
  bool useLabels = true;  ///< pair labels by naming convention first (kept even when far off)
};

struct DetectedPair
{
  Eigen::Index first = 0;
  Eigen::Index second = 0;
  double mismatch = 0.0;    ///< ‖mirror(first) − second‖ about the fitted plane
  bool fromLabels = false;  ///< named as a pair rather than found geometrically
};

struct PairDetection
{
  MarkerSymmetry symmetry;
  std::vector<DetectedPair> pairs;
  std::vector<Eigen::Index> midline;   ///< markers within tolerance of the plane, their own mirror
  std::vector<Eigen::Index> unpaired;  ///< markers with no mirror partner off the plane
  Eigen::Vector3d planeNormal = Eigen::Vector3d::UnitX();
  Eigen::Vector3d planePoint = Eigen::Vector3d::Zero();
  double tolerance = 0.0;  ///< the tolerance used
};

/// Finds mirror pairs by reflecting a neutral frame (#markers × 3) about the face's mid-sagittal
/// plane and matching: pairs named by mirroredLabelCandidates() are taken first and, when there are
/// two or more, give the first guess of the plane; the principal axes of the point cloud are the
/// other guesses. Each guess is refined by alternating mutual-nearest matching and a plane fit
/// (normal = principal direction of the pair differences, offset = mean of midpoints and midline
/// markers); the plane with the smallest mean mismatch wins. Remaining markers pair when they are
/// each other's nearest mirror image within the tolerance. Not a paper equation (the paper gives
/// the pairs by hand). O(#markers² · refinement steps). Throws InvalidArgument when the sizes
/// disagree or a position is not finite.
[[nodiscard]] PairDetection detectMarkerPairs(const Eigen::Ref<const Eigen::MatrixX3d>& neutral,
                                              const std::vector<std::string>& labels,
                                              const PairDetectionOptions& options = {});

} // namespace mocap
