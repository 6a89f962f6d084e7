#include "mocap/deform/face_rig.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/base/stopwatch.h"

#include <algorithm>

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
  m_bound = bindTake(binding, take, mesh.vertices, options.neutralFrame, options.scale);
  if (options.method == DeformMethod::Rbf)
    checkDistinctControls(m_bound.boundPoints, 1e-9 * mesh.size(), m_bound.labels);
  m_placement = fitSimilarity(m_bound.neutralMarkers, m_bound.boundPoints);
  m_factory = makeFactory(mesh, options);
  const Stopwatch setup;
  m_deformer = m_factory(m_bound.points);
  m_setupSeconds = setup.seconds();
}

FaceRig::~FaceRig() = default;

bool FaceRig::deform(const Take& take, Eigen::Index frame, MeshVertices& out)
{
  if (frame < 0 || frame >= take.frameCount())
    throw InvalidArgument("frame " + std::to_string(frame) + " is outside the take (0 … " +
                          std::to_string(take.frameCount() - 1) + ")");
  if (!m_bound.fits(take))
    throw InvalidArgument("the take no longer has the markers or frames the face rig was set up with");
  controlDisplacements(take, m_bound.markers, m_bound.neutral, m_bound.retarget, frame, m_displacements, m_present);
  deformFrame(*m_deformer, m_displacements, m_present, m_options.rotations, out);
  return std::all_of(m_present.begin(), m_present.end(), [](bool p) { return p; });
}

} // namespace mocap
