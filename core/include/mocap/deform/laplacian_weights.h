#pragma once

#include "mocap/model/mesh.h"

#include <Eigen/SparseCore>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Edge weights wᵢⱼ of a mesh Laplacian.
enum class LaplacianWeights
{
  Uniform,    ///< wᵢⱼ = 1 per edge: the paper's eqs 4–5, L = I − D⁻¹A after normalisation
  Cotangent,  ///< wᵢⱼ = (cot αᵢⱼ + cot βᵢⱼ)/2, the angles opposite edge ij (symmetric)
  MeanValue,  ///< wᵢⱼ = (tan(θ¹ᵢⱼ/2) + tan(θ²ᵢⱼ/2)) / ‖vᵢ − vⱼ‖, the paper's eq 6 (convex, not symmetric)
};

/// "uniform", "cotangent", "mean-value". O(1).
[[nodiscard]] std::string_view laplacianWeightsName(LaplacianWeights weights);
/// Every value's name, "a|b|c" (for usage texts and errors). O(#values).
[[nodiscard]] std::string laplacianWeightsNames();
[[nodiscard]] std::optional<LaplacianWeights> parseLaplacianWeights(std::string_view name);

/// The #vertices × #vertices Laplacian K with Kᵢⱼ = −wᵢⱼ for each edge and Kᵢᵢ = Σⱼ wᵢⱼ, so every
/// row sums to zero; symmetric for uniform and cotangent weights. Each triangle adds its edges'
/// terms, so an edge of a non-manifold mesh (shared by more than two triangles) sums the terms of
/// all its triangles and an isolated vertex gets an empty row — documented, not an error.
/// Throws InvalidArgument for cotangent or mean-value weights on a degenerate (zero-area) triangle,
/// naming it, since its angles are undefined; uniform weights accept it. O(#triangles log).
[[nodiscard]] Eigen::SparseMatrix<double> laplacianMatrix(const Eigen::Ref<const MeshVertices>& vertices,
                                                          const std::vector<Triangle>& triangles,
                                                          LaplacianWeights weights);

/// Number of edges shared by more than two triangles (0 for a manifold mesh). O(#triangles log).
[[nodiscard]] Eigen::Index countNonManifoldEdges(const std::vector<Triangle>& triangles);

} // namespace mocap
