#include "mocap/cleaning/head_marker_labels.h"

#include "mocap/model/marker_points.h"

#include <cctype>
#include <string>
#include <string_view>

namespace mocap {

std::vector<Eigen::Index> labelledHeadMarkers(const Take& take)
{
  const auto startsWith = [](const std::string& label, std::string_view prefix) {
    if (label.size() < prefix.size())
      return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(label[i])) != prefix[i])
        return false;
    return true;
  };
  std::vector<Eigen::Index> markers;
  for (const Eigen::Index m : markerPoints(take))  // a model output is never a head marker
    if (startsWith(take.label(m), "root") || startsWith(take.label(m), "head"))
      markers.push_back(m);
  if (markers.size() < 3)
    markers.clear();
  return markers;
}

} // namespace mocap
