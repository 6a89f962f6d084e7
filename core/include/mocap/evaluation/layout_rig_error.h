#pragma once

#include "mocap/deform/blendshape_solver.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// A layout solved from fewer bound markers than this is not judged: the solver needs three
/// present markers in a frame once it uses at least three (BlendshapeSolveOptions).
constexpr Eigen::Index kMinimumRigLayoutMarkers = 3;

struct LayoutRigErrorOptions
{
  /// How weights are solved, from a layout and from the full set alike. bvls by default: the
  /// seed paper's per-frame bounded fit, and the fastest.
  BlendshapeSolveOptions solve = [] {
    BlendshapeSolveOptions bvls;
    bvls.method = BlendshapeSolveMethod::Bvls;
    return bvls;
  }();
  /// Per take, at most this many frames are solved: every step-th frame counted from the neutral
  /// frame (so it is among them), step = ⌈#frames / maxFrames⌉, at the take's rate over step
  /// (temporal then smooths over the same time). 0: every frame.
  Eigen::Index maxFrames = 500;
  /// Head reference markers: each take's head motion is removed with them (stabilizeTake) before
  /// the binding is found in it, as `mocap solve --stabilize` does. planRigErrors uses the plan's.
  std::vector<std::string> stabilizeLabels;
  /// planRigErrors: random symmetric layouts per size for the baseline mean, and their seed.
  int randomSubsets = 20;
  std::uint64_t seed = 1;
};

/// The rig measure of one layout.
struct RigLayoutError
{
  Eigen::Index boundMarkers = 0;  ///< the layout's markers the binding binds: the ones solved from
  Eigen::Index frames = 0;        ///< frames solved from both the layout and the full set, all takes
  /// Mean over those frames and every shape of (w_layout − w_full)²; NaN when not judged (fewer
  /// than kMinimumRigLayoutMarkers bound markers, no frame solved in both, or cancelled).
  double mse = std::numeric_limits<double>::quiet_NaN();

  [[nodiscard]] bool judged() const { return !std::isnan(mse); }
};

struct LayoutRigErrors
{
  std::vector<RigLayoutError> layouts;  ///< one per layout given, in order
  Eigen::Index boundMarkers = 0;        ///< markers the binding binds (the full set)
  Eigen::Index frames = 0;              ///< frames the full set was solved in, all takes
  double seconds = 0.0;
  bool cancelled = false;
};

/// The seed paper's blendshape-weight error of marker layouts (Wellein et al. 2007 §3: MSE
/// between the weights solved from a subset and from the full set) on a semantic rig instead of
/// key poses picked from the take. Per take: copy, remove head motion, set up BlendshapeSolver
/// on the (subsampled) take and solve it from every bound marker once; then per layout solve it
/// again from the layout's bound markers only (the solver's `use` mask; labels the binding does
/// not bind add nothing) and pool the squared weight differences over the takes. Layouts run in
/// parallel on JobControl::threads(); results do not depend on the thread count. Progress and
/// cancellation through `control`; on cancellation the layouts not finished stay unjudged and
/// cancelled = true.
/// O(#takes · (#frames · #markers + F · #bound · #shapes) + #layouts · #takes · F · (#bound ·
/// #shapes + bounded-solve steps)) with F ≤ maxFrames frames per take.
/// Throws InvalidArgument for no takes, maxFrames < 0, and as stabilizeTake and BlendshapeSolver
/// do (a bound marker missing from a take, a binding for another mesh, bad solve options).
[[nodiscard]] LayoutRigErrors layoutRigErrors(const std::vector<Take>& takes, const BlendshapeRig& rig,
                                              const MeshBinding& binding,
                                              const std::vector<std::vector<std::string>>& layouts,
                                              const LayoutRigErrorOptions& options = {},
                                              const JobControl& control = {});

/// The rig measure of one size of a plan.
struct LayoutSizeRigErrors
{
  Eigen::Index markerCount = 0;
  std::optional<RigLayoutError> pfa;     ///< set where the plan has a PFA layout of this size
  std::optional<RigLayoutError> greedy;  ///< likewise for greedy
  int randomCount = 0;                   ///< random layouts judged
  double randomMse = std::numeric_limits<double>::quiet_NaN();  ///< their mean; NaN when none
};

struct PlanRigErrors
{
  std::vector<LayoutSizeRigErrors> sizes;  ///< one per LayoutPlan::sizes entry, in order
  RigLayoutError planned;                  ///< every planned marker as one layout
  Eigen::Index boundMarkers = 0;           ///< as LayoutRigErrors
  Eigen::Index frames = 0;
  double seconds = 0.0;
  bool cancelled = false;

  /// The entry for `markerCount`, or nullptr. O(#sizes).
  [[nodiscard]] const LayoutSizeRigErrors* size(Eigen::Index markerCount) const;
};

/// layoutRigErrors of a finished plan (planLayout on `takes`, with its head reference markers):
/// every size's PFA and greedy layout, `randomSubsets` random symmetric layouts per size
/// (selectRandom, seeded from options.seed, size and index: the same distribution as the plan's
/// random baseline, not the same draws), and all planned markers together. Cost and throws as
/// layoutRigErrors over those #sizes · (2 + randomSubsets) + 1 layouts; also InvalidArgument for
/// randomSubsets < 0.
[[nodiscard]] PlanRigErrors planRigErrors(const std::vector<Take>& takes, const LayoutResult& result,
                                          const BlendshapeRig& rig, const MeshBinding& binding,
                                          const LayoutRigErrorOptions& options = {},
                                          const JobControl& control = {});

} // namespace mocap
