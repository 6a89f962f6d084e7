#include "mocap/model/marker_set.h"

#include "mocap/model/marker_links.h"
#include "mocap/model/marker_points.h"

#include "mocap/base/error.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <cctype>
#include <set>

namespace mocap {

namespace {

constexpr Eigen::Index kLinksPerMarker = 2;

void checkIndexPair(const LabelPair& pair, Eigen::Index size, const char* what)
{
  if (pair.first < 0 || pair.second < 0 || pair.first >= size || pair.second >= size)
    throw InvalidArgument(std::string("marker set: a ") + what + " names a marker out of range");
  if (pair.first == pair.second)
    throw InvalidArgument(std::string("marker set: a ") + what + " joins a marker to itself");
}

bool allDigits(std::string_view text)
{
  return std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// The frame nearest `frame` where `marker` is valid, or −1.
Eigen::Index nearestValidFrame(const Take& take, Eigen::Index marker, Eigen::Index frame)
{
  const auto valid = take.valid();
  for (Eigen::Index d = 0; d < take.frameCount(); ++d) {
    if (frame - d >= 0 && valid(frame - d, marker))
      return frame - d;
    if (frame + d < take.frameCount() && valid(frame + d, marker))
      return frame + d;
  }
  return -1;
}

std::vector<LabelPair> nearestLinks(const PointSet& points)
{
  return nearestNeighbourLinks(points, kLinksPerMarker, std::numeric_limits<double>::infinity());
}

} // namespace

void validateMarkerSet(const MarkerSet& set)
{
  if (set.labels.empty())
    throw InvalidArgument("marker set: no labels");
  std::set<std::string> seen;
  for (const std::string& label : set.labels) {
    if (label.empty())
      throw InvalidArgument("marker set: an empty label");
    if (!seen.insert(label).second)
      throw InvalidArgument("marker set: label '" + label + "' appears twice");
  }
  if (set.neutral.rows() != set.size())
    throw InvalidArgument("marker set: one neutral position per label expected");
  if (!set.neutral.allFinite())
    throw InvalidArgument("marker set: a neutral position is not finite");
  for (const LabelPair& pair : set.pairs)
    checkIndexPair(pair, set.size(), "pair");
  for (const LabelPair& link : set.links)
    checkIndexPair(link, set.size(), "link");
  (void)set.symmetry();  // a marker in two pairs
  if (!set.meshVertices.empty() && static_cast<Eigen::Index>(set.meshVertices.size()) != set.size())
    throw InvalidArgument("marker set: the mesh binding needs one vertex per label");
  for (const Eigen::Index v : set.meshVertices)
    if (v < -1)
      throw InvalidArgument("marker set: a mesh vertex index below -1");
}

bool isUnlabelledLabel(std::string_view label)
{
  label = trim(label);
  if (!label.empty() && label.front() == '*')
    return label.size() > 1 && allDigits(label.substr(1));
  const std::string lower = toLower(label);
  for (const std::string_view prefix : {std::string_view("unlabeled"), std::string_view("unlabelled")}) {
    if (lower.compare(0, prefix.size(), prefix) != 0)
      continue;
    std::string_view rest = std::string_view(lower).substr(prefix.size());
    if (!rest.empty() && (rest.front() == ' ' || rest.front() == '_' || rest.front() == '-'))
      rest.remove_prefix(1);
    return allDigits(rest);
  }
  return false;
}

Eigen::Index mostCompleteFrame(const Take& take, const std::vector<Eigen::Index>& markers)
{
  const auto valid = take.valid();
  Eigen::Index best = -1;
  Eigen::Index bestCount = 0;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    Eigen::Index count = 0;
    for (const Eigen::Index m : markers)
      count += valid(f, m) ? 1 : 0;
    if (count > bestCount) {
      best = f;
      bestCount = count;
    }
  }
  return best;
}

Eigen::Index mostCompleteFrame(const Take& take)
{
  return mostCompleteFrame(take, markerPoints(take));
}

MarkerSet markerSetFromTake(const Take& take, Eigen::Index frame)
{
  std::vector<Eigen::Index> markers;
  const auto valid = take.valid();
  for (const Eigen::Index m : markerPoints(take))
    if (!isUnlabelledLabel(take.label(m)) && valid.col(m).any())
      markers.push_back(m);
  if (markers.empty())
    throw InvalidArgument("marker set: the take has no labelled marker with a valid sample");
  if (frame < -1 || frame >= take.frameCount())
    throw InvalidArgument("marker set: the neutral frame is out of range");
  if (frame < 0)
    frame = mostCompleteFrame(take, markers);
  MarkerSet set;
  set.units = take.units();
  set.neutral.resize(static_cast<Eigen::Index>(markers.size()), 3);
  for (std::size_t i = 0; i < markers.size(); ++i) {
    set.labels.push_back(take.label(markers[i]));
    const Eigen::Index source = nearestValidFrame(take, markers[i], frame);
    set.neutral.row(static_cast<Eigen::Index>(i)) = take.position(source, markers[i]).transpose();
  }
  if (!set.neutral.allFinite())
    throw InvalidArgument("marker set: a valid sample of the take is not finite");
  const PairDetection detection = detectMarkerPairs(set.neutral, set.labels);
  for (const DetectedPair& pair : detection.pairs)
    set.pairs.emplace_back(pair.first, pair.second);
  set.links = nearestLinks(set.neutral);
  return set;
}

} // namespace mocap
