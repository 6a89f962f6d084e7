#pragma once

#include "mocap/deform/laplacian_weights.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/deform/mesh_deformer.h"

#include <Eigen/SparseCholesky>

namespace mocap {

struct LaplacianOptions
{
  LaplacianWeights weights = LaplacianWeights::MeanValue;  ///< the paper's eq 6
  double constraintWeight = 1.0;                           ///< w of eq 7
};

/// Laplacian deformation with soft positional constraints, the paper's eq 7:
/// Ṽ = argmin ‖L·V − δ‖² + Σⱼ w²‖cⱼ(V) − targetⱼ‖², with L = D⁻¹K the Laplacian of
/// laplacianMatrix() normalised to unit diagonal (eq 5's I − D⁻¹A for uniform weights) and
/// δ = L·V_rest, so in displacements d = V − V_rest it reads ‖L·d‖² + Σ w²‖cⱼ·d − Δⱼ‖² (cⱼ: the
/// barycentric row of control j). A = LᵀL + w²CᵀC is factorised once by sparse Cholesky (LDLᵀ,
/// AMD ordering); since d = w²A⁻¹CᵀΔ is linear in Δ, the set-up also back-substitutes the
/// #controls columns of Cᵀ, and each frame is one product with that response. A mesh component
/// without any control has one vertex pinned to its rest position, so it stays where it is
/// instead of making A singular. A frame missing some controls uses the Sherman–Morrison–Woodbury
/// downdate of A⁻¹ (no new factorisation). Duplicate controls are accepted: soft constraints
/// average their targets. Set-up O(Cholesky(A) + #controls · nnz(factor)); per frame
/// O(#vertices · #controls).
class LaplacianDeformer : public MeshDeformer
{
public:
  /// Throws InvalidArgument for no controls, a control outside the mesh, a weight ≤ 0 or not
  /// finite, a degenerate triangle with cotangent or mean-value weights (laplacianMatrix), a vertex
  /// whose weights sum to ≤ 0 (cotangent weights on obtuse triangles) or a failed factorisation.
  LaplacianDeformer(MeshVertices rest, const std::vector<Triangle>& triangles, const std::vector<MeshPoint>& controls,
                    const LaplacianOptions& options = {});

  /// The reference per-frame path: builds w²CᵀΔ and back-substitutes it through the stored
  /// factorisation. O(nnz(factor)) per frame; the same result as deform() up to rounding.
  void deformBySubstitution(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const;

  /// Rotation-aware variant (beyond the paper, which keeps δ fixed so rotated regions shear):
  /// starting from the linear solution (missing controls skipped), `iterations` times estimate
  /// each vertex's rotation Rᵢ from its one-ring (kabschRotation of rest edges onto deformed ones),
  /// rotate its differential coordinate δᵢ by it and solve eq 7 again with the stored
  /// factorisation, each missing control held where the previous solution put it (Sorkine et
  /// al. 2004's rotated coordinates, iterated as in ARAP). O(iterations · (nnz(L) + nnz(factor)))
  /// per frame. Throws InvalidArgument for a wrong size, a non-finite displacement or iterations
  /// outside 0 … 100.
  void deformRotationAware(const Eigen::Ref<const PointSet>& displacements, const std::vector<bool>& present,
                           int iterations, MeshVertices& out);

  /// The normalised Laplacian L (unit diagonal, rows sum to zero).
  [[nodiscard]] const Eigen::SparseMatrix<double>& laplacian() const { return m_laplacian; }

protected:
  [[nodiscard]] Eigen::MatrixXd responseFor(const std::vector<bool>& present) const override;

private:
  Eigen::SparseMatrix<double> m_laplacian;
  Eigen::SparseMatrix<double> m_constraints;  // C, #controls × #vertices
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> m_solver;
  Eigen::MatrixXd m_inverseConstraints;  // K = A⁻¹Cᵀ
  Eigen::MatrixXd m_gram;                // H = C·K
  MeshVertices m_delta;                  // δ = L·V_rest, one row per vertex
  double m_weight = 1.0;
};

/// One frame: deformRotationAware with `rotations` iterations when `deformer` is a
/// LaplacianDeformer and rotations > 0, otherwise deformer.deform (missing controls skipped).
void deformFrame(MeshDeformer& deformer, const Eigen::Ref<const PointSet>& displacements,
                 const std::vector<bool>& present, int rotations, MeshVertices& out);

} // namespace mocap
