#include "mocap/cleaning/spike_detection.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/base/length_unit.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/valid_runs.h"

#include "spike_detector_parts.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

namespace mocap {

namespace {

using spikes::Run;
using spikes::Trajectory;

// The valid runs (findValidRuns) as inclusive windows, the form the detectors work on.
std::vector<Run> validRuns(const Eigen::Ref<const ValidMask>& valid)
{
  std::vector<Run> runs;
  for (const ValidRun& run : findValidRuns(valid))
    runs.push_back({run.first, run.first + run.length - 1});
  return runs;
}

constexpr EnumTable<SpikeMethod, 2> kSpikeMethods{{{
    {SpikeMethod::Paper, "paper"},
    {SpikeMethod::Robust, "robust"},
}}};

// One pass of the detector over every valid run of a trajectory whose samples are checked.
std::vector<Eigen::Index> detectOnce(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                                     const SpikeOptions& options, double floor)
{
  std::vector<Eigen::Index> flags;
  spikes::RobustWork work;
  for (const Run& run : validRuns(valid)) {
    if (options.method == SpikeMethod::Paper)
      spikes::detectPaper(xyz, run, options.factor, flags);
    else
      spikes::detectRobust(xyz, run, options.threshold, floor, work, flags);
  }
  return flags;
}

std::vector<Eigen::Index> detectIn(const Trajectory& xyz, const Eigen::Ref<const ValidMask>& valid,
                                   const SpikeOptions& options, double floor)
{
  if (xyz.rows() != valid.size())
    throw InvalidArgument("trajectory has " + std::to_string(xyz.rows()) + " frames but its validity mask " +
                          std::to_string(valid.size()));
  for (Eigen::Index f = 0; f < xyz.rows(); ++f)
    if (valid(f) && !xyz.row(f).allFinite())
      throw InvalidArgument("valid sample at frame " + std::to_string(f) + " is not a finite position");
  std::vector<Eigen::Index> flags = detectOnce(xyz, valid, options, floor);
  if (options.method == SpikeMethod::Paper)
    return flags;  // eq 9 as written: one pass
  // A spike can hide a smaller one beside it (it widens the local scale); once it is replaced,
  // the neighbour stands out. So the detector judges the trajectory again with its flags so far
  // replaced exactly as replaceSpikes will, until a pass adds nothing: repairing the flags and
  // detecting again with the same settings then finds nothing new.
  Eigen::Matrix<double, Eigen::Dynamic, 3> repaired;
  std::vector<Eigen::Index> frames;
  std::vector<Eigen::RowVector3d> positions;
  for (int pass = 1; pass < options.maxPasses && !flags.empty(); ++pass) {
    repaired = xyz;
    frames.clear();
    positions.clear();
    spikes::replaceFlagged(xyz, valid, flags, frames, positions);
    for (std::size_t k = 0; k < frames.size(); ++k)
      repaired.row(frames[k]) = positions[k];
    const std::vector<Eigen::Index> again = detectOnce(repaired, valid, options, floor);
    std::vector<Eigen::Index> merged;
    merged.reserve(flags.size() + again.size());
    std::set_union(flags.begin(), flags.end(), again.begin(), again.end(), std::back_inserter(merged));
    if (merged.size() == flags.size())
      break;
    flags = std::move(merged);
  }
  return flags;
}

} // namespace

void checkSpikeOptions(const SpikeOptions& options)
{
  if (!(std::isfinite(options.factor) && options.factor > 0.0))
    throw InvalidArgument("spike factor must be a finite number > 0, not " + std::to_string(options.factor));
  if (!(std::isfinite(options.threshold) && options.threshold > 0.0))
    throw InvalidArgument("spike threshold must be a finite number > 0, not " +
                          std::to_string(options.threshold));
  if (!(std::isfinite(options.noiseFloor) && options.noiseFloor >= 0.0))
    throw InvalidArgument("spike noise floor must be a finite number >= 0, not " +
                          std::to_string(options.noiseFloor));
  if (options.maxPasses < 1 || options.maxPasses > 100)
    throw InvalidArgument("spike detection passes must be in 1..100, not " + std::to_string(options.maxPasses));
}

std::optional<SpikeMethod> parseSpikeMethod(std::string_view name)
{
  return kSpikeMethods.parse(name);
}

std::string_view spikeMethodName(SpikeMethod method)
{
  return kSpikeMethods.name(method, "robust");
}

std::string spikeMethodNames()
{
  return kSpikeMethods.names();
}

std::vector<Eigen::Index> detectSpikes(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& xyz,
                                       const Eigen::Ref<const ValidMask>& valid, const SpikeOptions& options)
{
  checkSpikeOptions(options);
  return detectIn(xyz, valid, options, options.noiseFloor);
}

std::vector<SpikeFlag> detectSpikes(const Take& take, const SpikeOptions& options, const JobControl& job)
{
  checkSpikeOptions(options);
  const double floor = options.noiseFloor / millimetresPer(take.units());
  std::vector<SpikeFlag> flags;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    job.checkpoint(static_cast<double>(m) / static_cast<double>(take.markerCount()));
    if (!isMarker(take, m))
      continue;
    std::vector<Eigen::Index> frames;
    try {
      frames = detectIn(take.trajectory(m), take.valid().col(m), options, floor);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("marker " + take.label(m) + ": " + e.what());
    }
    for (Eigen::Index f : frames)
      flags.push_back({m, f});
  }
  return flags;
}

} // namespace mocap
