#include "mocap/cleaning/head_marker_labels.h"

#include "mocap/model/marker_points.h"

#include <cctype>
#include <cstddef>
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
  // Other systems put the subject before the name (SUBJECTS:LABEL_PREFIXES): "Anna:root-1".
  const auto name = [](const std::string& label) {
    const std::size_t colon = label.rfind(':');
    return colon == std::string::npos ? label : label.substr(colon + 1);
  };
  std::vector<Eigen::Index> markers;
  for (const Eigen::Index m : markerPoints(take)) {  // a model output is never a head marker
    const std::string named = name(take.label(m));
    if (startsWith(named, "root") || startsWith(named, "head"))
      markers.push_back(m);
  }
  if (markers.size() < 3)
    markers.clear();
  return markers;
}

} // namespace mocap
