#include "mocap/cleaning/fill/regression_fill.h"

#include "mocap/cleaning/border_blend.h"
#include "mocap/base/error.h"
#include "mocap/cleaning/fill/neighbour_selection.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace mocap {

namespace {

// A step this many times a marker's usual large step (95th percentile) is a jump, not motion.
constexpr double kJumpFactor = 10.0;
// Frames used to rank the candidate predictors.
constexpr std::size_t kRankingFrames = 60;

void checkRegressionFillOptions(const RegressionFillOptions& options)
{
  if (options.neighbours < 1 || options.neighbours > 1000)
    throw InvalidArgument("regression fill: neighbours must be in 1..1000");
  if (!(options.ridge >= 0.0) || !std::isfinite(options.ridge))
    throw InvalidArgument("regression fill: the ridge weight must be finite and not negative");
  if (options.maxTrainingFrames < 10)
    throw InvalidArgument("regression fill: at least 10 training frames are needed");
  if (options.window < 1)
    throw InvalidArgument("regression fill: the training window must be at least one frame");
}

// Whether marker j (valid from `from` to `to`) jumps there.
bool jumps(const FillContext& context, Eigen::Index j, Eigen::Index from, Eigen::Index to)
{
  const double limit = kJumpFactor * kJumpFactor * context.usualSquaredStep(j);
  if (!(limit > 0.0))
    return false;
  const auto trajectory = context.take().trajectory(j);
  for (Eigen::Index f = from + 1; f <= to; ++f)
    if ((trajectory.row(f) - trajectory.row(f - 1)).squaredNorm() > limit)
      return true;
  return false;
}

// Candidates valid in at least 3/4 of the grid rows `rows`, ranked by the variance of their
// offset to the marker there (least first).
std::vector<Eigen::Index> steadiest(const FillContext& context, Eigen::Index marker,
                                    const std::vector<Eigen::Index>& candidates,
                                    const std::vector<Eigen::Index>& rows)
{
  const auto count = candidates.size();
  std::vector<Eigen::RowVector3d> sums(count, Eigen::RowVector3d::Zero());
  std::vector<double> squares(count, 0.0);
  std::vector<Eigen::Index> seen(count, 0);
  for (const Eigen::Index r : rows) {
    const double* row = context.row(r);
    const Eigen::Map<const Eigen::RowVector3d> own(row + 3 * marker);
    for (std::size_t c = 0; c < count; ++c) {
      const Eigen::Index j = candidates[c];
      if (!context.valid(r, j))
        continue;
      const Eigen::RowVector3d offset = own - Eigen::Map<const Eigen::RowVector3d>(row + 3 * j);
      sums[c] += offset;
      squares[c] += offset.squaredNorm();
      ++seen[c];
    }
  }
  std::vector<std::pair<double, Eigen::Index>> ranked;
  ranked.reserve(count);
  for (std::size_t c = 0; c < count; ++c) {
    const Eigen::Index n = seen[c];
    if (n < 2 || 4 * n < 3 * static_cast<Eigen::Index>(rows.size()))
      continue;
    const auto size = static_cast<double>(n);
    ranked.emplace_back((squares[c] - sums[c].squaredNorm() / size) / size, candidates[c]);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<Eigen::Index> order;
  order.reserve(ranked.size());
  for (const auto& entry : ranked)
    order.push_back(entry.second);
  return order;
}

void accumulate(RegressionSystem::Sums& sums, const Eigen::MatrixXd& x,
                const Eigen::Matrix<double, Eigen::Dynamic, 3>& y)
{
  sums.frames = x.rows();
  sums.x = x.colwise().sum();
  sums.y = y.colwise().sum();
  sums.xx = Eigen::MatrixXd::Zero(x.cols(), x.cols());
  sums.xy = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(x.cols(), 3);
  if (x.rows() == 0)
    return;  // (Eigen's product kernels divide by the row count)
  sums.xx.selfadjointView<Eigen::Lower>().rankUpdate(x.transpose());
  sums.xx = sums.xx.selfadjointView<Eigen::Lower>();
  sums.xy.noalias() = x.transpose() * y;
}

// Solves A X = B for a small symmetric positive definite A by an unblocked Cholesky
// factorisation A = UᵀU in the upper triangle, column by column (Eigen's blocked LLT spends more
// on workspace than on arithmetic at these sizes); falls back to a pivoted LDLT of the untouched
// lower triangle when A is not numerically positive definite.
Eigen::Matrix<double, Eigen::Dynamic, 3> solveSymmetric(Eigen::MatrixXd a,
                                                        const Eigen::Matrix<double, Eigen::Dynamic, 3>& b)
{
  const Eigen::Index n = a.rows();
  Eigen::VectorXd diagonal(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double pivot = a(j, j) - a.col(j).head(j).squaredNorm();
    if (!(pivot > 0.0))
      return a.selfadjointView<Eigen::Lower>().ldlt().solve(b);
    diagonal(j) = std::sqrt(pivot);
    for (Eigen::Index i = j + 1; i < n; ++i)
      a(j, i) = (a(j, i) - a.col(i).head(j).dot(a.col(j).head(j))) / diagonal(j);
  }
  Eigen::Matrix<double, Eigen::Dynamic, 3> x = b;
  for (Eigen::Index i = 0; i < n; ++i)  // Uᵀ y = b
    x.row(i) = (x.row(i) - a.col(i).head(i).transpose() * x.topRows(i)) / diagonal(i);
  for (Eigen::Index i = n - 1; i >= 0; --i)  // U x = y
    x.row(i) = (x.row(i) - a.row(i).segment(i + 1, n - i - 1) * x.bottomRows(n - i - 1)) / diagonal(i);
  return x;
}

} // namespace

Eigen::MatrixXd predictorTrack(const Take& take, const std::vector<Eigen::Index>& predictors,
                               Eigen::Index first, Eigen::Index length)
{
  const auto count = static_cast<Eigen::Index>(predictors.size());
  Eigen::MatrixXd coordinates(length + 2, 3 * count);
  const Eigen::Index begin = std::max<Eigen::Index>(0, first - 1);
  const Eigen::Index end = std::min(take.frameCount(), first + length + 1);
  coordinates.topRows(begin - first + 1).setZero();  // the border rows outside the take
  coordinates.bottomRows(first + length + 1 - end).setZero();
  for (Eigen::Index k = 0; k < count; ++k)
    coordinates.block(begin - first + 1, 3 * k, end - begin, 3) =
        take.trajectory(predictors[static_cast<std::size_t>(k)]).middleRows(begin, end - begin);
  return coordinates;
}

Eigen::Matrix<double, Eigen::Dynamic, 3> RegressionFit::apply(const Eigen::MatrixXd& coordinates) const
{
  const Eigen::Index n = weights.rows();
  Eigen::Matrix<double, Eigen::Dynamic, 3> out(coordinates.rows(), 3);
  out.rowwise() = targetMean - featureMean * weights;
  out.noalias() += coordinates.leftCols(n).lazyProduct(weights);  // small: no blocked GEMM set-up
  return out;
}

Eigen::Matrix<double, Eigen::Dynamic, 3> RegressionFit::track(const Take& take, Eigen::Index first,
                                                              Eigen::Index length) const
{
  return apply(predictorTrack(take, predictors, first, length));
}

RegressionFit RegressionSystem::solve(Eigen::Index count, double ridge, bool withoutHeldOut) const
{
  RegressionFit fit;
  const bool subtract = withoutHeldOut && heldOut.frames > 0;
  const Eigen::Index frames = all.frames - (subtract ? heldOut.frames : 0);
  count = std::min({count, static_cast<Eigen::Index>(predictors.size()), (frames - 1) / 3});
  if (count < 1)
    return fit;
  const Eigen::Index n = 3 * count;
  const auto size = static_cast<double>(frames);
  Eigen::RowVectorXd meanX = all.x.head(n);
  Eigen::RowVector3d meanY = all.y;
  Eigen::MatrixXd normal = all.xx.topLeftCorner(n, n);
  Eigen::Matrix<double, Eigen::Dynamic, 3> cross = all.xy.topRows(n);
  if (subtract) {
    meanX -= heldOut.x.head(n);
    meanY -= heldOut.y;
    normal -= heldOut.xx.topLeftCorner(n, n);
    cross -= heldOut.xy.topRows(n);
  }
  meanX /= size;
  meanY /= size;
  normal.noalias() -= size * meanX.transpose() * meanX;  // centred sums
  cross.noalias() -= size * meanX.transpose() * meanY;
  normal.diagonal().array() += ridge * std::max(normal.diagonal().mean(), 1e-300);
  fit.weights = solveSymmetric(normal, cross);
  fit.predictors.assign(predictors.begin(), predictors.begin() + count);
  fit.featureMean = meanX + origin.head(n);
  fit.targetMean = meanY + targetOrigin;
  return fit;
}

RegressionSystem buildRegression(const FillContext& context, Eigen::Index marker,
                                 const Eigen::Ref<const ValidMask>& markerValid, Eigen::Index from,
                                 Eigen::Index to, const RegressionFillOptions& options,
                                 const std::vector<FrameRange>& heldOut)
{
  checkRegressionFillOptions(options);
  const Take& take = context.take();
  RegressionSystem system;
  const auto candidates = markersValidThrough(take, marker, from, to);
  if (candidates.empty()) {
    system.reason = "no other marker is valid through the gap and its borders";
    return system;
  }
  // Grid rows within the window where the marker is valid, thinned to the training budget.
  const Eigen::Index stride = context.stride();
  const Eigen::Index firstRow = (std::max<Eigen::Index>(0, from - options.window) + stride - 1) / stride;
  const Eigen::Index lastRow = std::min(take.frameCount() - 1, to + options.window) / stride;
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = firstRow; r <= lastRow; ++r)
    if (markerValid(r * stride))
      rows.push_back(r);
  const auto budget = static_cast<std::size_t>(options.maxTrainingFrames);
  if (rows.size() > budget) {
    std::vector<Eigen::Index> thinned;
    for (std::size_t i = 0; i < budget; ++i)
      thinned.push_back(rows[i * rows.size() / budget]);
    rows.swap(thinned);
  }
  std::vector<Eigen::Index> sample;
  for (std::size_t i = 0; i < rows.size(); i += std::max<std::size_t>(1, rows.size() / kRankingFrames))
    sample.push_back(rows[i]);
  std::vector<Eigen::Index> predictors;
  for (const Eigen::Index j : steadiest(context, marker, candidates, sample)) {
    if (static_cast<int>(predictors.size()) == options.neighbours)
      break;
    if (!jumps(context, j, from, to))
      predictors.push_back(j);
  }
  if (predictors.empty()) {
    system.reason = "no marker valid (without jumps) through the gap is valid in most frames around it";
    return system;
  }

