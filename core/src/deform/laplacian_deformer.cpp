#include "mocap/deform/laplacian_deformer.h"

#include "mocap/base/error.h"
#include "mocap/math/kabsch.h"
#include "mocap/math/union_find.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <string>

namespace mocap {

namespace {

// Component label of every vertex (union-find over the triangles' edges).
std::vector<Eigen::Index> components(Eigen::Index vertexCount, const std::vector<Triangle>& triangles)
{
  UnionFind sets(vertexCount);
  for (const Triangle& t : triangles)
    for (int e = 1; e < 3; ++e)
      sets.unite(t[static_cast<std::size_t>(e)], t[0]);
  std::vector<Eigen::Index> label(static_cast<std::size_t>(vertexCount));
  for (Eigen::Index v = 0; v < vertexCount; ++v)
    label[static_cast<std::size_t>(v)] = sets.find(v);
  return label;
}

// L = D⁻¹K with D = diag(K); an isolated vertex keeps an empty row.
Eigen::SparseMatrix<double> normalised(const Eigen::SparseMatrix<double>& k, const std::string& weights)
{
  Eigen::VectorXd scale(k.rows());
  for (Eigen::Index i = 0; i < k.rows(); ++i) {
    const double d = k.coeff(i, i);
    const bool isolated = k.col(i).nonZeros() == 0;  // the structure is symmetric
    if (!isolated && !(d > 0.0))
      throw InvalidArgument("laplacian: the " + weights + " weights of vertex " + std::to_string(i) +
                            " sum to " + std::to_string(d) + " (obtuse triangles); use mean-value weights");
    scale(i) = isolated ? 0.0 : 1.0 / d;
  }
  return scale.asDiagonal() * k;
}

} // namespace

LaplacianDeformer::LaplacianDeformer(MeshVertices rest, const std::vector<Triangle>& triangles,
                                     const std::vector<MeshPoint>& controls, const LaplacianOptions& options)
    : MeshDeformer(std::move(rest)), m_weight(options.constraintWeight)
{
  const Eigen::Index n = this->rest().rows();
  if (controls.empty())
    throw InvalidArgument("laplacian: no controls");
  if (!(m_weight > 0.0) || !std::isfinite(m_weight) || m_weight > 1e6)
    throw InvalidArgument("laplacian: the constraint weight must be in (0, 1e6]");
  m_laplacian = normalised(laplacianMatrix(this->rest(), triangles, options.weights),
                           std::string(laplacianWeightsName(options.weights)));
  std::vector<Eigen::Triplet<double>> entries;
  const std::vector<Eigen::Index> component = components(n, triangles);
  std::vector<bool> controlled(static_cast<std::size_t>(n), false);
  for (std::size_t c = 0; c < controls.size(); ++c)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index v = controls[c].vertices[static_cast<std::size_t>(k)];
      if (v < 0 || v >= n)
        throw InvalidArgument("laplacian: control " + std::to_string(c + 1) + " is bound off the mesh (vertex " +
                              std::to_string(v) + ")");
      if (controls[c].weights(k) != 0.0) {
        entries.emplace_back(static_cast<Eigen::Index>(c), v, controls[c].weights(k));
        controlled[static_cast<std::size_t>(component[static_cast<std::size_t>(v)])] = true;
      }
    }
  m_constraints.resize(static_cast<Eigen::Index>(controls.size()), n);
  m_constraints.setFromTriplets(entries.begin(), entries.end());

  Eigen::SparseMatrix<double> a = Eigen::SparseMatrix<double>(m_laplacian.transpose()) * m_laplacian;
  a += (m_weight * m_weight) * Eigen::SparseMatrix<double>(m_constraints.transpose() * m_constraints);
  // Pin one vertex of every component no control reaches (its root), so A is positive definite.
  std::vector<Eigen::Triplet<double>> pins;
  for (Eigen::Index v = 0; v < n; ++v)
    if (component[static_cast<std::size_t>(v)] == v && !controlled[static_cast<std::size_t>(v)])
      pins.emplace_back(v, v, 1.0);
  Eigen::SparseMatrix<double> pinned(n, n);
  pinned.setFromTriplets(pins.begin(), pins.end());
  a += pinned;
  m_solver.compute(a);
  if (m_solver.info() != Eigen::Success || (m_solver.vectorD().array() <= 0.0).any())
    throw InvalidArgument("laplacian: the system could not be factorised (is a control bound to an isolated "
                          "part of the mesh?)");
  m_delta = m_laplacian * this->rest();
  m_inverseConstraints = m_solver.solve(Eigen::MatrixXd(m_constraints.transpose()));
  m_gram = m_constraints * m_inverseConstraints;
  setResponse((m_weight * m_weight) * m_inverseConstraints);
}

