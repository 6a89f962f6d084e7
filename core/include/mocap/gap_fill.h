#pragma once

#include "mocap/gaps.h"
#include "mocap/sample_patch.h"
#include "mocap/take.h"

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

struct FillOptions
{
  FillMethod method = FillMethod::Auto;
  Eigen::Index maxGap = 0;  ///< longest gap filled, in frames; 0 = unlimited
  int neighbours = 6;       ///< n of guenter, lin-ouhyoung, zhang-n (eqs 6-7), rigid and auto; 1..1000
};

/// What happened to one gap.
struct GapFillReport
{
  Gap gap;
  bool filled = false;
  std::string method;  ///< what filled it (auto names its ingredients)
  std::string reason;  ///< why not
};

struct FillResult
{
  std::vector<SamplePatch> patches;  ///< one per filled gap, samples valid, residual 0, state Filled
  std::vector<GapFillReport> gaps;   ///< one per gap, in findGaps order
};

/// Fills every gap of at most maxGap frames with `options.method`; the take is not changed:
/// apply the patches (sample_patch.h) to do so, or show them as a preview. Each gap is filled
/// from the take's valid samples only (never from another gap's fill), so the result does not
/// depend on the order of the gaps and no invalid sample of another marker is read or touched.
/// A gap that cannot be filled is reported with the reason, never invented: longer than maxGap;
/// the marker never valid; a gap touching the first or last frame with a method that needs both
/// sides (linear, spline); too few neighbours. Edge gaps are extrapolated by the methods that
/// can: guenter, lin-ouhyoung, zhang3, zhang-n (propagated from the one border), rigid and auto
/// (carried by the neighbours' rigid motion / regression from the one border) and pca. An empty
/// take has no gaps. Implements eqs 3-7 through the methods (see their headers). Throws
/// InvalidArgument for an unknown method, maxGap < 0, neighbours outside 1..1000, or a valid
/// sample that is not finite. O(#frames · #markers) plus each method's cost per gap (at most
/// O(length · #markers) for the neighbour methods; pca adds one model of the whole take).
[[nodiscard]] FillResult fillGaps(const Take& take, const FillOptions& options);

/// Like fillGaps(take, options) but only for `gaps`, each of which must be a run of invalid
/// samples of the take (as findGaps returns them; InvalidArgument otherwise). Reports follow
/// `gaps`. Used by evaluations and by the studio to fill a selection.
[[nodiscard]] FillResult fillGaps(const Take& take, const std::vector<Gap>& gaps, const FillOptions& options);

} // namespace mocap
