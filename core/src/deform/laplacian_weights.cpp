#include "mocap/deform/laplacian_weights.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace mocap {

namespace {

constexpr EnumTable<LaplacianWeights, 3> kWeights{{{
    {LaplacianWeights::Uniform, "uniform"},
    {LaplacianWeights::Cotangent, "cotangent"},
    {LaplacianWeights::MeanValue, "mean-value"},
}}};

} // namespace

std::string_view laplacianWeightsName(LaplacianWeights weights)
{
  return kWeights.name(weights, "?");
}

std::string laplacianWeightsNames()
{
  return kWeights.names();
}

std::optional<LaplacianWeights> parseLaplacianWeights(std::string_view name)
{
  return kWeights.parse(name);
}

namespace {

// |a × b| and a·b of the two edges leaving a corner; the angle is atan2(first, second).
std::pair<double, double> corner(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return {a.cross(b).norm(), a.dot(b)};
}

} // namespace

Eigen::SparseMatrix<double> laplacianMatrix(const Eigen::Ref<const MeshVertices>& vertices,
                                            const std::vector<Triangle>& triangles, LaplacianWeights weights)
{
  const Eigen::Index n = vertices.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(triangles.size() * 12);
  const auto addEdge = [&](Eigen::Index i, Eigen::Index j, double w) {
    entries.emplace_back(i, j, -w);
    entries.emplace_back(i, i, w);
  };
  std::map<std::pair<Eigen::Index, Eigen::Index>, bool> uniformSeen;  // uniform: each edge once
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (const Eigen::Index v : tri)
      if (v < 0 || v >= n)
        throw InvalidArgument("laplacian: triangle " + std::to_string(t) + " uses a vertex outside the mesh");
    if (weights == LaplacianWeights::Uniform) {
      for (int e = 0; e < 3; ++e) {
        const Eigen::Index i = tri[static_cast<std::size_t>(e)], j = tri[static_cast<std::size_t>((e + 1) % 3)];
        if (uniformSeen.emplace(std::minmax(i, j), true).second) {
          addEdge(i, j, 1.0);
          addEdge(j, i, 1.0);
        }
      }
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      // Corner at vertex i with neighbours j and l (the other two corners of the triangle).
      const Eigen::Index i = tri[static_cast<std::size_t>(k)];
      const Eigen::Index j = tri[static_cast<std::size_t>((k + 1) % 3)];
      const Eigen::Index l = tri[static_cast<std::size_t>((k + 2) % 3)];
      const Eigen::Vector3d toJ = (vertices.row(j) - vertices.row(i)).transpose();
      const Eigen::Vector3d toL = (vertices.row(l) - vertices.row(i)).transpose();
      const auto [sine, cosine] = corner(toJ, toL);  // scaled by |toJ||toL|
      const double lengths = toJ.norm() * toL.norm();
      if (!(sine > 1e-12 * lengths) || !(lengths > 0.0))
        throw InvalidArgument("laplacian: triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) +
                              ", " + std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
                              ") is degenerate (zero area): " + std::string(laplacianWeightsName(weights)) +
                              " weights are undefined there; fix the mesh or use uniform weights");
      if (weights == LaplacianWeights::Cotangent) {
        // The angle at i is opposite edge jl.
        const double half = 0.5 * cosine / sine;
        addEdge(j, l, half);
        addEdge(l, j, half);
      } else {
        // tan(θ/2) = sin θ / (1 + cos θ), in the scaled form |a×b| / (|a||b| + a·b).
        const double tanHalf = sine / (lengths + cosine);
        addEdge(i, j, tanHalf / toJ.norm());
        addEdge(i, l, tanHalf / toL.norm());
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

Eigen::Index countNonManifoldEdges(const std::vector<Triangle>& triangles)
{
  std::map<std::pair<Eigen::Index, Eigen::Index>, int> uses;
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e)
      ++uses[std::minmax(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)])];
  Eigen::Index count = 0;
  for (const auto& [edge, n] : uses)
    count += n > 2 ? 1 : 0;
  return count;
}

} // namespace mocap
