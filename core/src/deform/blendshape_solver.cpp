#include "mocap/deform/blendshape_solver.h"

#include "mocap/base/stopwatch.h"
#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/math/banded_cholesky.h"
#include "mocap/math/bounded_least_squares.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace mocap {

namespace {

constexpr EnumTable<BlendshapeSolveMethod, 3> kSolveMethods{{{
    {BlendshapeSolveMethod::Bvls, "bvls"},
    {BlendshapeSolveMethod::Ridge, "ridge"},
    {BlendshapeSolveMethod::Temporal, "temporal"},
}}};

using Mask = std::vector<bool>;

void checkSolveOptions(const BlendshapeSolveOptions& options)
{
  const auto nonNegative = [](double v) { return v >= 0.0 && std::isfinite(v); };
  if (options.lambda && !nonNegative(*options.lambda))
    throw InvalidArgument("blendshape solve: λ must be finite and ≥ 0");
  if (!nonNegative(options.smoothness))
    throw InvalidArgument("blendshape solve: the smoothness must be finite and ≥ 0");
  if (!nonNegative(options.sparsity))
    throw InvalidArgument("blendshape solve: the sparsity must be finite and ≥ 0");
  if (!(options.minimumMarkerShare >= 0.0 && options.minimumMarkerShare <= 1.0))
    throw InvalidArgument("blendshape solve: the minimum marker share must be in [0, 1]");
  if (!(options.maximumWeight > 0.0 && std::isfinite(options.maximumWeight)))
    throw InvalidArgument("blendshape solve: the maximum weight must be finite and > 0");
}

/// The shapes' deltas at the bound points (3·#points × #shapes). O(#points · #shapes · log).
Eigen::MatrixXd sampleShapes(const BlendshapeRig& rig, const std::vector<MeshPoint>& points)
{
  Eigen::MatrixXd a(3 * static_cast<Eigen::Index>(points.size()), rig.shapeCount());
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s) {
    const SparseShape& shape = rig.shapes[static_cast<std::size_t>(s)];
    for (std::size_t m = 0; m < points.size(); ++m) {
      Eigen::Vector3d delta = Eigen::Vector3d::Zero();
      for (int c = 0; c < 3; ++c)
        delta += points[m].weights(c) * shape.deltaOf(points[m].vertices[static_cast<std::size_t>(c)]);
      a.block<3, 1>(3 * static_cast<Eigen::Index>(m), s) = delta;
    }
  }
  return a;
}

/// Every frame's retargeted displacements of the used markers (#frames × 3·#used, zero where
/// missing) and which are present.
struct Observations
{
  Eigen::MatrixXd b;
  std::vector<Mask> present;  // per frame, per used marker
  std::vector<bool> solvable; // enough markers present
};

Observations observe(const Take& take, const std::vector<Eigen::Index>& used, const PointSet& neutral,
                     const Retarget& retarget, std::size_t minimumMarkers)
{
  Observations o;
  const auto count = static_cast<Eigen::Index>(used.size());
  o.b = Eigen::MatrixXd::Zero(take.frameCount(), 3 * count);
  o.present.resize(static_cast<std::size_t>(take.frameCount()));
  o.solvable.resize(static_cast<std::size_t>(take.frameCount()));
  PointSet displacements;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    Mask& present = o.present[static_cast<std::size_t>(f)];
    controlDisplacements(take, used, neutral, retarget, f, displacements, present);
    std::size_t n = 0;
    for (Eigen::Index m = 0; m < count; ++m)
      if (present[static_cast<std::size_t>(m)]) {
        o.b.block<1, 3>(f, 3 * m) = displacements.row(m);
        ++n;
      }
    o.solvable[static_cast<std::size_t>(f)] = n >= minimumMarkers;
  }
  return o;
}

Eigen::MatrixXd presentRows(const Eigen::MatrixXd& a, const Mask& present)
{
  Eigen::Index rows = 0;
  for (const bool p : present)
    rows += p ? 3 : 0;
  Eigen::MatrixXd out(rows, a.cols());
  Eigen::Index r = 0;
  for (std::size_t m = 0; m < present.size(); ++m)
    if (present[m]) {
      out.middleRows<3>(r) = a.middleRows<3>(3 * static_cast<Eigen::Index>(m));
      r += 3;
    }
  return out;
}

