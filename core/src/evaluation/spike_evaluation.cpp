#include "mocap/evaluation/spike_evaluation.h"

#include "mocap/base/error.h"
#include "mocap/base/length_unit.h"
#include "mocap/base/random.h"
#include "mocap/math/pi.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap {

namespace {

constexpr Eigen::Index kSpacing = 5;  // frames kept free around each spike and cut gap

// Uniform on the unit sphere (Archimedes: z uniform in [-1, 1], longitude uniform).
Eigen::RowVector3d randomDirection(Random& random)
{
  const double z = 2.0 * random.uniform() - 1.0;
  const double longitude = 2.0 * kPi * random.uniform();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(longitude), r * std::sin(longitude), z};
}

struct Injection
{
  Eigen::Index marker = 0;
  Eigen::Index first = 0;
  Eigen::Index length = 1;
  Eigen::RowVector3d offset = Eigen::RowVector3d::Zero();
};

enum class Shape
{
  Single,
  Block,
  NextToGap,
};

bool isFree(const SampleMask& reserved, Eigen::Index marker, Eigen::Index first, Eigen::Index last)
{
  return first >= 0 && last < reserved.rows() && !reserved.col(marker).segment(first, last - first + 1).any();
}

void reserve(SampleMask& reserved, Eigen::Index marker, Eigen::Index first, Eigen::Index last)
{
  const Eigen::Index from = std::max<Eigen::Index>(0, first - kSpacing);
  const Eigen::Index to = std::min<Eigen::Index>(reserved.rows() - 1, last + kSpacing);
  reserved.col(marker).segment(from, to - from + 1) = true;
}

// Places one spike of `shape` on `truth` (cutting its gap there), or returns false.
bool place(Take& truth, SampleMask& reserved, Random& random, Shape shape,
           const std::vector<Eigen::Index>& markers, Injection& out)
{
  const Eigen::Index frames = truth.frameCount();
  const auto pick = random.below(static_cast<Eigen::Index>(markers.size()));
  const Eigen::Index marker = markers[static_cast<std::size_t>(pick)];
  const Eigen::Index first = random.below(frames);
  const Eigen::Index length = shape == Shape::Block ? 2 + random.below(2) : 1;
  const Eigen::Index last = first + length - 1;
  auto valid = truth.valid().col(marker);
  if (last >= frames || !valid.segment(first, length).all() || !isFree(reserved, marker, first, last))
    return false;
  if (shape == Shape::NextToGap) {
    const bool atRunEnd = first == 0 || last == frames - 1 || !valid(first - 1) || !valid(last + 1);
    if (!atRunEnd) {
      const Eigen::Index gap = 5 + random.below(11);
      const bool after = random.below(2) == 1;
      const Eigen::Index from = after ? last + 1 : std::max<Eigen::Index>(0, first - gap);
      const Eigen::Index to = after ? std::min(frames - 1, last + gap) : first - 1;
      if (!isFree(reserved, marker, from, to))
        return false;
      valid.segment(from, to - from + 1) = false;
      truth.residuals().col(marker).segment(from, to - from + 1) = -1.0;
      reserve(reserved, marker, from, to);
    }
  }
  reserve(reserved, marker, first, last);
  out = {marker, first, length, randomDirection(random)};
  return true;
}

} // namespace

std::vector<SpikeEvaluation> evaluateSpikes(const Take& take, const SpikeEvaluationOptions& options)
{
  if (options.count <= 0)
    throw InvalidArgument("spike count must be > 0, not " + std::to_string(options.count));
  if (!(std::isfinite(options.amplitude) && options.amplitude > 0.0))
    throw InvalidArgument("spike amplitude must be a finite number of millimetres > 0, not " +
                          std::to_string(options.amplitude));
  std::vector<Eigen::Index> markers;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (take.frameCount() > 0 && take.valid().col(m).any())
      markers.push_back(m);
  if (markers.empty())
    throw InvalidArgument("the take has no valid sample to put spikes on");
  checkSpikeOptions(options.detector);
  SpikeOptions detector = options.detector;

  const double toTake = 1.0 / millimetresPer(take.units());
  Take truth = take;
  SampleMask reserved = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  Random random(options.seed);
  std::vector<Injection> injections;
  // Random tries until the count is reached or the take has had no room for a long while.
  constexpr int kMaxMisses = 100000;
  for (int misses = 0; misses < kMaxMisses && static_cast<int>(injections.size()) < options.count;) {
    const auto shape = static_cast<Shape>(injections.size() % 3);
    Injection injection;
    if (!place(truth, reserved, random, shape, markers, injection)) {
      ++misses;
      continue;
    }
    misses = 0;
    injection.offset *= options.amplitude * toTake;
    injections.push_back(injection);
  }
  Take corrupted = truth;
  SampleMask injected = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  for (const Injection& injection : injections) {
    auto xyz = corrupted.trajectory(injection.marker);
    for (Eigen::Index f = injection.first; f < injection.first + injection.length; ++f) {
      xyz.row(f) += injection.offset;
      injected(f, injection.marker) = true;
    }
  }
  const Eigen::Index injectedCount = injected.count();
  const Eigen::Index validCount = truth.valid().count();

  std::vector<SpikeEvaluation> results;
  for (SpikeMethod method : {SpikeMethod::Paper, SpikeMethod::Robust}) {
    detector.method = method;
    SampleMask before = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
    for (const SpikeFlag& flag : detectSpikes(truth, detector))
      before(flag.frame, flag.marker) = true;
    const std::vector<SpikeFlag> flags = detectSpikes(corrupted, detector);
    SpikeEvaluation result;
    result.method = std::string(spikeMethodName(method));
    result.spikes = static_cast<int>(injections.size());
    result.injected = injectedCount;
    for (const SpikeFlag& flag : flags) {
      if (injected(flag.frame, flag.marker))
        ++result.detected;
      else if (!before(flag.frame, flag.marker))
        ++result.falseAlarms;
    }
    result.flaggedBefore = before.count();
    result.cleanSamples = validCount - injectedCount - (before && !injected).count();
    result.falseAlarmRate = result.cleanSamples > 0 ? static_cast<double>(result.falseAlarms) /
                                                          static_cast<double>(result.cleanSamples)
                                                    : 0.0;
    result.recall =
        injectedCount > 0 ? static_cast<double>(result.detected) / static_cast<double>(injectedCount) : 0.0;
    double squares = 0.0;
    Eigen::Index replaced = 0;
    for (const SamplePatch& patch : replaceSpikes(corrupted, flags))
      for (std::size_t i = 0; i < patch.frames.size(); ++i) {
        const Eigen::Index f = patch.frames[i];
        if (!injected(f, patch.marker))
          continue;
        const Eigen::RowVector3d error =
            patch.positions.row(static_cast<Eigen::Index>(i)) - truth.trajectory(patch.marker).row(f);
        squares += error.squaredNorm();
        ++replaced;
      }
    result.restoredRmse = replaced > 0 ? std::sqrt(squares / static_cast<double>(replaced)) / toTake
                                       : std::numeric_limits<double>::quiet_NaN();
    results.push_back(result);
  }
  return results;
}

} // namespace mocap
