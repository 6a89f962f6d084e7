#include "mocap/cleaning/fill/neighbour_propagation.h"

#include "mocap/math/pi.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mocap {

namespace {

const char* ruleName(PropagationRule rule)
{
  switch (rule) {
  case PropagationRule::Guenter: return "guenter";
  case PropagationRule::LinOuhyoung: return "lin-ouhyoung";
  case PropagationRule::Zhang3: return "zhang3";
  case PropagationRule::ZhangN: return "zhang-n";
  }
  return "?";
}

} // namespace

Eigen::Vector3d zhang3Weights(const Eigen::Vector3d& distances)
{
  const double all = distances.sum();  // eq 3
  Eigen::Vector3d weights;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const double ratio = all > 0.0 ? distances(i) / all : 1.0 / 3.0;
    weights(i) = std::pow((1.0 + std::cos(ratio * kPi)) / 2.0, 4);  // eq 4
  }
  return weights;
}

Eigen::VectorXd zhangNWeights(const Eigen::VectorXd& distances)
{
  if (distances.size() == 0)
    return {};
  const double nearest = distances.minCoeff();   // R_s
  const double farthest = distances.maxCoeff();  // R_f
  if (!(farthest > nearest))
    return Eigen::VectorXd::Ones(distances.size());
  return ((distances.array() - nearest) / (farthest - nearest) * (kPi / 2.5)).cos().matrix();  // eq 6
}

Eigen::VectorXd linOuhyoungWeights(const Eigen::VectorXd& distances)
{
  const Eigen::Index n = distances.size();
  if (n == 0)
    return {};
  const Eigen::Index coincident = (distances.array() <= 0.0).count();
  Eigen::VectorXd weights(n);
  for (Eigen::Index i = 0; i < n; ++i)
    weights(i) = coincident > 0 ? (distances(i) <= 0.0 ? 1.0 : 0.0) : 1.0 / distances(i);
  return weights / weights.sum();
}

GapPrediction propagateFromNeighbours(const GapQuery& gap, PropagationRule rule, int neighbours)
{
  const Eigen::Index start = gap.before() >= 0 ? gap.before() : gap.after();
  if (start < 0)
    return GapPrediction::failure("the marker has no valid sample");
  const bool forward = gap.before() >= 0;  // a gap at frame 0 is recovered backwards in time
  const Eigen::Index wanted = rule == PropagationRule::Zhang3 ? 3 : std::max(1, neighbours);
  const Eigen::Index needed = rule == PropagationRule::Zhang3 ? 3 : 1;
  const Take& take = gap.take;
  const auto valid = take.valid();

  GapPrediction prediction;
  prediction.method = ruleName(rule);
  prediction.positions.resize(gap.length, 3);
  Eigen::RowVector3d position = gap.at(start);
  std::vector<std::pair<double, Eigen::Index>> candidates;
  candidates.reserve(static_cast<std::size_t>(take.markerCount()));
  Eigen::VectorXd distances;
  Eigen::Matrix<double, Eigen::Dynamic, 3> displacements;
  for (Eigen::Index step = 0; step < gap.length; ++step) {
    const Eigen::Index t = forward ? gap.first + step : gap.last() - step;
    const Eigen::Index previous = forward ? t - 1 : t + 1;
    candidates.clear();
    for (Eigen::Index j = 0; j < take.markerCount(); ++j)
      if (j != gap.marker && valid(previous, j) && valid(t, j))
        candidates.emplace_back((take.trajectory(j).row(previous) - position).norm(), j);
    const auto count = std::min<Eigen::Index>(wanted, static_cast<Eigen::Index>(candidates.size()));
    if (count < needed)
      return GapPrediction::failure("frame " + std::to_string(t) + " has " +
                                    std::to_string(candidates.size()) +
                                    " neighbours valid in it and the frame before; " + prediction.method +
                                    " needs " + std::to_string(needed));
    std::partial_sort(candidates.begin(), candidates.begin() + count, candidates.end());
    distances.resize(count);
    displacements.resize(count, 3);
    for (Eigen::Index i = 0; i < count; ++i) {
      const auto& [distance, j] = candidates[static_cast<std::size_t>(i)];
      distances(i) = distance;
      displacements.row(i) = take.trajectory(j).row(t) - take.trajectory(j).row(previous);
    }
    switch (rule) {
    case PropagationRule::Guenter: position += displacements.colwise().mean(); break;
    case PropagationRule::LinOuhyoung:
      position += linOuhyoungWeights(distances).transpose() * displacements;
      break;
    case PropagationRule::Zhang3:
      position += zhang3Weights(distances).transpose() * displacements;  // eq 5
      break;
    case PropagationRule::ZhangN: {
      const Eigen::VectorXd weights = zhangNWeights(distances);
      position += weights.transpose() * displacements / weights.sum();  // eq 7
      break;
    }
    }
    prediction.positions.row(forward ? step : gap.length - 1 - step) = position;
  }
  return prediction;
}

} // namespace mocap