/// RMS over the present markers of |A·w − b| per marker, in take units.
double frameResidual(const Eigen::MatrixXd& a, const Eigen::RowVectorXd& b, const Mask& present,
                     const Eigen::VectorXd& w, double uniformScale)
{
  const Eigen::VectorXd fit = a * w;
  double sum = 0.0;
  int n = 0;
  for (std::size_t m = 0; m < present.size(); ++m)
    if (present[m]) {
      const auto row = 3 * static_cast<Eigen::Index>(m);
      sum += (fit.segment<3>(row) - b.segment<3>(row).transpose()).squaredNorm();
      ++n;
    }
  return n > 0 ? std::sqrt(sum / n) / uniformScale : std::numeric_limits<double>::quiet_NaN();
}

/// Complete frames as columns, for GCV.
Eigen::MatrixXd completeFrames(const Observations& o)
{
  std::vector<Eigen::Index> rows;
  for (std::size_t f = 0; f < o.present.size(); ++f)
    if (std::all_of(o.present[f].begin(), o.present[f].end(), [](bool p) { return p; }))
      rows.push_back(static_cast<Eigen::Index>(f));
  Eigen::MatrixXd b(o.b.cols(), static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    b.col(static_cast<Eigen::Index>(i)) = o.b.row(rows[i]).transpose();
  return b;
}

/// Per-frame bounded solves, one factorised problem per pattern of present markers, each frame
/// warm-started from the previous one; 0 ≤ w ≤ `upper` per shape.
void solvePerFrame(const Eigen::MatrixXd& a, const Observations& o, double ridge, double sparsity,
                   const Eigen::VectorXd& upper, const JobControl& control, Eigen::MatrixXd& weights)
{
  const Eigen::Index shapes = a.cols();
  const Eigen::VectorXd lower = Eigen::VectorXd::Zero(shapes);
  std::map<Mask, std::unique_ptr<BoundedLeastSquares>> solvers;
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(shapes);
  const auto frames = static_cast<Eigen::Index>(o.present.size());
  constexpr Eigen::Index kBlock = 512;
  Eigen::Index blockStart = 0, blockEnd = 0;
  Eigen::MatrixXd atbBlock;
  Eigen::VectorXd atb;
  BoundedLeastSquares::Workspace workspace;
  for (Eigen::Index f = 0; f < frames; ++f) {
    const Mask& present = o.present[static_cast<std::size_t>(f)];
    if (o.solvable[static_cast<std::size_t>(f)]) {
      auto& solver = solvers[present];
      if (!solver)
        solver = std::make_unique<BoundedLeastSquares>(presentRows(a, present), lower, upper, ridge);
      // Aᵀb for a block of frames at once (one matrix product; a missing marker's entries of b
      // are zero, so they add nothing, as its dropped rows would not).
      if (f >= blockEnd) {
        blockStart = f;
        blockEnd = std::min(frames, f + kBlock);
        atbBlock.noalias() = a.transpose() * o.b.middleRows(blockStart, blockEnd - blockStart).transpose();
      }
      atb = atbBlock.col(f - blockStart);
      atb.array() -= sparsity;
      solver->solveNormal(atb, previous, true, workspace);
    }
    weights.row(f) = previous.transpose();
    if (f % 256 == 0)
      control.checkpoint(static_cast<double>(f) / static_cast<double>(frames));
  }
}

/// The least share of an isolated expression a shape's weight is scaled back up from: a shape the
/// markers barely see is shrunk hard by the ridge, and undoing more would blow its noise up.
constexpr double kMinimumResponse = 0.5;

/// Per shape, what the per-frame bounded ridge solve reports for the actor's full expression of
/// that shape alone (b = A·e_s·extent_s, noise-free, box [0, upper]) over what it should
/// (extent_s), clamped to [kMinimumResponse, 1]; 1 for a shape that moves no bound point. A held
/// expression is also the temporal solve's answer (its second differences vanish). The whole take
/// of an actor is shrunk less than this where shapes overlap, yet far more nearly so than a
/// range-of-motion take's usual solve (short peaks smoothed, GCV's λ of a sparse take). Not a
/// paper equation. O(#shapes · the bounded solve).
Eigen::VectorXd isolatedResponse(const Eigen::MatrixXd& a, const Eigen::VectorXd& extent, const Eigen::VectorXd& upper,
                                 double ridge)
{
  const Eigen::Index shapes = a.cols();
  Eigen::VectorXd response = Eigen::VectorXd::Ones(shapes);
  const BoundedLeastSquares solver(a, Eigen::VectorXd::Zero(shapes), upper, ridge);
  for (Eigen::Index s = 0; s < shapes; ++s)
    if (a.col(s).squaredNorm() > 0.0)
      response(s) = std::clamp(solver.solve(a.col(s) * extent(s))(s) / extent(s), kMinimumResponse, 1.0);
  return response;
}

/// μ given at 100 Hz for a take at `rate`: second differences shrink with the square of the
/// sample interval while the data term grows with the sample count, so μ scales with rate⁴.
double temporalWeight(double muAt100Hz, double rate)
{
  return rate > 0.0 && std::isfinite(rate) ? muAt100Hz * std::pow(rate / 100.0, 4.0) : muAt100Hz;
}

/// Lower band (half-bandwidth 2) of c·I + μ·DᵀD, D the (n−2) × n second-difference operator.
BandedCholesky::Band temporalBand(Eigen::Index n, double c, double mu)
{
  BandedCholesky::Band band = BandedCholesky::Band::Zero(n, 3);
  band.col(0).setConstant(c);
  const double d[3] = {1.0, -2.0, 1.0};
  for (Eigen::Index r = 0; r + 2 < n; ++r)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j <= i; ++j)
        band(r + i, i - j) += mu * d[i] * d[j];
  return band;
}

