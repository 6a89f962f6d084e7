#pragma once

#include "mocap/deform/mesh_deformer.h"
#include "mocap/deform/laplacian_deformer.h"
#include "mocap/deform/rbf_deformer.h"
#include "mocap/deform/retarget.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// How the rest of the mesh follows the bound points.
enum class DeformMethod
{
  Rbf,        ///< RbfDeformer, the paper's eqs 1–3
  Laplacian,  ///< LaplacianDeformer, the paper's eq 7
};

/// "rbf", "laplacian". O(1).
[[nodiscard]] std::string_view deformMethodName(DeformMethod method);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string deformMethodNames();
[[nodiscard]] std::optional<DeformMethod> parseDeformMethod(std::string_view name);

struct FaceRigOptions
{
  DeformMethod method = DeformMethod::Rbf;
  RbfOptions rbf;
  LaplacianOptions laplacian;
  int rotations = 0;  ///< Laplacian rotation-aware iterations per frame (deformFrame); 0 = linear
  RetargetScale scale = RetargetScale::Uniform;
  /// The neutral frame as the take numbers frames; none: the first frame with every bound marker.
  std::optional<long long> neutralFrame;
};

/// A face mesh driven by a take through a marker binding: the per-take set-up that `mocap deform`
/// and the studio's face-mesh panel share. Set-up finds the bound markers in the take, picks the
/// neutral frame, fits the retarget (take → mesh displacements) and the placement (take → mesh
/// positions, both by fitSimilarity of the neutral markers onto their bound points) and builds
/// the deformer once; each frame is then the retargeted marker displacements from the neutral
/// frame through deformFrame (markers missing in a frame are skipped). The take must already be
/// in the frame the binding was made in (head motion removed by stabilizeTake when the binding
/// was), and keep its marker order between set-up and deform. Not a paper equation; it assembles
/// the paper's §3 pipeline. Set-up O(deformer set-up + #frames · #markers to find a neutral
/// frame); per frame O(#vertices · #controls), or the rotation-aware cost with rotations > 0.
class FaceRig
{
public:
  /// Throws InvalidArgument for a bound label the take does not have (markerIndices), no usable
  /// neutral frame (chooseNeutralFrame), fewer than three bound markers or coincident neutral
  /// markers (fitSimilarity), rotations with RBF or outside 0 … 100, bound points that coincide
  /// with RBF (checkDistinctControls), a binding made for another vertex count, and whatever the
  /// deformer's constructor throws.
  FaceRig(const Mesh& mesh, const MeshBinding& binding, const Take& take, const FaceRigOptions& options = {});
  ~FaceRig();
  FaceRig(const FaceRig&) = delete;
  FaceRig& operator=(const FaceRig&) = delete;

  /// The deformed mesh (#vertices × 3, mesh units) in `frame` (0-based) of `take`. Returns
  /// whether every bound marker was present in that frame. Throws InvalidArgument for a frame
  /// outside the take or a take with fewer markers than at set-up. O(#vertices · #controls).
  bool deform(const Take& take, Eigen::Index frame, MeshVertices& out);

  [[nodiscard]] const FaceRigOptions& options() const { return m_options; }
  [[nodiscard]] const std::vector<std::string>& labels() const { return m_bound.labels; }
  /// Take marker index per bound marker, in binding order.
  [[nodiscard]] const std::vector<Eigen::Index>& markers() const { return m_bound.markers; }
  [[nodiscard]] const std::vector<MeshPoint>& points() const { return m_bound.points; }
  [[nodiscard]] Eigen::Index neutralFrame() const { return m_bound.neutral; }
  [[nodiscard]] const Retarget& retarget() const { return m_bound.retarget; }
  /// Take (neutral frame) → mesh: where the rest mesh sits over the neutral markers.
  [[nodiscard]] const Similarity& placement() const { return m_placement; }
  [[nodiscard]] const MeshVertices& rest() const { return m_deformer->rest(); }
  /// Builds a deformer of the same kind and options for other controls (leave-out evaluation).
  [[nodiscard]] const DeformerFactory& factory() const { return m_factory; }
  /// Wall-clock seconds the deformer's set-up took.
  [[nodiscard]] double setupSeconds() const { return m_setupSeconds; }

private:
  FaceRigOptions m_options;
  BoundTake m_bound;
  Similarity m_placement;
  DeformerFactory m_factory;
  std::unique_ptr<MeshDeformer> m_deformer;
  double m_setupSeconds = 0.0;
  PointSet m_displacements;  // per-frame scratch
  std::vector<bool> m_present;
};

} // namespace mocap
