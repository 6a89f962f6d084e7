#include "mocap/deform/rbf_deformer.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/math/smooth_step.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace mocap {

namespace {

constexpr EnumTable<RbfKernel, 4> kKernels{{{
    {RbfKernel::Exp, "exp"},
    {RbfKernel::Gaussian, "gaussian"},
    {RbfKernel::Biharmonic, "biharmonic"},
    {RbfKernel::ThinPlate, "thin-plate"},
}}};

} // namespace

std::string_view rbfKernelName(RbfKernel kernel)
{
  return kKernels.name(kernel, "?");
}

std::string rbfKernelNames()
{
  return kKernels.names();
}

std::optional<RbfKernel> parseRbfKernel(std::string_view name)
{
  return kKernels.parse(name);
}

double rbfKernel(RbfKernel kernel, double r, double c)
{
  switch (kernel) {
  case RbfKernel::Exp: return std::exp(-r / c);
  case RbfKernel::Gaussian: return std::exp(-(r / c) * (r / c));
  case RbfKernel::Biharmonic: return r;
  case RbfKernel::ThinPlate: return r > 0.0 ? r * r * std::log(r) : 0.0;
  }
  return 0.0;
}

namespace {

// φ(‖aᵢ − bⱼ‖) for every row pair.
Eigen::MatrixXd kernelMatrix(const Eigen::Ref<const PointSet>& a, const Eigen::Ref<const PointSet>& b,
                             const RbfOptions& options)
{
  Eigen::MatrixXd phi(a.rows(), b.rows());
  for (Eigen::Index j = 0; j < b.rows(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      phi(i, j) = rbfKernel(options.kernel, (a.row(i) - b.row(j)).norm(), options.radius);
  return phi;
}

// [x y z 1] rows, the affine block.
Eigen::MatrixXd affineRows(const Eigen::Ref<const PointSet>& points)
{
  Eigen::MatrixXd q(points.rows(), 4);
  q.leftCols<3>() = points;
  q.col(3).setOnes();
  return q;
}

} // namespace

RbfDeformer::RbfDeformer(MeshVertices rest, const Eigen::Ref<const PointSet>& controls, const RbfOptions& options)
    : MeshDeformer(std::move(rest)), m_controls(controls), m_options(options)
{
  if (controls.rows() == 0)
    throw InvalidArgument("rbf: no controls");
  if (!controls.allFinite() || !this->rest().allFinite())
    throw InvalidArgument("rbf: a control or vertex coordinate is not finite");
  if (!(options.radius > 0.0) || !std::isfinite(options.radius))
    throw InvalidArgument("rbf: the radius must be a positive number");
  if (options.upAxis < 0 || options.upAxis > 2 || !(options.blendWidth > 0.0) || options.blendWidth > 0.5)
    throw InvalidArgument("rbf: up axis must be 0, 1 or 2 and the blend width in (0, 0.5]");
  const double size = (controls.colwise().maxCoeff() - controls.colwise().minCoeff()).norm();
  checkDistinctControls(controls, 1e-9 * std::max(size, 1e-300));
  setResponse(buildResponse(m_controls));
}

Eigen::MatrixXd RbfDeformer::responseFor(const std::vector<bool>& present) const
{
  std::vector<Eigen::Index> kept;
  for (std::size_t c = 0; c < present.size(); ++c)
    if (present[c])
      kept.push_back(static_cast<Eigen::Index>(c));
  return buildResponse(m_controls(kept, Eigen::all));
}

namespace {

// S = [[Φ Q]; [Qᵀ 0]] of eq 2 (Q = [x y z 1] rows only with the affine term).
Eigen::MatrixXd controlSystem(const PointSet& controls, const RbfOptions& options)
{
  const Eigen::Index k = controls.rows();
  const Eigen::Index size = k + (options.affine ? 4 : 0);
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(size, size);
  system.topLeftCorner(k, k) = kernelMatrix(controls, controls, options);
  if (options.affine) {
    const Eigen::MatrixXd q = affineRows(controls);
    system.topRightCorner(k, 4) = q;
    system.bottomLeftCorner(4, k) = q.transpose();
  }
  return system;
}

// M for one set of controls without regions: [Φ_vc Q_v] · (the first #controls columns of S⁻¹).
Eigen::MatrixXd singleResponse(const MeshVertices& rest, const PointSet& controls, const RbfOptions& options)
{
  const Eigen::Index k = controls.rows();
  const bool affine = options.affine;
  if (affine && k < 4)
    throw InvalidArgument("rbf: the affine term needs at least 4 controls, there are " + std::to_string(k) +
                          " (use fewer regions or turn the affine term off)");
  const Eigen::MatrixXd system = controlSystem(controls, options);
  const Eigen::Index size = system.rows();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  if (!lu.isInvertible() || lu.rcond() < 1e-14)
    throw InvalidArgument(std::string("rbf: the control system is singular (") +
                          (affine ? "coplanar controls with the affine term, or " : "") +
                          "a kernel that cannot separate these controls; try another kernel or radius)");
  const Eigen::MatrixXd inverse = lu.solve(Eigen::MatrixXd::Identity(size, k));
  Eigen::MatrixXd basis(rest.rows(), size);
  basis.leftCols(k) = kernelMatrix(rest, controls, options);
  if (affine)
    basis.rightCols<4>() = affineRows(rest);
  return basis * inverse;
}

} // namespace

Eigen::MatrixXd RbfDeformer::buildResponse(const PointSet& controls) const
{
  if (!m_options.regions)
    return singleResponse(rest(), controls, m_options);
  // Top, middle and bottom thirds of the controls' height; each region's RBF sees its controls and
  // those within the blend band, so the blended field still interpolates every control.
  const Eigen::VectorXd height = controls.col(m_options.upAxis);
  const double low = height.minCoeff();
  const double span = height.maxCoeff() - low;
  if (!(span > 0.0))
    throw InvalidArgument("rbf: --regions needs controls at different heights");
  const double band = m_options.blendWidth * span;
  const double borders[2] = {low + span / 3.0, low + 2.0 * span / 3.0};
  const std::size_t minimum = std::min<std::size_t>(static_cast<std::size_t>(controls.rows()), m_options.affine ? 4 : 1);
  Eigen::MatrixXd response = Eigen::MatrixXd::Zero(rest().rows(), controls.rows());
  for (int region = 0; region < 3; ++region) {
    const double from = region == 0 ? -std::numeric_limits<double>::infinity() : borders[region - 1] - band;
    const double to = region == 2 ? std::numeric_limits<double>::infinity() : borders[region] + band;
    std::vector<Eigen::Index> members;
    for (Eigen::Index c = 0; c < controls.rows(); ++c)
      if (height(c) >= from && height(c) <= to)
        members.push_back(c);
    // A sparse region borrows the controls nearest in height, so its system stays solvable.
    if (members.size() < minimum) {
      std::vector<Eigen::Index> order(static_cast<std::size_t>(controls.rows()));
      std::iota(order.begin(), order.end(), Eigen::Index{0});
      const double centre = region == 0 ? low : region == 2 ? low + span : 0.5 * (borders[0] + borders[1]);
      std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
        return std::abs(height(a) - centre) < std::abs(height(b) - centre);
      });
      order.resize(minimum);
      members = order;
      std::sort(members.begin(), members.end());
    }
    const Eigen::MatrixXd part = singleResponse(rest(), controls(members, Eigen::all), m_options);
    for (Eigen::Index v = 0; v < rest().rows(); ++v) {
      const double y = rest()(v, m_options.upAxis);
      const double below = region == 0 ? 1.0 : smoothStep((y - (borders[region - 1] - band)) / (2.0 * band));
      const double above = region == 2 ? 0.0 : smoothStep((y - (borders[region] - band)) / (2.0 * band));
      const double weight = below - above;  // partition of unity over the three regions
      if (weight == 0.0)
        continue;
      for (std::size_t j = 0; j < members.size(); ++j)
        response(v, members[j]) += weight * part(v, static_cast<Eigen::Index>(j));
    }
  }
  return response;
}

void RbfDeformer::deformDirect(const Eigen::Ref<const PointSet>& displacements, MeshVertices& out) const
{
  if (displacements.rows() != m_controls.rows())
    throw InvalidArgument("rbf: one displacement per control needed");
  const Eigen::Index k = m_controls.rows();
  const Eigen::MatrixXd system = controlSystem(m_controls, m_options);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(system.rows(), 3);
  rhs.topRows(k) = displacements;
  const Eigen::MatrixXd weights = system.fullPivLu().solve(rhs);
  out = rest();
  for (Eigen::Index v = 0; v < rest().rows(); ++v) {
    Eigen::RowVector3d d = Eigen::RowVector3d::Zero();
    for (Eigen::Index c = 0; c < k; ++c)
      d += weights.row(c) * rbfKernel(m_options.kernel, (rest().row(v) - m_controls.row(c)).norm(), m_options.radius);
    if (m_options.affine)
      d += rest().row(v) * weights.middleRows(k, 3) + weights.row(k + 3);
    out.row(v) += d;
  }
}

} // namespace mocap
