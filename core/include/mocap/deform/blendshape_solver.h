#pragma once

#include "mocap/base/job_control.h"
#include "mocap/deform/actor_profile.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/deform/retarget.h"
#include "mocap/model/blendshape_rig.h"
#include "mocap/model/take.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// How per-frame blendshape weights are solved from the bound markers' displacements.
enum class BlendshapeSolveMethod
{
  Bvls,      ///< per frame min ‖A·w − b‖², 0 ≤ w ≤ 1 (the faithful baseline of Wellein et al. 2007 §1)
  Ridge,     ///< per frame, plus λ‖w‖², λ by generalised cross-validation unless given
  Temporal,  ///< the whole take at once, plus λ‖w‖² and μ‖second differences of w over time‖²
};

/// "bvls", "ridge", "temporal". O(1).
[[nodiscard]] std::string_view blendshapeSolveMethodName(BlendshapeSolveMethod method);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string blendshapeSolveMethodNames();
[[nodiscard]] std::optional<BlendshapeSolveMethod> parseBlendshapeSolveMethod(std::string_view name);

/// λ, μ and the sparsity weight are relative to trace(AᵀA)/#shapes, the mean squared motion a
/// shape gives the bound points, so one value suits a rig in millimetres or in metres.
struct BlendshapeSolveOptions
{
  BlendshapeSolveMethod method = BlendshapeSolveMethod::Temporal;
  std::optional<double> lambda;  ///< ridge and temporal; none: chosen by GCV (bvls: 0)
  /// temporal: μ, the weight of the weights' second differences, as at 100 Hz: scaled by
  /// (frame rate / 100)⁴ so a take at another rate is smoothed over the same time.
  double smoothness = 1.0;
  double sparsity = 0.0;         ///< an L1 term s·Σw (w ≥ 0, so a linear cost) pulling unused shapes to 0
  RetargetScale scale = RetargetScale::Uniform;
  /// The neutral frame as the take numbers frames; none: the first frame with every bound marker.
  std::optional<long long> neutralFrame;
  /// Frames with fewer present bound markers than this share (and than 3) are not solved but
  /// hold the previous frame's weights, flagged in BlendshapeSolveResult::held.
  double minimumMarkerShare = 0.5;
  /// An actor's calibration (actor_profile.h): its neutral positions (matched by label, placed
  /// rigidly on the take's `neutralFrame`, or its first frame with the most bound markers, by
  /// placeActorNeutral) replace the neutral frame, and the weights are in the actor's range
  /// (1 = the actor's maximum): each is the rig's weight over the shape's extent. The solve itself
  /// stays in the rig's units (λ, GCV, μ and the sparsity shrink each shape as without a profile),
  /// only its upper bound becomes maximumWeight · extent. A profile calibrated from a
  /// range-of-motion take also undoes the shrinkage: 1 is the actor's full expression as this
  /// solve reports it (each weight is also divided by the shape's response to its full expression
  /// alone under the take's λ, at least 0.5, and the bound follows). None: the take's neutral
  /// frame and the rig's range.
  std::shared_ptr<const ActorProfile> actor;
  /// The weights' upper bound: 1, the rig's (or the actor's) full expression; calibration solves
  /// a range-of-motion take with more so that an exaggerated shape is not clipped.
  double maximumWeight = 1.0;
};

struct BlendshapeSolveResult
{
  Eigen::MatrixXd weights;   ///< #frames × #shapes, each in [0, maximumWeight]
  Eigen::VectorXd residual;  ///< per frame, RMS distance (take units) of the present markers from the rig's points; NaN where held
  std::vector<bool> held;    ///< frames with too few markers, left at the previous frame's weights (0 before the first solved one)
  double lambda = 0.0;       ///< the λ used (relative, see BlendshapeSolveOptions)
  bool lambdaChosen = false; ///< λ came from GCV
  int iterations = 0;        ///< temporal: ADMM iterations run
  double solveSeconds = 0.0;
};