  std::vector<Eigen::Index> kept;
  std::vector<Eigen::Index> held;
  for (const Eigen::Index r : rows) {
    if (!std::all_of(predictors.begin(), predictors.end(),
                     [&](Eigen::Index j) { return context.valid(r, j); }))
      continue;
    const Eigen::Index f = r * stride;
    const bool inside = std::any_of(heldOut.begin(), heldOut.end(), [f](const FrameRange& range) {
      return f >= range.first && f <= range.second;
    });
    (inside ? held : kept).push_back(r);
  }
  const auto count = static_cast<Eigen::Index>(predictors.size());
  if (kept.size() + held.size() < 4) {
    system.reason = "too few frames where the marker and its predictors are valid";
    return system;
  }
  const Eigen::Index reference = kept.empty() ? held.front() : kept.front();
  system.origin.resize(3 * count);
  for (Eigen::Index k = 0; k < count; ++k)
    system.origin.segment<3>(3 * k) = Eigen::Map<const Eigen::RowVector3d>(
        context.row(reference) + 3 * predictors[static_cast<std::size_t>(k)]);
  system.targetOrigin = Eigen::Map<const Eigen::RowVector3d>(context.row(reference) + 3 * marker);
  const auto gather = [&](const std::vector<Eigen::Index>& list, RegressionSystem::Sums& sums) {
    Eigen::MatrixXd x(static_cast<Eigen::Index>(list.size()), 3 * count);
    Eigen::Matrix<double, Eigen::Dynamic, 3> y(x.rows(), 3);
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      const double* row = context.row(list[static_cast<std::size_t>(i)]);
      for (Eigen::Index k = 0; k < count; ++k)
        x.block<1, 3>(i, 3 * k) =
            Eigen::Map<const Eigen::RowVector3d>(row + 3 * predictors[static_cast<std::size_t>(k)]);
      y.row(i) = Eigen::Map<const Eigen::RowVector3d>(row + 3 * marker);
    }
    x.rowwise() -= system.origin;
    y.rowwise() -= system.targetOrigin;
    accumulate(sums, x, y);
  };
  gather(held, system.heldOut);
  gather(kept, system.all);
  system.all.frames += system.heldOut.frames;
  system.all.x += system.heldOut.x;
  system.all.y += system.heldOut.y;
  system.all.xx += system.heldOut.xx;
  system.all.xy += system.heldOut.xy;
  system.predictors = std::move(predictors);
  return system;
}

