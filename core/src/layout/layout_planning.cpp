#include "mocap/layout/layout_planning.h"

#include "mocap/base/text.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/layout/layout_symmetry.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <optional>
#include <set>
#include <string>

namespace mocap {

namespace {

using Field = LayoutRequestError::Field;

// The planned markers: the patterns' matches among the marker points (model outputs are never
// planned) or the default set, without the excluded ones.
std::vector<std::string> plannedLabels(const Take& first, const LayoutRequest& request)
{
  std::vector<std::string> planned = request.markerPatterns.empty()
                                         ? defaultPlannedLabels(first, request.stabilizeLabels)
                                         : labelsMatching(markerLabels(first), request.markerPatterns, Field::Markers);
  if (!request.excludePatterns.empty()) {
    const std::vector<std::string> excluded = labelsMatching(first.labels(), request.excludePatterns, Field::Exclude);
    const auto isExcluded = [&](const std::string& label) {
      return std::find(excluded.begin(), excluded.end(), label) != excluded.end();
    };
    planned.erase(std::remove_if(planned.begin(), planned.end(), isExcluded), planned.end());
  }
  return planned;
}

std::string keyPoseName(const KeyPose& pose)
{
  return pose.take == 0 ? std::to_string(pose.frame) : std::to_string(pose.take + 1) + ":" + std::to_string(pose.frame);
}

// Rows of `frames` of the key poses; each must be a frame every planned marker has, once.
std::vector<Eigen::Index> keyPoseRows(const std::vector<Take>& takes, const LayoutFrames& frames,
                                      const std::vector<KeyPose>& poses)
{
  std::vector<Eigen::Index> rows;
  for (const KeyPose& pose : poses) {
    if (pose.take >= takes.size())
      throw LayoutRequestError(Field::KeyPoses, "there is no take " + std::to_string(pose.take + 1));
    const Take& take = takes[pose.take];
    const long long index = pose.frame - take.firstFrame();
    const Eigen::Index row =
        index >= 0 && index < take.frameCount() ? frames.rowOf(pose.take, static_cast<Eigen::Index>(index)) : -1;
    if (row < 0)
      throw LayoutRequestError(Field::KeyPoses,
                               "frame " + keyPoseName(pose) + " is outside the take or lacks a planned marker");
    if (std::find(rows.begin(), rows.end(), row) != rows.end())
      throw LayoutRequestError(Field::KeyPoses, "frame " + keyPoseName(pose) + " is given twice");
    rows.push_back(row);
  }
  return rows;
}

// A whole decimal number (optionally signed), or nullopt.
std::optional<long long> wholeNumber(std::string_view text)
{
  const std::string copy(text);
  std::size_t used = 0;
  try {
    const long long value = std::stoll(copy, &used);
    if (used == copy.size() && !copy.empty() && copy.find_first_of(" \t+") == std::string::npos)
      return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

} // namespace

std::vector<KeyPose> parseKeyPoses(std::string_view text)
{
  const std::string_view trimmed = trim(text);
  if (trimmed.empty() || trimmed == "auto")
    return {};
  std::vector<KeyPose> poses;
  for (const std::string_view rawField : split(trimmed, ',')) {
    const std::string_view field = trim(rawField);
    KeyPose pose;
    std::string_view frameText = field;
    if (const std::size_t colon = field.find(':'); colon != std::string_view::npos) {
      const std::string_view takeText = field.substr(0, colon);
      const auto take = wholeNumber(takeText);
      if (!take || *take < 1 || takeText.find_first_not_of("0123456789") != std::string_view::npos)
        throw LayoutRequestError(Field::KeyPoses, "bad take number in '" + std::string(field) + "'");
      pose.take = static_cast<std::size_t>(*take - 1);
      frameText = field.substr(colon + 1);
    }
    const auto frame = wholeNumber(frameText);
    if (!frame)
      throw LayoutRequestError(Field::KeyPoses, "expected auto or frame numbers, not '" + std::string(field) + "'");
    pose.frame = *frame;
    poses.push_back(pose);
  }
  return poses;
}

std::vector<std::string> labelsMatching(const std::vector<std::string>& labels,
                                        const std::vector<std::string>& patterns, Field field)
{
  std::set<std::string> found;
  for (const std::string& pattern : patterns) {
    bool any = false;
    for (const std::string& label : labels)
      if (globMatch(pattern, label)) {
        found.insert(label);
        any = true;
      }
    if (!any)
      throw LayoutRequestError(field, "no marker matches '" + pattern + "'");
  }
  std::vector<std::string> ordered;
  for (const std::string& label : labels)
    if (found.count(label) != 0)
      ordered.push_back(label);
  return ordered;
}

LayoutResult planLayout(const std::vector<Take>& takes, const LayoutRequest& request, const RunControl& control)
{
  if (takes.empty())
    throw InvalidArgument("layout planning needs at least one take");
  LayoutResult result;
  result.stabilizeLabels = request.stabilizeLabels;
  LayoutFramesOptions frameOptions;
  frameOptions.stabilizeLabels = request.stabilizeLabels;
  frameOptions.markers = plannedLabels(takes.front(), request);
  result.frames = collectLayoutFrames(takes, frameOptions);

  LayoutPlanOptions options = request.plan;
  options.keyFrames = keyPoseRows(takes, result.frames, request.keyPoses);
  if (request.pairsFile.empty()) {
    result.detection = detectLayoutPairs(result.frames, options.keyFrames);
    result.symmetry = result.detection->symmetry;
  } else {
    result.symmetry = readMarkerPairs(request.pairsFile, result.frames.labels);
  }
  result.plan = planMarkerLayout(result.frames, result.symmetry, options, control);
  return result;
}

std::vector<std::string> LayoutResult::labelsOf(const std::vector<Eigen::Index>& markers) const
{
  std::vector<std::string> labels;
  for (const Eigen::Index m : markers)
    labels.push_back(frames.labels[static_cast<std::size_t>(m)]);
  return labels;
}

const ScoredLayout* LayoutResult::layout(Eigen::Index markerCount) const
{
  const LayoutSize* entry = plan.size(markerCount);
  return entry ? entry->layout(plan.method) : nullptr;
}

std::vector<std::string> LayoutResult::captureLabels(const ScoredLayout* chosen) const
{
  std::vector<std::string> labels = chosen ? labelsOf(chosen->markers) : frames.labels;
  labels.insert(labels.end(), stabilizeLabels.begin(), stabilizeLabels.end());
  return labels;
}

} // namespace mocap
