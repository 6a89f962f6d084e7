#include "mocap/deform/face_rig.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"

#include <algorithm>
#include <chrono>

namespace mocap {

namespace {

constexpr EnumTable<DeformMethod, 2> kDeformMethods{{{
    {DeformMethod::Rbf, "rbf"},
    {DeformMethod::Laplacian, "laplacian"},
}}};

} // namespace

std::string_view deformMethodName(DeformMethod method)
{
  return kDeformMethods.name(method, "laplacian");
}

std::string deformMethodNames()
{
  return kDeformMethods.names();
}

std::optional<DeformMethod> parseDeformMethod(std::string_view name)
{
  return kDeformMethods.parse(name);
}

namespace {

// The factory owns copies of the rest mesh, so it stays valid after the rig's inputs are gone.
DeformerFactory makeFactory(const Mesh& mesh, const FaceRigOptions& options)
{
  if (options.method == DeformMethod::Laplacian)
    return [rest = mesh.vertices, triangles = mesh.triangles(),
            lap = options.laplacian](const std::vector<MeshPoint>& controls) -> std::unique_ptr<MeshDeformer> {
      return std::make_unique<LaplacianDeformer>(rest, triangles, controls, lap);
    };
  return [rest = mesh.vertices, rbf = options.rbf](const std::vector<MeshPoint>& controls) -> std::unique_ptr<MeshDeformer> {
    return std::make_unique<RbfDeformer>(rest, boundPositions(rest, controls), rbf);
  };
}

} // namespace

FaceRig::FaceRig(const Mesh& mesh, const MeshBinding& binding, const Take& take, const FaceRigOptions& options)
    : m_options(options)
{
  if (options.rotations < 0 || options.rotations > 100)
    throw InvalidArgument("rotation iterations must be 0 … 100, not " + std::to_string(options.rotations));
  if (options.rotations > 0 && options.method != DeformMethod::Laplacian)
    throw InvalidArgument("rotation iterations need Laplacian deformation");
  if (binding.meshVertices != 0 && binding.meshVertices != mesh.vertexCount())
    throw InvalidArgument("the binding was made for a mesh of " + std::to_string(binding.meshVertices) +
                          " vertices, not " + std::to_string(mesh.vertexCount()));
  for (const MarkerBinding& marker : binding.markers) {
    m_labels.push_back(marker.label);
    m_points.push_back(marker.point);
  }
  m_markers = markerIndices(take, m_labels);
  m_neutral = chooseNeutralFrame(take, m_markers, options.neutralFrame);
  const PointSet bound = boundPositions(mesh.vertices, m_points);
  if (options.method == DeformMethod::Rbf)
    checkDistinctControls(bound, 1e-9 * mesh.size(), m_labels);
  const PointSet neutral = markerPositions(take, m_neutral, m_markers);
  m_retarget = fitRetarget(neutral, bound, options.scale);
  m_placement = fitSimilarity(neutral, bound);
  m_factory = makeFactory(mesh, options);
  const auto start = std::chrono::steady_clock::now();
  m_deformer = m_factory(m_points);
  m_setupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

FaceRig::~FaceRig() = default;

bool FaceRig::deform(const Take& take, Eigen::Index frame, MeshVertices& out)
{
  if (frame < 0 || frame >= take.frameCount())
    throw InvalidArgument("frame " + std::to_string(frame) + " is outside the take (0 … " +
                          std::to_string(take.frameCount() - 1) + ")");
  if (m_neutral >= take.frameCount() ||
      std::any_of(m_markers.begin(), m_markers.end(), [&](Eigen::Index m) { return m >= take.markerCount(); }))
    throw InvalidArgument("the take no longer has the markers or frames the face rig was set up with");
  controlDisplacements(take, m_markers, m_neutral, m_retarget, frame, m_displacements, m_present);
  deformFrame(*m_deformer, m_displacements, m_present, m_options.rotations, out);
  return std::all_of(m_present.begin(), m_present.end(), [](bool p) { return p; });
}

} // namespace mocap
