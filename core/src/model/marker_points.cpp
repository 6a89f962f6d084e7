#include "mocap/model/marker_points.h"

#include "mocap/base/error.h"
#include "mocap/model/marker_edits.h"

namespace mocap {

namespace {

std::vector<Eigen::Index> pointsWhere(const Take& take, bool marker)
{
  std::vector<Eigen::Index> points;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (isMarker(take, m) == marker)
      points.push_back(m);
  return points;
}

/// "angle"/"angles" for a count of a type; "other" has no plural of its own ("2 others" reads as
/// well as "2 angles"), "virtual" is an adjective ("36 virtual points").
std::string kindNoun(PointType type, bool one)
{
  const std::string name(pointTypeName(type));
  const std::string noun = type == PointType::Virtual ? name + " point" : name;
  return one ? noun : noun + "s";
}

} // namespace

bool isMarker(const Take& take, Eigen::Index point)
{
  return take.pointType(point) == PointType::Marker;
}

std::vector<Eigen::Index> markerPoints(const Take& take)
{
  return pointsWhere(take, true);
}

std::vector<std::string> markerLabels(const Take& take)
{
  std::vector<std::string> labels;
  for (const Eigen::Index m : markerPoints(take))
    labels.push_back(take.label(m));
  return labels;
}

std::vector<Eigen::Index> modelOutputPoints(const Take& take)
{
  return pointsWhere(take, false);
}

double markerValidFraction(const Take& take)
{
  Eigen::Index samples = 0;
  Eigen::Index valid = 0;
  for (const Eigen::Index m : markerPoints(take)) {
    samples += take.frameCount();
    valid += take.valid().col(m).count();
  }
  return samples == 0 ? 0.0 : static_cast<double>(valid) / static_cast<double>(samples);
}

std::array<Eigen::Index, kPointTypeCount> pointTypeCounts(const Take& take)
{
  std::array<Eigen::Index, kPointTypeCount> counts{};
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    ++counts[static_cast<std::size_t>(take.pointType(m))];
  return counts;
}

std::string describeModelOutputs(const Take& take)
{
  const std::array<Eigen::Index, kPointTypeCount> counts = pointTypeCounts(take);
  const Eigen::Index outputs = take.markerCount() - counts[static_cast<std::size_t>(PointType::Marker)];
  if (outputs == 0)
    return {};
  std::string kinds;
  for (std::size_t t = 1; t < counts.size(); ++t) {
    if (counts[t] == 0)
      continue;
    kinds += (kinds.empty() ? "" : ", ") + std::to_string(counts[t]) + " " +
             kindNoun(static_cast<PointType>(t), counts[t] == 1);
  }
  return std::to_string(outputs) + (outputs == 1 ? " model output (" : " model outputs (") + kinds + ")";
}

std::optional<Take> withoutModelOutputs(const Take& take, const std::string& file)
{
  if (modelOutputPoints(take).empty())
    return std::nullopt;
  if (markerPoints(take).empty())
    throw InvalidArgument(file + " holds marker positions; this take has only model outputs (" +
                          describeModelOutputs(take) + ")");
  return subsetTake(take, markerLabels(take));
}

} // namespace mocap
