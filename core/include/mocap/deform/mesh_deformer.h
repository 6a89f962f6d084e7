#pragma once

#include "mocap/deform/mesh_binding.h"
#include "mocap/math/kabsch.h"
#include "mocap/model/mesh.h"

#include <Eigen/Core>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mocap {

/// What RBF and Laplacian deformation share once set up: vertex displacements are linear in the
/// control displacements, d = M·c with M the #vertices × #controls response matrix, so each frame
/// is one matrix product. M is computed in double and stored in single precision: a frame reads
/// all of M, so halving it (and doubling the SIMD width) doubles the frame rate, while the
/// relative error it adds to a displacement stays below 1e-6. A frame missing some controls uses the response of the remaining ones
/// (the controls are skipped, not held), computed by the subclass on first use and cached per
/// pattern of missing controls.
class MeshDeformer
{
public:
  virtual ~MeshDeformer() = default;
  MeshDeformer(const MeshDeformer&) = delete;
  MeshDeformer& operator=(const MeshDeformer&) = delete;

  [[nodiscard]] Eigen::Index vertexCount() const { return m_rest.rows(); }
  [[nodiscard]] Eigen::Index controlCount() const { return m_response.cols(); }
  [[nodiscard]] const MeshVertices& rest() const { return m_rest; }
  /// M: column c is the displacement of every vertex per unit displacement of control c.
  [[nodiscard]] const Eigen::MatrixXf& response() const { return m_response; }

  /// out = rest + M·displacements (#controls × 3). Throws InvalidArgument for a wrong size or a
  /// non-finite displacement. O(#vertices · #controls).
  void deform(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const;
  /// As deform, skipping the controls whose `present` entry is false (their displacement rows are
  /// ignored). With no control present the mesh stays at rest. The first frame of a new pattern
  /// costs one responseFor() call; up to 64 patterns are cached.
  void deform(const Eigen::Ref<const PointSet>& displacements, const std::vector<bool>& present, MeshVertices& out);

protected:
  explicit MeshDeformer(MeshVertices rest) : m_rest(std::move(rest)) {}
  /// Subclasses set the full response once in their constructor.
  void setResponse(const Eigen::MatrixXd& response) { m_response = response.cast<float>(); }
  /// The response (#vertices × #present) of the deformation driven by the present controls only.
  [[nodiscard]] virtual Eigen::MatrixXd responseFor(const std::vector<bool>& present) const = 0;

private:
  void addProduct(const Eigen::MatrixXf& response, const PointSet& displacements, MeshVertices& out) const;

  MeshVertices m_rest;
  Eigen::MatrixXf m_response;
  std::map<std::vector<bool>, Eigen::MatrixXf> m_cache;
};

/// Throws InvalidArgument naming the first two controls (rows of `controls`, called by `names`
/// when given, else by number) closer than `tolerance`: markers bound to the same mesh point make
/// an interpolation singular. O(#controls²).
void checkDistinctControls(const Eigen::Ref<const PointSet>& controls, double tolerance,
                           const std::vector<std::string>& names = {});

/// Builds a deformer of the rest mesh driven by the given control points.
using DeformerFactory = std::function<std::unique_ptr<MeshDeformer>(const std::vector<MeshPoint>& controls)>;

} // namespace mocap
