#pragma once

#include "mocap/deform/mesh_deformer.h"

#include <optional>
#include <string>
#include <string_view>

namespace mocap {

/// Radial basis φ(r) of the RBF deformer; c is RbfOptions::radius.
enum class RbfKernel
{
  Exp,         ///< e^(−r/c), the paper's choice with c = 64 (§2.1)
  Gaussian,    ///< e^(−(r/c)²)
  Biharmonic,  ///< r
  ThinPlate,   ///< r² log r
};

/// "exp", "gaussian", "biharmonic", "thin-plate". O(1).
[[nodiscard]] std::string_view rbfKernelName(RbfKernel kernel);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string rbfKernelNames();
[[nodiscard]] std::optional<RbfKernel> parseRbfKernel(std::string_view name);
/// φ(r) for `kernel` with radius c. O(1).
[[nodiscard]] double rbfKernel(RbfKernel kernel, double r, double c);

struct RbfOptions
{
  RbfKernel kernel = RbfKernel::Exp;
  double radius = 64.0;  ///< c, in mesh units (the paper's 64)
  /// Adds a + B·x to the interpolant (with Σ pₖ = 0, Σ pₖ xₖᵀ = 0), so affine motion, rigid motion
  /// included, is reproduced exactly; needs ≥ 4 non-coplanar controls (per region).
  bool affine = true;
  /// The paper's fix for opposing control points (§4, Fig. 4): split the face into top, middle and
  /// bottom thirds of the controls' extent along `upAxis`, deform each with its own RBF and blend
  /// them smoothly over a band of ±blendWidth (fraction of that extent) around each border.
  bool regions = false;
  int upAxis = 1;           ///< mesh axis pointing up (0 x, 1 y, 2 z); OBJ faces are usually y-up
  double blendWidth = 0.1;  ///< half-width of the blend band, fraction of the controls' height
};

/// RBF interpolation of control displacements (the paper's eqs 1–3): solve Φ·p = V for the weights
/// pₖ (eq 2, Φₖₗ = φ(‖xₖ − xₗ‖), plus the affine block when enabled), then every vertex moves by
/// Σ pₖ φ(‖x − xₖ‖) (eq 3). Since p is linear in V, the vertex × control response
/// M = [Φ_vc Q_v]·[[Φ Q]; [Qᵀ 0]]⁻¹ is precomputed once; a frame is then one product M·V.
/// Set-up O(#controls³ + #vertices · #controls²); per frame O(#vertices · #controls).
class RbfDeformer : public MeshDeformer
{
public:
  /// `controls`: rest positions of the bound points (#controls × 3, mesh units). Throws
  /// InvalidArgument for no controls, a non-finite value, radius ≤ 0, coincident controls (the
  /// system would be singular), too few or coplanar controls for the affine term, or a region
  /// without a control.
  RbfDeformer(MeshVertices rest, const Eigen::Ref<const PointSet>& controls, const RbfOptions& options = {});

  [[nodiscard]] const RbfOptions& options() const { return m_options; }

  /// The naive evaluation for the benchmark and tests: solve eq 2 for this frame's weights and sum
  /// eq 3 at every vertex (no regions). O(#controls³ + #vertices · #controls) per frame.
  void deformDirect(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const;

protected:
  [[nodiscard]] Eigen::MatrixXd responseFor(const std::vector<bool>& present) const override;

private:
  [[nodiscard]] Eigen::MatrixXd buildResponse(const PointSet& controls) const;

  PointSet m_controls;
  RbfOptions m_options;
};

} // namespace mocap