/// The whole take at once: min Σₜ ½‖Aₜwₜ − bₜ‖² + ½λ‖wₜ‖² + s·Σwₜ + ½μ‖D·W‖², 0 ≤ W ≤ 1, by ADMM
/// (Boyd et al. 2011, over-relaxed) splitting the quadratic from the box (upper bound `upper` per shape). With AᵀA = VΛVᵀ the
/// quadratic step decouples into #shapes pentadiagonal systems along time, factorised once, so an
/// iteration costs O(#frames · #shapes²). Missing markers' rows are imputed from the current
/// weights each iteration (the majorise-minimise step for dropped rows). Returns the iterations.
int solveTemporal(const Eigen::MatrixXd& a, const Observations& o, double ridge, double mu, double sparsity,
                  const Eigen::VectorXd& upper, const JobControl& control, Eigen::MatrixXd& weights)
{
  const Eigen::Index frames = o.b.rows(), shapes = a.cols();
  const Eigen::MatrixXd gram = a.transpose() * a;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  const Eigen::VectorXd g = eigen.eigenvalues().cwiseMax(0.0);
  // ρ starts at a tenth of the mean eigenvalue and is rebalanced (Boyd et al. §3.4.1) whenever
  // one residual outgrows the other tenfold; refactorising is O(#frames · #shapes).
  double rho = std::max(0.1 * g.mean() + ridge, 1e-300);
  std::vector<BandedCholesky> factors(static_cast<std::size_t>(shapes));
  const auto factorise = [&] {
    for (Eigen::Index k = 0; k < shapes; ++k)
      factors[static_cast<std::size_t>(k)] = BandedCholesky(temporalBand(frames, g(k) + ridge + rho, mu));
  };
  factorise();

  // Aᵀb of the present rows, and per incomplete frame its missing markers.
  Eigen::MatrixXd atb = o.b * a;
  atb.array() -= sparsity;
  std::vector<std::pair<Eigen::Index, std::vector<Eigen::Index>>> incomplete;
  for (Eigen::Index f = 0; f < frames; ++f) {
    const Mask& present = o.present[static_cast<std::size_t>(f)];
    const bool solvable = o.solvable[static_cast<std::size_t>(f)];
    std::vector<Eigen::Index> missing;
    for (std::size_t m = 0; m < present.size(); ++m)
      if (!present[m] || !solvable)
        missing.push_back(static_cast<Eigen::Index>(m));
    if (!solvable)
      atb.row(f).setConstant(-sparsity);
    if (!missing.empty())
      incomplete.emplace_back(f, std::move(missing));
  }

  constexpr double kAlpha = 1.6, kTolerance = 1e-5;
  constexpr int kMaxIterations = 2000;
  const double scale = std::sqrt(static_cast<double>(frames * shapes));
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(frames, shapes), z = x, u = x, rhs(frames, shapes);
  int iteration = 0;
  while (iteration < kMaxIterations) {
    ++iteration;
    rhs = atb + rho * (z - u);
    for (const auto& [f, missing] : incomplete)
      for (const Eigen::Index m : missing) {
        const auto rows = a.middleRows<3>(3 * m);
        rhs.row(f).noalias() += (rows.transpose() * (rows * x.row(f).transpose())).transpose();
      }
    Eigen::MatrixXd y = rhs * v;
    for (Eigen::Index k = 0; k < shapes; ++k)
      factors[static_cast<std::size_t>(k)].solveInPlace(y.col(k));
    x.noalias() = y * v.transpose();
    const Eigen::MatrixXd relaxed = kAlpha * x + (1.0 - kAlpha) * z;
    Eigen::MatrixXd zNew = (relaxed + u).cwiseMax(0.0);
    for (Eigen::Index k = 0; k < shapes; ++k)
      zNew.col(k) = zNew.col(k).cwiseMin(upper(k));
    u += relaxed - zNew;
    const double primal = (x - zNew).norm(), dual = (zNew - z).norm();
    z = zNew;
    if (primal < kTolerance * scale && dual < kTolerance * scale)
      break;
    if (primal > 10.0 * dual || dual > 10.0 * primal) {
      const double factor = primal > dual ? 2.0 : 0.5;
      rho *= factor;
      u /= factor;
      factorise();
    }
    if (iteration % 16 == 0)
      control.checkpoint(static_cast<double>(iteration) / kMaxIterations);
  }
  weights = z;
  return iteration;
}

} // namespace

