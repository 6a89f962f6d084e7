#include "mocap/model/marker_links.h"

#include "mocap/base/error.h"
#include "mocap/model/marker_points.h"

#include <algorithm>
#include <cmath>

namespace mocap {

std::vector<MarkerLink> nearestNeighbourLinks(const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3>>& points,
                                              int neighbours, double maxRatio)
{
  if (neighbours < 1)
    throw InvalidArgument("marker links need at least one neighbour per marker");
  if (!(maxRatio > 0.0))
    throw InvalidArgument("the longest marker link must be a ratio > 0 of the median");
  const Eigen::Index n = points.rows();
  std::vector<std::pair<double, MarkerLink>> links;
  std::vector<std::pair<double, Eigen::Index>> distances;
  for (Eigen::Index a = 0; a < n; ++a) {
    distances.clear();
    for (Eigen::Index b = 0; b < n; ++b)
      if (b != a)
        distances.emplace_back((points.row(a) - points.row(b)).norm(), b);
    const auto count = std::min(distances.size(), static_cast<std::size_t>(neighbours));
    std::partial_sort(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(count), distances.end());
    for (std::size_t i = 0; i < count; ++i)
      links.push_back({distances[i].first, {std::min(a, distances[i].second), std::max(a, distances[i].second)}});
  }
  std::sort(links.begin(), links.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
  links.erase(std::unique(links.begin(), links.end(), [](const auto& x, const auto& y) { return x.second == y.second; }),
              links.end());
  if (links.empty())
    return {};
  std::vector<double> lengths;
  for (const auto& link : links)
    lengths.push_back(link.first);
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  const double limit = maxRatio * lengths[lengths.size() / 2];
  std::vector<MarkerLink> kept;
  for (const auto& link : links)
    if (link.first <= limit)
      kept.push_back(link.second);
  return kept;
}

std::vector<MarkerLink> nearestNeighbourLinks(const Take& take, Eigen::Index frame, int neighbours, double maxRatio)
{
  if (frame < 0 || frame >= take.frameCount())
    throw InvalidArgument("frame " + std::to_string(frame) + " is outside the take (" +
                          std::to_string(take.frameCount()) + " frames)");
  std::vector<Eigen::Index> valid;
  for (const Eigen::Index m : markerPoints(take))
    if (take.isValid(frame, m) && take.position(frame, m).allFinite())
      valid.push_back(m);
  Eigen::Matrix<double, Eigen::Dynamic, 3> points(static_cast<Eigen::Index>(valid.size()), 3);
  for (std::size_t i = 0; i < valid.size(); ++i)
    points.row(static_cast<Eigen::Index>(i)) = take.position(frame, valid[i]).transpose();
  std::vector<MarkerLink> links = nearestNeighbourLinks(points, neighbours, maxRatio);
  for (MarkerLink& link : links)
    link = {valid[static_cast<std::size_t>(link.first)], valid[static_cast<std::size_t>(link.second)]};
  return links;
}

} // namespace mocap
