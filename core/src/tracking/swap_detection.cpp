#include "mocap/tracking/swap_detection.h"

#include "mocap/base/error.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <cmath>

namespace mocap {

namespace {

constexpr double kJumpQuantile = 0.95;

void checkSwapOptions(const SwapOptions& options)
{
  if (!(options.jumpFactor >= 2.0 && options.jumpFactor <= 1000.0))
    throw InvalidArgument("swap detection: the jump factor must be in [2, 1000]");
  if (!(options.minJump >= 0.0) || !std::isfinite(options.minJump))
    throw InvalidArgument("swap detection: the minimum jump must be a finite distance ≥ 0");
  if (!(options.swappedFraction > 0.0 && options.swappedFraction < 1.0))
    throw InvalidArgument("swap detection: the swapped fraction must be in (0, 1)");
}

bool predictable(const Take& take, Eigen::Index frame, Eigen::Index marker)
{
  return frame >= 2 && take.isValid(frame, marker) && take.isValid(frame - 1, marker) &&
         take.isValid(frame - 2, marker);
}

Eigen::Vector3d prediction(const Take& take, Eigen::Index frame, Eigen::Index marker)
{
  return 2.0 * take.position(frame - 1, marker) - take.position(frame - 2, marker);
}

} // namespace

Eigen::VectorXd jumpThresholds(const Take& take, const SwapOptions& options)
{
  checkSwapOptions(options);
  const double floor = options.minJump > 0.0 ? options.minJump : 1.0 / millimetresPer(take.units());
  Eigen::VectorXd threshold = Eigen::VectorXd::Constant(take.markerCount(), floor);
  std::vector<double> errors;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    errors.clear();
    for (Eigen::Index f = 2; f < take.frameCount(); ++f)
      if (predictable(take, f, m))
        errors.push_back((take.position(f, m) - prediction(take, f, m)).norm());
    if (errors.empty())
      continue;
    const auto k = static_cast<std::ptrdiff_t>(kJumpQuantile * static_cast<double>(errors.size() - 1));
    std::nth_element(errors.begin(), errors.begin() + k, errors.end());
    const double typical = errors[static_cast<std::size_t>(k)];
    if (std::isfinite(typical))
      threshold(m) = std::max(floor, options.jumpFactor * typical);
  }
  return threshold;
}

SampleMask findJumps(const Take& take, const SwapOptions& options)
{
  const Eigen::VectorXd threshold = jumpThresholds(take, options);
  SampleMask jumps = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  for (const Eigen::Index m : markerPoints(take))
    for (Eigen::Index f = 2; f < take.frameCount(); ++f)
      jumps(f, m) = predictable(take, f, m) && (take.position(f, m) - prediction(take, f, m)).norm() > threshold(m);
  return jumps;
}

namespace {

// The best explained swap among the jumping markers of one frame, if any.
std::vector<LabelSwap> swapsAt(const Take& take, Eigen::Index frame, const std::vector<Eigen::Index>& jumping,
                               const Eigen::VectorXd& error, const SwapOptions& options)
{
  std::vector<LabelSwap> candidates;
  for (std::size_t i = 0; i < jumping.size(); ++i) {
    for (std::size_t j = i + 1; j < jumping.size(); ++j) {
      const Eigen::Index a = jumping[i];
      const Eigen::Index b = jumping[j];
      const double ab = (take.position(frame, b) - prediction(take, frame, a)).norm();
      const double ba = (take.position(frame, a) - prediction(take, frame, b)).norm();
      if (std::max(ab, ba) < options.swappedFraction * std::min(error(a), error(b)))
        candidates.push_back({frame, std::min(a, b), std::max(a, b), error(a) + error(b), ab + ba});
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const LabelSwap& x, const LabelSwap& y) { return x.explained / x.jump < y.explained / y.jump; });
  std::vector<LabelSwap> chosen;
  std::vector<Eigen::Index> used;
  for (const LabelSwap& swap : candidates) {
    if (std::find(used.begin(), used.end(), swap.first) != used.end() ||
        std::find(used.begin(), used.end(), swap.second) != used.end())
      continue;
    chosen.push_back(swap);
    used.push_back(swap.first);
    used.push_back(swap.second);
  }
  return chosen;
}

} // namespace

std::vector<LabelSwap> repairSwaps(Take& take, const SwapOptions& options, const JobControl& job)
{
  checkSwapOptions(options);
  std::vector<LabelSwap> swaps;
  if (take.empty())
    return swaps;
  const Eigen::VectorXd threshold = jumpThresholds(take, options);
  Eigen::VectorXd error = Eigen::VectorXd::Zero(take.markerCount());
  const std::vector<Eigen::Index> markers = markerPoints(take);
  std::vector<Eigen::Index> jumping;
  for (Eigen::Index f = 2; f < take.frameCount(); ++f) {
    job.checkpoint(static_cast<double>(f) / static_cast<double>(take.frameCount()));
    jumping.clear();
    for (const Eigen::Index m : markers) {  // a model output's jump is no swap, and never a partner
      if (!predictable(take, f, m))
        continue;
      error(m) = (take.position(f, m) - prediction(take, f, m)).norm();
      if (error(m) > threshold(m))
        jumping.push_back(m);
    }
    if (jumping.size() < 2)
      continue;
    for (const LabelSwap& swap : swapsAt(take, f, jumping, error, options)) {
      exchangeMarkersFrom(take, swap.first, swap.second, f);
      swaps.push_back(swap);
    }
  }
  return swaps;
}

std::vector<LabelSwap> detectSwaps(const Take& take, const SwapOptions& options, const JobControl& job)
{
  Take copy = take;
  return repairSwaps(copy, options, job);
}

} // namespace mocap