/// Solves a take to the weights of a blendshape rig through a marker binding. Set-up (once per
/// take and rig) finds the bound markers, picks the neutral frame and fits the retarget as
/// FaceRig does, samples each shape's delta at the bound points (A, 3·#markers × #shapes, mesh
/// units) and factorises AᵀA. Per frame, the retargeted marker displacements from the neutral
/// frame b ≈ A·w; markers missing in a frame drop their rows. The take must already be in the
/// frame the binding was made in (stabilizeTake). Not a paper equation: the per-frame bounded
/// fit is Wellein et al.'s §1 model on a semantic rig; ridge, GCV and the temporal prior are ours.
/// Set-up O(#markers · #shapes² + #shapes³); per frame O(#markers · #shapes) plus the bounded
/// solve's active-set steps (bvls, ridge) or O(#shapes²) per ADMM iteration (temporal).
class BlendshapeSolver
{
public:
  /// Throws InvalidArgument as FaceRig does for the binding and take, for a binding made for
  /// another vertex count, an invalid rig (checkRig), options out of range (negative λ, μ or
  /// sparsity, a marker share outside [0, 1], a maximum weight not > 0) and an actor profile that
  /// lacks a bound marker or one of the rig's shapes.
  BlendshapeSolver(const BlendshapeRig& rig, const MeshBinding& binding, const Take& take,
                   const BlendshapeSolveOptions& options = {});

  /// Solves every frame of `take` (the same markers as at set-up), using only the bound markers
  /// flagged in `use` (all when empty; leave-out evaluation hides some). Reports progress and
  /// stops with JobCancelled through `control`.
  [[nodiscard]] BlendshapeSolveResult solve(const Take& take, const std::vector<bool>& use = {},
                                            const JobControl& control = {}) const;

  [[nodiscard]] const BlendshapeSolveOptions& options() const { return m_options; }
  [[nodiscard]] const std::vector<std::string>& labels() const { return m_bound.labels; }
  [[nodiscard]] const std::vector<Eigen::Index>& markers() const { return m_bound.markers; }
  [[nodiscard]] const std::vector<MeshPoint>& points() const { return m_bound.points; }
  /// −1 when the neutral is an actor's.
  [[nodiscard]] Eigen::Index neutralFrame() const { return m_bound.neutral; }
  /// The bound markers' neutral positions (#markers × 3, take units).
  [[nodiscard]] const PointSet& neutralMarkers() const { return m_bound.neutralMarkers; }
  [[nodiscard]] const Retarget& retarget() const { return m_bound.retarget; }
  /// The shapes' deltas at the bound points: rows 3m … 3m+2 are marker m's x, y, z (mesh units),
  /// each column times the actor's extent when solving with an actor profile.
  [[nodiscard]] const Eigen::MatrixXd& shapeMatrix() const { return m_a; }
  /// trace(AᵀA)/#shapes of the rig's deltas (without the actor's extents): the unit of λ, μ and
  /// the sparsity weight.
  [[nodiscard]] double scaleOfTerms() const { return m_termScale; }
  [[nodiscard]] double setupSeconds() const { return m_setupSeconds; }

private:
  BlendshapeSolveOptions m_options;
  BoundTake m_bound;
  Eigen::MatrixXd m_rigShapes;  // the rig's deltas at the bound points
  Eigen::VectorXd m_extent;     // the actor's extents, ones without a profile
  Eigen::MatrixXd m_a;          // m_rigShapes · diag(m_extent)
  double m_termScale = 1.0;
  double m_setupSeconds = 0.0;
};

/// The λ (relative to `termScale`) minimising the generalised cross-validation score of the
/// unconstrained ridge fit A·w ≈ b summed over the columns of `b` (3·#markers × #frames, complete
/// frames only): GCV(λ) = n·Σ‖b − A·w_λ‖² / (n − tr H_λ)², over a log grid 1e-8 … 1e2. From one
/// eigendecomposition of AᵀA, O(#shapes³ + #frames · n · #shapes + grid · #shapes).
[[nodiscard]] double chooseRidgeLambda(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                       const Eigen::Ref<const Eigen::MatrixXd>& b, double termScale);

} // namespace mocap
