#pragma once

#include "mocap/model/gaps.h"
#include "mocap/base/job_control.h"
#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The gap-filling methods; see each method's header for the details.
enum class FillMethod
{
  Linear,       ///< straight line between the border samples (interpolation_fill.h)
  Spline,       ///< cubic through two valid samples either side (interpolation_fill.h)
  Guenter,      ///< average displacement of the nearest valid neighbours, Guenter et al. [2]
  LinOuhyoung,  ///< distance-weighted neighbour displacements, Lin & Ouhyoung [1]
  Zhang3,       ///< the paper's three-neighbour muscle mechanism, eqs 3-5
  ZhangN,       ///< the paper's n-neighbour form, eqs 6-7
  Rigid,        ///< rigid (Kabsch) motion of nearby markers valid through the gap (rigid_fill.h)
  Pca,          ///< low-rank model of the take, Gløersen & Federolf 2016 (pca_fill.h)
  Auto,         ///< the best we have: validated blend of several predictors (auto_fill.h)
};

/// Every method, in the order of the enum. O(1).
[[nodiscard]] const std::vector<FillMethod>& allFillMethods();

/// "linear", "spline", "guenter", "lin-ouhyoung", "zhang3", "zhang-n", "rigid", "pca", "auto"
/// (exactly, lower case); std::nullopt for anything else. The paper's method is zhang3 (eqs 3-5),
/// zhang-n its eqs 6-7, guenter and lin-ouhyoung its baselines [2] and [1]. O(1).
[[nodiscard]] std::optional<FillMethod> parseFillMethod(std::string_view name);

/// The name parseFillMethod accepts for `method`. O(1).
[[nodiscard]] std::string_view fillMethodName(FillMethod method);

/// Defaults that never invent much: gaps up to half a second, interior gaps only, markers seen in
/// at least a fifth of the take. Fields after `neighbours` were added later, so the brace form
/// {method, maxGap, neighbours} keeps its meaning for the first three.
struct FillOptions
{
  FillMethod method = FillMethod::Auto;
  /// Longest gap filled, in frames; 0: take maxGapSeconds instead.
  Eigen::Index maxGap = 0;
  int neighbours = 6;  ///< n of guenter, lin-ouhyoung, zhang-n (eqs 6-7), rigid and auto; 1..1000
  /// Longest gap filled, in seconds of the take's frame rate (rounded to frames, at least 1), used
  /// when maxGap is 0; 0 = unlimited. Finite and >= 0.
  double maxGapSeconds = 0.5;
  /// Fill gaps touching the first or last frame (beyond a marker's first or last valid sample)
  /// with the methods that can extrapolate; false leaves them open ("edge gap (extrapolation off)").
  bool extrapolate = false;
  /// Markers valid in fewer than this fraction of the frames are left open (too little to go on),
  /// unless named in fillAnyway. In [0, 1]; 0 fills every marker.
  double minValidFraction = 0.2;
  /// Markers filled whatever their valid fraction (e.g. the ones a technician selected).
  std::vector<Eigen::Index> fillAnyway{};
};

/// Why a gap was left open; None for a filled gap.
enum class UnfilledCause
{
  None,
  NeverValid,   ///< the marker has no valid sample at all
  RarelyValid,  ///< valid in fewer frames than minValidFraction
  TooLong,      ///< longer than the longest gap to fill
  EdgeGap,      ///< touches the first or last frame and extrapolate is off
  Method,       ///< the method could not fill it (reason says why)
  ModelOutput,  ///< the point is a model output (an angle, a force...), not a marker position
};

/// "never_valid", "rarely_valid", "too_long", "edge_gap", "method", "model_output" ("" for None),
/// for reports. O(1).
[[nodiscard]] std::string_view unfilledCauseName(UnfilledCause cause);

/// The longest gap `options` fill in a take recorded at `frameRate` Hz, in frames; 0 = unlimited.
/// Throws InvalidArgument for a rate that is not finite and positive. O(1).
[[nodiscard]] Eigen::Index longestGapFrames(const FillOptions& options, double frameRate);

/// What happened to one gap.
struct GapFillReport
{
  Gap gap;
  bool filled = false;
  std::string method;  ///< what filled it (auto names its ingredients)
  std::string reason;  ///< why not
  UnfilledCause cause = UnfilledCause::None;
};

struct FillResult
{
  std::vector<SamplePatch> patches;  ///< one per filled gap, samples valid, residual 0, state Filled
  std::vector<GapFillReport> gaps;   ///< one per gap, in findGaps order
};

/// The safety rules of `options`, gap by gap, before any method runs: one report per gap of
/// `gaps` (in order), cause None when the rules let it be filled, else the cause and reason
/// fillGaps leaves it open with, checked in this order: the marker never valid; valid in under
/// minValidFraction of the frames (unless in fillAnyway); longer than the longest gap
/// (longestGapFrames); touching the first or last frame while extrapolate is off. The one place
/// these rules are decided: fillGaps and the studio's Gaps dock both ask it. Throws
/// InvalidArgument as fillGaps does for bad options or a gap outside the take.
/// O(#frames · #markers + #gaps).
[[nodiscard]] std::vector<GapFillReport> checkFillRules(const Take& take, const std::vector<Gap>& gaps,
                                                        const FillOptions& options);

/// Fills the gaps `options` allow with `options.method`; the take is not changed: apply the
/// patches (sample_patch.h) to do so, or show them as a preview. Each gap is filled from the
/// take's valid samples only (never from another gap's fill), so the result does not depend on
/// the order of the gaps and no invalid sample of another marker is read or touched. A gap left
/// open is reported with its cause and reason, never invented: the rules of checkFillRules, then
/// the method could not (a gap touching the first or last frame with a method that needs
/// both sides, linear or spline; too few neighbours). With extrapolate on, edge gaps are
/// extrapolated by the methods that can: guenter, lin-ouhyoung, zhang3, zhang-n (propagated from
/// the one border), rigid and auto (carried by the neighbours' rigid motion / regression from the
/// one border) and pca. An empty take has no gaps. Implements eqs 3-7 through the methods (see
/// their headers). Throws InvalidArgument for an unknown method, maxGap < 0, maxGapSeconds or
/// minValidFraction out of range, a marker of fillAnyway outside the take, neighbours outside
/// 1..1000, or a valid sample that is not finite. O(#frames · #markers) plus each method's cost
/// per gap (at most O(length · #markers) for the neighbour methods; pca adds one model of the
/// whole take).
[[nodiscard]] FillResult fillGaps(const Take& take, const FillOptions& options, const JobControl& job = {});

/// Like fillGaps(take, options) but only for `gaps`, each of which must be a run of invalid
/// samples of the take (as findGaps returns them; InvalidArgument otherwise). Reports follow
/// `gaps`. Used by evaluations and by the studio to fill a selection. Model outputs
/// (marker_points.h) are neither filled (cause ModelOutput) nor used as neighbours: a take that
/// holds some is filled on a copy of its marker points.
/// `job` is checked between gaps (a cancelled fill throws JobCancelled).
[[nodiscard]] FillResult fillGaps(const Take& take, const std::vector<Gap>& gaps, const FillOptions& options,
                                  const JobControl& job = {});

} // namespace mocap
