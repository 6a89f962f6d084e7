#include "mocap/cleaning/fill/pca_fill.h"

#include "mocap/cleaning/border_blend.h"
#include "mocap/base/error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>

namespace mocap {

namespace {

constexpr Eigen::Index kMinCompleteFrames = 20;

// Linear interpolation of a marker's missing samples (held at the take's ends): EM's starting point.
void interpolateMissing(Eigen::Ref<Eigen::MatrixXd> block, const Eigen::Ref<const ValidMask>& valid)
{
  const Eigen::Index frames = block.rows();
  Eigen::Index previous = -1;
  for (Eigen::Index f = 0; f <= frames; ++f) {
    if (f < frames && !valid(f))
      continue;
    for (Eigen::Index g = previous + 1; g < f; ++g) {
      if (previous < 0)
        block.row(g) = block.row(f);
      else if (f == frames)
        block.row(g) = block.row(previous);
      else {
        const double s = static_cast<double>(g - previous) / static_cast<double>(f - previous);
        block.row(g) = (1.0 - s) * block.row(previous) + s * block.row(f);
      }
    }
    previous = f;
  }
}

struct Model
{
  Eigen::RowVectorXd mean;
  Eigen::MatrixXd components;
  Eigen::VectorXd variances;
  double noise = 0.0;
};

Model fitModel(const Eigen::MatrixXd& data, double varianceKept)
{
  Model model;
  model.mean = data.colwise().mean();
  const Eigen::MatrixXd centred = data.rowwise() - model.mean;
  const Eigen::MatrixXd covariance =
      (centred.transpose() * centred) / static_cast<double>(std::max<Eigen::Index>(1, data.rows() - 1));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
  const Eigen::VectorXd values = eigen.eigenvalues().reverse().cwiseMax(0.0);
  const double total = values.sum();
  Eigen::Index kept = 1;
  double explained = values(0);
  while (kept < values.size() - 1 && explained < varianceKept * total)
    explained += values(kept++);
  model.components = eigen.eigenvectors().rowwise().reverse().leftCols(kept);
  model.variances = values.head(kept);
  const Eigen::Index dropped = values.size() - kept;
  model.noise = dropped > 0 ? values.tail(dropped).mean() : 0.0;
  // A floor keeps Λ⁻¹ and σ² finite on noiseless (e.g. synthetic) data.
  const double floor = 1e-12 * std::max(total, 1e-300);
  model.noise = std::max(model.noise, floor);
  model.variances = model.variances.cwiseMax(floor);
  return model;
}

// Conditional mean of the coordinates of `missing` blocks given the others, for each row of `frames`.
void reconstructRows(const Eigen::RowVectorXd& mean, const Eigen::MatrixXd& components,
                     const Eigen::VectorXd& variances, double noise, const std::vector<Eigen::Index>& missing,
                     const std::vector<Eigen::Index>& frames, Eigen::MatrixXd& data)
{
  const Eigen::Index blocks = data.cols() / 3;
  std::vector<bool> isMissing(static_cast<std::size_t>(blocks), false);
  for (const Eigen::Index b : missing)
    isMissing[static_cast<std::size_t>(b)] = true;
  std::vector<Eigen::Index> known;
  for (Eigen::Index b = 0; b < blocks; ++b)
    if (!isMissing[static_cast<std::size_t>(b)])
      for (Eigen::Index c = 0; c < 3; ++c)
        known.push_back(3 * b + c);
  const Eigen::Index k = components.cols();
  const Eigen::MatrixXd knownBasis = components(known, Eigen::all);
  Eigen::MatrixXd normal = knownBasis.transpose() * knownBasis;
  normal.diagonal() += noise * variances.cwiseInverse();
  const Eigen::LDLT<Eigen::MatrixXd> solver(normal);
  Eigen::VectorXd coefficients(k);
  for (const Eigen::Index f : frames) {
    const Eigen::VectorXd centred = (data(f, known) - mean(known)).transpose();
    coefficients = solver.solve(knownBasis.transpose() * centred);
    for (const Eigen::Index b : missing)
      data.block<1, 3>(f, 3 * b) =
          mean.segment<3>(3 * b) + (components.middleRows<3>(3 * b) * coefficients).transpose();
  }
}

} // namespace

PcaFillModel::PcaFillModel(const Take& take, const PcaFillOptions& options) : m_take(&take)
{
  if (!(options.varianceKept > 0.0 && options.varianceKept <= 1.0))
    throw InvalidArgument("pca fill: the variance kept must be in (0, 1]");
  if (options.iterations < 1 || options.iterations > 1000)
    throw InvalidArgument("pca fill: iterations must be in 1..1000");
  if (!(options.minValidFraction >= 0.0 && options.minValidFraction <= 1.0))
    throw InvalidArgument("pca fill: the minimum valid fraction must be in [0, 1]");
  const Eigen::Index frames = take.frameCount();
  m_column.assign(static_cast<std::size_t>(take.markerCount()), -1);
  const auto valid = take.valid();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const Eigen::Index count = valid.col(m).count();
    if (count >= 2 && static_cast<double>(count) >= options.minValidFraction * static_cast<double>(frames)) {
      m_column[static_cast<std::size_t>(m)] = static_cast<Eigen::Index>(m_markers.size());
      m_markers.push_back(m);
    }
  }
  const auto blocks = static_cast<Eigen::Index>(m_markers.size());
  if (blocks < 2 || frames < 3) {
    m_unusableReason = "the PCA model needs two markers valid in enough frames";
    return;
  }
  m_completed.resize(frames, 3 * blocks);
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index m = m_markers[static_cast<std::size_t>(b)];
    m_completed.middleCols<3>(3 * b) = take.trajectory(m);
    interpolateMissing(m_completed.middleCols<3>(3 * b), valid.col(m));
  }

  // Frames grouped by their set of missing markers: one factorisation per set.
  std::map<std::vector<Eigen::Index>, std::vector<Eigen::Index>> patterns;
  std::vector<Eigen::Index> complete;
  for (Eigen::Index f = 0; f < frames; ++f) {
    std::vector<Eigen::Index> missing;
    for (Eigen::Index b = 0; b < blocks; ++b)
      if (!valid(f, m_markers[static_cast<std::size_t>(b)]))
        missing.push_back(b);
    if (missing.empty())
      complete.push_back(f);
    else
      patterns[missing].push_back(f);
  }

  const auto completeCount = static_cast<Eigen::Index>(complete.size());
  Model model = completeCount >= kMinCompleteFrames
                    ? fitModel(m_completed(complete, Eigen::all), options.varianceKept)
                    : fitModel(m_completed, options.varianceKept);
  const double scale = std::max(1e-12, (m_completed.rowwise() - model.mean).norm());
  for (int iteration = 0; iteration < options.iterations && !patterns.empty(); ++iteration) {
    const Eigen::MatrixXd previous = m_completed;
    for (const auto& [missing, rows] : patterns)
      reconstructRows(model.mean, model.components, model.variances, model.noise, missing, rows, m_completed);
    if ((m_completed - previous).norm() <= 1e-9 * scale || iteration + 1 == options.iterations)
      break;
    model = fitModel(m_completed, options.varianceKept);
  }
  m_mean = model.mean;
  m_components = model.components;
  m_variances = model.variances;
  m_noise = model.noise;
}