std::string_view blendshapeSolveMethodName(BlendshapeSolveMethod method)
{
  return kSolveMethods.name(method, "temporal");
}

std::string blendshapeSolveMethodNames()
{
  return kSolveMethods.names();
}

std::optional<BlendshapeSolveMethod> parseBlendshapeSolveMethod(std::string_view name)
{
  return kSolveMethods.parse(name);
}

double chooseRidgeLambda(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& b,
                         double termScale)
{
  if (b.rows() != a.rows())
    throw InvalidArgument("GCV: the frames have " + std::to_string(b.rows()) + " rows, the matrix " +
                          std::to_string(a.rows()));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a.transpose() * a);
  const Eigen::VectorXd g = eigen.eigenvalues().cwiseMax(0.0);
  // β²ₖ summed over frames: the squared components of b along A's left singular vectors.
  const Eigen::MatrixXd c = eigen.eigenvectors().transpose() * (a.transpose() * b);
  Eigen::VectorXd beta2 = Eigen::VectorXd::Zero(g.size());
  const double tiny = 1e-12 * std::max(g.maxCoeff(), 1e-300);
  for (Eigen::Index k = 0; k < g.size(); ++k)
    if (g(k) > tiny)
      beta2(k) = c.row(k).squaredNorm() / g(k);
  const double total = b.squaredNorm(), n = static_cast<double>(a.rows());
  double best = 1e-3, bestScore = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 100; ++i) {
    const double relative = std::pow(10.0, -8.0 + 0.1 * i), lambda = relative * termScale;
    double residual = total, trace = 0.0;
    for (Eigen::Index k = 0; k < g.size(); ++k) {
      const double shrink = lambda / (g(k) + lambda);
      residual -= beta2(k) * (1.0 - shrink * shrink);
      trace += g(k) / (g(k) + lambda);
    }
    if (n - trace <= 1e-9)
      continue;
    const double score = n * std::max(residual, 0.0) / ((n - trace) * (n - trace));
    if (score < bestScore) {
      bestScore = score;
      best = relative;
    }
  }
  return best;
}

BlendshapeSolver::BlendshapeSolver(const BlendshapeRig& rig, const MeshBinding& binding, const Take& take,
                                   const BlendshapeSolveOptions& options)
    : m_options(options)
{
  const Stopwatch setup;
  checkSolveOptions(options);
  checkRig(rig);
  if (options.actor) {
    if (take.units() != options.actor->units)
      throw InvalidArgument("the take is in " + std::string(unitName(take.units())) + ", the actor's neutral in " +
                            std::string(unitName(options.actor->units)));
    std::vector<std::string> labels;
    for (const MarkerBinding& marker : binding.markers)
      labels.push_back(marker.label);
    const std::vector<Eigen::Index> markers = markerIndices(take, labels);
    const Eigen::Index frame = options.neutralFrame ? chooseNeutralFrame(take, markers, options.neutralFrame) : -1;
    m_bound = bindTakeToNeutral(binding, take, rig.neutral.vertices,
                                placeActorNeutral(actorNeutral(*options.actor, labels), take, markers, frame),
                                options.scale);
  } else {
    m_bound = bindTake(binding, take, rig.neutral.vertices, options.neutralFrame, options.scale);
  }
  m_rigShapes = sampleShapes(rig, m_bound.points);
  m_extent = options.actor ? actorExtents(*options.actor, rig.shapeNames())
                           : Eigen::VectorXd::Ones(m_rigShapes.cols());
  m_a = m_rigShapes * m_extent.asDiagonal();
  m_termScale = std::max(m_rigShapes.squaredNorm() / static_cast<double>(m_rigShapes.cols()), 1e-300);
  m_setupSeconds = setup.seconds();
}