GapPrediction predictRegression(const GapQuery& gap, const RegressionFillOptions& options,
                                const FillContext* context)
{
  checkRegressionFillOptions(options);
  if (context != nullptr && &context->take() != &gap.take)
    throw InvalidArgument("regression fill: the context belongs to another take");
  const Eigen::Index before = gap.before();
  const Eigen::Index after = gap.after();
  if (before < 0 && after < 0)
    return GapPrediction::failure("the marker has no valid sample");
  std::unique_ptr<FillContext> own;
  if (context == nullptr) {
    own = std::make_unique<FillContext>(gap.take);
    context = own.get();
  }
  const Eigen::Index from = before >= 0 ? before : gap.first;
  const Eigen::Index to = after >= 0 ? after : gap.last();
  const RegressionSystem system = buildRegression(*context, gap.marker, gap.markerValid, from, to, options);
  if (!system.usable())
    return GapPrediction::failure(system.reason);
  const RegressionFit fit = system.solve(options.neighbours, options.ridge);
  if (fit.predictors.empty())
    return GapPrediction::failure("too few frames where the marker and its predictors are valid");
  GapPrediction prediction;
  prediction.method = "regression";
  prediction.positions = blendBorders(gap, fit.track(gap.take, gap.first, gap.length));
  return prediction;
}

} // namespace mocap
