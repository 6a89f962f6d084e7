#include "mocap/deform/mesh_deformer.h"

#include "mocap/base/error.h"

#include <string>

namespace mocap {

void MeshDeformer::deform(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const
{
  if (displacements.rows() != controlCount())
    throw InvalidArgument("deform: " + std::to_string(displacements.rows()) + " displacements for " +
                          std::to_string(controlCount()) + " controls");
  if (!displacements.allFinite())
    throw InvalidArgument("deform: a control displacement is not finite");
  addProduct(m_response, displacements, out);
}

void MeshDeformer::deform(const Eigen::Ref<const PointSet>& displacements, const std::vector<bool>& present,
                          MeshVertices& out)
{
  if (present.size() != static_cast<std::size_t>(controlCount()) || displacements.rows() != controlCount())
    throw InvalidArgument("deform: the presence mask and displacements must have one entry per control");
  std::vector<Eigen::Index> kept;
  for (std::size_t c = 0; c < present.size(); ++c)
    if (present[c])
      kept.push_back(static_cast<Eigen::Index>(c));
  if (kept.size() == present.size()) {
    deform(displacements, out);
    return;
  }
  if (kept.empty()) {
    out = m_rest;
    return;
  }
  auto found = m_cache.find(present);
  if (found == m_cache.end()) {
    if (m_cache.size() >= 64)
      m_cache.clear();
    found = m_cache.emplace(present, responseFor(present).cast<float>()).first;
  }
  const PointSet subset = displacements(kept, Eigen::all);
  if (!subset.allFinite())
    throw InvalidArgument("deform: a control displacement is not finite");
  addProduct(found->second, subset, out);
}

void MeshDeformer::addProduct(const Eigen::MatrixXf& response, const PointSet& displacements, MeshVertices& out) const
{
  // Column-major single-precision product first (Eigen's fastest layout), then one pass adding
  // it to the rest positions in double.
  const Eigen::Matrix<float, Eigen::Dynamic, 3> moved = response * displacements.cast<float>();
  out = m_rest + moved.cast<double>();
}

void checkDistinctControls(const Eigen::Ref<const PointSet>& controls, double tolerance,
                           const std::vector<std::string>& names)
{
  const auto name = [&](Eigen::Index c) {
    return static_cast<std::size_t>(c) < names.size() ? names[static_cast<std::size_t>(c)] : std::to_string(c + 1);
  };
  for (Eigen::Index a = 0; a < controls.rows(); ++a)
    for (Eigen::Index b = a + 1; b < controls.rows(); ++b)
      if ((controls.row(a) - controls.row(b)).norm() <= tolerance)
        throw InvalidArgument("controls " + name(a) + " and " + name(b) +
                              " are at the same mesh point: bind them to different points or drop one");
}

} // namespace mocap