void LaplacianDeformer::deformBySubstitution(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const
{
  if (displacements.rows() != controlCount() || !displacements.allFinite())
    throw InvalidArgument("laplacian: one finite displacement per control needed");
  const Eigen::MatrixXd rhs = (m_weight * m_weight) * (m_constraints.transpose() * displacements);
  out = rest();
  out += m_solver.solve(rhs);
}

void LaplacianDeformer::deformRotationAware(const Eigen::Ref<const PointSet>& displacements,
                                            const std::vector<bool>& present, int iterations, MeshVertices& out)
{
  if (iterations < 0 || iterations > 100)
    throw InvalidArgument("laplacian: rotation iterations must be in 0 … 100");
  deform(displacements, present, out);
  const double w2 = m_weight * m_weight;
  const Eigen::Index n = rest().rows();
  // Targets: present controls as given, missing ones where the linear solution put them.
  Eigen::Matrix<double, Eigen::Dynamic, 3> targets = m_constraints * (out - rest());
  for (std::size_t c = 0; c < present.size(); ++c)
    if (present[c])
      targets.row(static_cast<Eigen::Index>(c)) = displacements.row(static_cast<Eigen::Index>(c));
  const Eigen::Matrix<double, Eigen::Dynamic, 3> constraintTerm = w2 * (m_constraints.transpose() * targets);
  // Lᵀ: its column i lists row i of L, i.e. vertex i's one-ring.
  const Eigen::SparseMatrix<double> rows = m_laplacian.transpose();
  Eigen::Matrix<double, Eigen::Dynamic, 3> rotated(n, 3);
  for (int it = 0; it < iterations; ++it) {
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for (Eigen::SparseMatrix<double>::InnerIterator entry(rows, i); entry; ++entry) {
        const Eigen::Index j = entry.row();
        if (j == i)
          continue;
        covariance += (out.row(j) - out.row(i)).transpose() * (rest().row(j) - rest().row(i));
      }
      rotated.row(i) = (kabschRotation(covariance) * m_delta.row(i).transpose()).transpose();
    }
    const Eigen::Matrix<double, Eigen::Dynamic, 3> rhs = rows * (rotated - m_delta) + constraintTerm;
    out = rest() + m_solver.solve(rhs);
  }
}

void deformFrame(MeshDeformer& deformer, const Eigen::Ref<const PointSet>& displacements,
                 const std::vector<bool>& present, int rotations, MeshVertices& out)
{
  if (rotations > 0)
    if (auto* laplacian = dynamic_cast<LaplacianDeformer*>(&deformer)) {
      laplacian->deformRotationAware(displacements, present, rotations, out);
      return;
    }
  deformer.deform(displacements, present, out);
}

Eigen::MatrixXd LaplacianDeformer::responseFor(const std::vector<bool>& present) const
{
  std::vector<Eigen::Index> kept, missing;
  for (std::size_t c = 0; c < present.size(); ++c)
    (present[c] ? kept : missing).push_back(static_cast<Eigen::Index>(c));
  // A' = A − w²C_MᵀC_M, so A'⁻¹ = A⁻¹ + K_M (I/w² − H_MM)⁻¹ K_Mᵀ (Woodbury) and the response
  // w²A'⁻¹C_Pᵀ = w²(K_P + K_M (I/w² − H_MM)⁻¹ H_MP).
  const double w2 = m_weight * m_weight;
  const Eigen::MatrixXd small =
      Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(missing.size()), static_cast<Eigen::Index>(missing.size())) /
          w2 -
      m_gram(missing, missing);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(small);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-12 / w2))
    throw InvalidArgument("laplacian: without the missing controls a part of the mesh has no control left");
  const Eigen::MatrixXd correction = ldlt.solve(Eigen::MatrixXd(m_gram(missing, kept)));
  return w2 * (m_inverseConstraints(Eigen::all, kept) + m_inverseConstraints(Eigen::all, missing) * correction);
}

} // namespace mocap
