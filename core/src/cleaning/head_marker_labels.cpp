#include "mocap/cleaning/head_marker_labels.h"

#include "mocap/model/marker_points.h"
#include "mocap/model/subject_prefix.h"

#include <cctype>
#include <cstddef>
#include <string_view>

namespace mocap {

std::vector<Eigen::Index> labelledHeadMarkers(const Take& take)
{
  const auto startsWith = [](std::string_view label, std::string_view prefix) {
    if (label.size() < prefix.size())
      return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(label[i])) != prefix[i])
        return false;
    return true;
  };
  std::vector<Eigen::Index> markers;
  for (const Eigen::Index m : markerPoints(take)) {  // a model output is never a head marker
    const std::string_view named = withoutSubjectPrefix(take.label(m));  // "Anna:root-1"
    if (startsWith(named, "root") || startsWith(named, "head"))
      markers.push_back(m);
  }
  if (markers.size() < 3)
    markers.clear();
  return markers;
}

} // namespace mocap