Eigen::Matrix<double, Eigen::Dynamic, 3> PcaFillModel::reconstructSpan(Eigen::Index first, Eigen::Index last,
                                                                       Eigen::Index marker) const
{
  const auto blocks = static_cast<Eigen::Index>(m_markers.size());
  const Eigen::Index own = m_column[static_cast<std::size_t>(marker)];
  Eigen::MatrixXd rows = m_completed.middleRows(first, last - first + 1);
  // Consecutive frames with the same missing markers share one factorisation.
  std::vector<Eigen::Index> pattern;
  std::vector<Eigen::Index> frames;
  const auto flush = [&] {
    if (!frames.empty())
      reconstructRows(m_mean, m_components, m_variances, m_noise, pattern, frames, rows);
    frames.clear();
  };
  for (Eigen::Index f = first; f <= last; ++f) {
    std::vector<Eigen::Index> missing;
    for (Eigen::Index b = 0; b < blocks; ++b)
      if (b == own || !m_take->isValid(f, m_markers[static_cast<std::size_t>(b)]))
        missing.push_back(b);
    if (missing != pattern) {
      flush();
      pattern = std::move(missing);
    }
    frames.push_back(f - first);
  }
  flush();
  return rows.middleCols<3>(3 * own);
}

GapPrediction PcaFillModel::predict(const GapQuery& gap) const
{
  if (&gap.take != m_take)
    throw InvalidArgument("pca fill: the gap is not from the take the model was built from");
  if (!usable())
    return GapPrediction::failure(m_unusableReason);
  if (m_column[static_cast<std::size_t>(gap.marker)] < 0)
    return GapPrediction::failure("the marker is valid in too few frames for the PCA model");
  const Eigen::Index first = std::max<Eigen::Index>(0, gap.first - 1);
  const Eigen::Index last = std::min(m_take->frameCount() - 1, gap.last() + 1);
  BorderedTrack track = BorderedTrack::Zero(gap.length + 2, 3);
  track.middleRows(first - (gap.first - 1), last - first + 1) = reconstructSpan(first, last, gap.marker);
  GapPrediction prediction;
  prediction.method = "pca";
  prediction.positions = blendBorders(gap, track);
  return prediction;
}

} // namespace mocap
