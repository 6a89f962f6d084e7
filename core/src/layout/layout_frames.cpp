#include "mocap/layout/layout_frames.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/math/kabsch.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace mocap {

Eigen::Index LayoutFrames::rowOf(std::size_t take, Eigen::Index frame) const
{
  const auto it = std::lower_bound(origin.begin(), origin.end(), std::make_pair(take, frame));
  return it != origin.end() && *it == std::make_pair(take, frame)
             ? static_cast<Eigen::Index>(it - origin.begin())
             : -1;
}

namespace {

std::vector<Eigen::Index> indicesOf(const Take& take, const std::vector<std::string>& labels,
                                    std::size_t takeNumber, const char* what)
{
  std::vector<Eigen::Index> indices;
  std::set<std::string> seen;
  for (const std::string& label : labels) {
    const auto m = take.markerIndex(label);
    if (!m)
      throw InvalidArgument(std::string(what) + " marker '" + label + "' is not in take " +
                            std::to_string(takeNumber + 1));
    if (!seen.insert(label).second)
      throw InvalidArgument(std::string(what) + " marker '" + label + "' is given twice");
    indices.push_back(*m);
  }
  return indices;
}

} // namespace

std::vector<std::string> defaultPlannedLabels(const Take& take, const std::vector<std::string>& excluded)
{
  std::vector<std::string> labels;
  for (const std::string& label : markerLabels(take))
    if (!isUnlabelledLabel(label) && std::find(excluded.begin(), excluded.end(), label) == excluded.end())
      labels.push_back(label);
  return labels;
}

LayoutFrames collectLayoutFrames(const std::vector<Take>& takes, const LayoutFramesOptions& options)
{
  if (takes.empty())
    throw InvalidArgument("layout planning needs at least one take");
  if (!(options.blockSeconds > 0.0) || !std::isfinite(options.blockSeconds) || options.holdoutEvery < 2)
    throw InvalidArgument("layout planning: blockSeconds must be positive and holdoutEvery at least 2");
  LayoutFrames result;
  result.labels = options.markers.empty() ? defaultPlannedLabels(takes.front(), options.stabilizeLabels)
                                          : options.markers;
  for (const std::string& label : result.labels)
    if (std::find(options.stabilizeLabels.begin(), options.stabilizeLabels.end(), label) !=
        options.stabilizeLabels.end())
      throw InvalidArgument("layout planning: reference marker '" + label + "' cannot also be planned");
  const Eigen::Index markers = result.markerCount();
  if (markers < 2)
    throw InvalidArgument("layout planning needs at least two markers, got " + std::to_string(markers));
  result.stabilized = !options.stabilizeLabels.empty();

  std::vector<Eigen::MatrixXd> blocks;
  PointSet firstMean;
  for (std::size_t t = 0; t < takes.size(); ++t) {
    Take take = takes[t];
    take.convertUnits(LengthUnit::Millimetre);
    const std::vector<Eigen::Index> planned = indicesOf(take, result.labels, t, "planned");
    if (result.stabilized)
      removeHeadMotion(take,
                       estimateHeadMotion(take, indicesOf(take, options.stabilizeLabels, t, "reference")));
    std::vector<Eigen::Index> frames;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      bool usable = true;
      for (const Eigen::Index m : planned)
        usable = usable && take.isValid(f, m);
      if (!usable) {
        ++result.droppedFrames;
        continue;
      }
      for (const Eigen::Index m : planned)
        if (!take.position(f, m).allFinite())
          throw InvalidArgument("layout planning: marker '" + take.label(m) +
                                "' has a non-finite valid sample in frame " +
                                std::to_string(take.firstFrame() + f) + " of take " + std::to_string(t + 1));
      frames.push_back(f);
    }
    Eigen::MatrixXd block(static_cast<Eigen::Index>(frames.size()), 3 * markers);
    for (std::size_t i = 0; i < frames.size(); ++i)
      for (Eigen::Index j = 0; j < markers; ++j)
        block.row(static_cast<Eigen::Index>(i)).segment<3>(3 * j) =
            take.position(frames[i], planned[static_cast<std::size_t>(j)]).transpose();
    if (block.rows() > 0) {
      // Later sessions join the first one's head frame: one rigid fit of the mean shapes.
      PointSet mean(markers, 3);
      const Eigen::RowVectorXd average = block.colwise().mean();
      for (Eigen::Index j = 0; j < markers; ++j)
        mean.row(j) = average.segment<3>(3 * j);
      if (firstMean.size() == 0) {
        firstMean = mean;
      } else {
        const Eigen::Isometry3d fit = kabsch(mean, firstMean);
        for (Eigen::Index r = 0; r < block.rows(); ++r)
          for (Eigen::Index j = 0; j < markers; ++j)
            block.row(r).segment<3>(3 * j) =
                (fit * Eigen::Vector3d(block.row(r).segment<3>(3 * j).transpose())).transpose();
      }
    }
    // Blocks of blockSeconds in take time; the last block of every holdoutEvery is held apart.
    const double blockFrames = std::max(1.0, std::round(options.blockSeconds * take.frameRate()));
    const auto base = static_cast<Eigen::Index>(result.origin.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const auto blockIndex = static_cast<long long>(static_cast<double>(frames[i]) / blockFrames);
      const bool held = blockIndex % options.holdoutEvery == options.holdoutEvery - 1;
      (held ? result.test : result.training).push_back(base + static_cast<Eigen::Index>(i));
      result.origin.emplace_back(t, frames[i]);
    }
    blocks.push_back(std::move(block));
  }
  Eigen::Index rows = 0;
  for (const auto& block : blocks)
    rows += block.rows();
  result.frames.resize(rows, 3 * markers);
  Eigen::Index at = 0;
  for (const auto& block : blocks) {
    result.frames.middleRows(at, block.rows()) = block;
    at += block.rows();
  }
  const auto training = static_cast<Eigen::Index>(result.training.size());
  if (training < 3 * markers + 1)
    throw InvalidArgument("layout planning: " + std::to_string(training) + " training frames for " +
                          std::to_string(3 * markers) + " features (" + std::to_string(markers) +
                          " markers); need at least " + std::to_string(3 * markers + 1) +
                          " frames with every planned marker valid");
  if (result.test.empty())
    throw InvalidArgument("layout planning: no frames left for testing");
  return result;
}

} // namespace mocap
