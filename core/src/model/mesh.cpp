#include "mocap/model/mesh.h"

#include "mocap/base/error.h"

#include <algorithm>
#include <string>

namespace mocap {

std::vector<Triangle> Mesh::triangles() const
{
  std::vector<Triangle> result;
  result.reserve(faces.size() * 2);
  for (const MeshFace& face : faces)
    for (std::size_t i = 1; i + 1 < face.vertices.size(); ++i)
      result.push_back({face.vertices[0], face.vertices[i], face.vertices[i + 1]});
  return result;
}

double Mesh::size() const
{
  if (vertices.rows() == 0)
    return 0.0;
  return (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

namespace {

void checkIndices(const std::vector<Eigen::Index>& indices, Eigen::Index count, std::size_t corners,
                  std::size_t face, const char* what)
{
  if (indices.empty())
    return;
  if (indices.size() != corners)
    throw InvalidArgument("mesh: face " + std::to_string(face) + " has " + std::to_string(indices.size()) + " " +
                          what + " indices for " + std::to_string(corners) + " corners");
  for (const Eigen::Index i : indices)
    if (i < 0 || i >= count)
      throw InvalidArgument("mesh: face " + std::to_string(face) + " uses " + what + " " + std::to_string(i) +
                            " of " + std::to_string(count));
}

} // namespace

void checkMesh(const Mesh& mesh)
{
  if (!mesh.vertices.allFinite() || !mesh.uvs.allFinite() || !mesh.normals.allFinite())
    throw InvalidArgument("mesh: a coordinate is not finite");
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const MeshFace& face = mesh.faces[f];
    if (face.vertices.size() < 3)
      throw InvalidArgument("mesh: face " + std::to_string(f) + " has fewer than 3 vertices");
    checkIndices(face.vertices, mesh.vertexCount(), face.vertices.size(), f, "vertex");
    checkIndices(face.uvs, mesh.uvs.rows(), face.vertices.size(), f, "uv");
    checkIndices(face.normals, mesh.normals.rows(), face.vertices.size(), f, "normal");
    std::vector<Eigen::Index> sorted = face.vertices;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw InvalidArgument("mesh: face " + std::to_string(f) + " repeats a vertex");
  }
}

} // namespace mocap