BlendshapeSolveResult BlendshapeSolver::solve(const Take& take, const std::vector<bool>& use,
                                              const JobControl& control) const
{
  const Stopwatch solveTime;
  if (!use.empty() && use.size() != m_bound.markers.size())
    throw InvalidArgument("blendshape solve: " + std::to_string(use.size()) + " marker flags for " +
                          std::to_string(m_bound.markers.size()) + " bound markers");
  if (!m_bound.fits(take))
    throw InvalidArgument("the take no longer has the markers or frames the solver was set up with");
  std::vector<Eigen::Index> used;
  Mask usedRows;
  for (std::size_t m = 0; m < m_bound.markers.size(); ++m) {
    const bool on = use.empty() || use[m];
    usedRows.push_back(on);
    if (on)
      used.push_back(m_bound.markers[m]);
  }
  if (used.empty())
    throw InvalidArgument("blendshape solve: no marker is used");
  // Solved in the rig's units (w = extent · the actor's weight), so that λ (and GCV's choice of
  // it), μ and the sparsity shrink each shape as they do without a profile; only the box becomes
  // the actor's, [0, maximum · extent]. Solving A·diag(extent) instead would weigh a shape's ridge
  // and smoothness by 1 / extent² (and rescale λ's unit with trace(AᵀA)), so the profile would also
  // change how much each shape is shrunk, not only its unit.
  const Eigen::MatrixXd a = presentRows(m_rigShapes, usedRows);
  const Eigen::VectorXd upper = m_options.maximumWeight * m_extent;
  const auto minimum = std::max<std::size_t>(
      std::min<std::size_t>(3, used.size()),
      static_cast<std::size_t>(std::ceil(m_options.minimumMarkerShare * static_cast<double>(used.size()))));
  PointSet neutral(static_cast<Eigen::Index>(used.size()), 3);
  for (std::size_t m = 0, row = 0; m < usedRows.size(); ++m)
    if (usedRows[m])
      neutral.row(static_cast<Eigen::Index>(row++)) = m_bound.neutralMarkers.row(static_cast<Eigen::Index>(m));
  const Observations o = observe(take, used, neutral, m_bound.retarget, minimum);

  BlendshapeSolveResult result;
  if (m_options.method == BlendshapeSolveMethod::Bvls) {
    result.lambda = 0.0;
  } else if (m_options.lambda) {
    result.lambda = *m_options.lambda;
  } else {
    const Eigen::MatrixXd complete = completeFrames(o);
    result.lambdaChosen = complete.cols() > 0;
    result.lambda = result.lambdaChosen ? chooseRidgeLambda(a, complete, m_termScale) : 1e-3;
  }
  const double ridge = result.lambda * m_termScale, sparsity = m_options.sparsity * m_termScale;
  // An actor calibrated from a range-of-motion take: 1 is the actor's full expression as this
  // solve reports it, so the ridge's shrinkage of an expression is undone in the actor's units
  // (and the box follows, keeping the weights within maximumWeight).
  const Eigen::VectorXd unit =
      m_options.actor && !m_options.actor->romSource.empty() && ridge > 0.0
          ? Eigen::VectorXd(m_extent.cwiseProduct(isolatedResponse(a, m_extent, upper, ridge)))
          : m_extent;
  const Eigen::VectorXd box = m_options.maximumWeight * unit;
  result.weights.resize(take.frameCount(), m_a.cols());
  if (m_options.method == BlendshapeSolveMethod::Temporal)
    result.iterations =
        solveTemporal(a, o, ridge, temporalWeight(m_options.smoothness * m_termScale, take.frameRate()), sparsity,
                      box, control, result.weights);
  else
    solvePerFrame(a, o, ridge, sparsity, box, control, result.weights);

  result.held.resize(o.solvable.size());
  result.residual.resize(take.frameCount());
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    const auto i = static_cast<std::size_t>(f);
    result.held[i] = !o.solvable[i];
    if (result.held[i]) {
      result.weights.row(f) = f > 0 ? Eigen::RowVectorXd(result.weights.row(f - 1))
                                    : Eigen::RowVectorXd::Zero(m_a.cols());
      result.residual(f) = std::numeric_limits<double>::quiet_NaN();
    } else {
      result.residual(f) = frameResidual(a, o.b.row(f), o.present[i], result.weights.row(f).transpose(),
                                         m_bound.retarget.uniformScale);
    }
  }
  result.weights *= unit.cwiseInverse().asDiagonal();  // the actor's units
  result.solveSeconds = solveTime.seconds();
  return result;
}

} // namespace mocap
