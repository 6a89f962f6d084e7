#include "mocap/io/vicon_virtual_points.h"

#include "mocap/model/marker_points.h"
#include "mocap/model/subject_prefix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <unordered_map>

namespace mocap {

namespace {

/// Plug-in Gait's segments (lower and upper body): pelvis, femurs, tibias, feet, toes, head,
/// thorax, clavicles, humeri, radii, hands.
constexpr std::array<std::string_view, 19> kSegments{"PEL", "LFE", "RFE", "LTI", "RTI", "LFO", "RFO",
                                                      "LTO", "RTO", "HED", "TRX", "LCL", "RCL", "LHU",
                                                      "RHU", "LRA", "RRA", "LHN", "RHN"};
/// A segment's points: its origin, then the ends of its anterior, lateral and proximal axes.
constexpr std::string_view kAxisPoints = "OALP";
/// The largest |cos| between two axes taken as a right angle: 1.1° off (Nexus writes them at right
/// angles to float precision; an integer file's scale moves a 50 mm axis by a few tenths of a degree).
constexpr double kRightAngleCos = 0.02;

using SegmentPoints = std::array<Eigen::Index, 4>;

/// Whether the three axes from the origin point are at right angles in every frame where the four
/// points are valid, and there is such a frame. O(#frames).
bool areAxes(const Take& take, const SegmentPoints& points)
{
  const auto valid = take.valid();
  Eigen::Index frames = 0;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    if (!std::all_of(points.begin(), points.end(), [&](Eigen::Index p) { return valid(f, p); }))
      continue;
    const Eigen::Vector3d origin = take.position(f, points[0]);
    std::array<Eigen::Vector3d, 3> axes;
    for (std::size_t a = 0; a < axes.size(); ++a)
      axes[a] = take.position(f, points[a + 1]) - origin;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const Eigen::Vector3d& u = axes[a];
      const Eigen::Vector3d& v = axes[(a + 1) % axes.size()];
      const double lengths = u.norm() * v.norm();
      if (!(lengths > 0.0) || std::abs(u.dot(v)) > kRightAngleCos * lengths)
        return false;  // a zero axis, a NaN or a slant: not a segment's axes
    }
    ++frames;
  }
  return frames > 0;
}

bool isSegment(std::string_view code)
{
  return std::find(kSegments.begin(), kSegments.end(), code) != kSegments.end();
}

bool isCentreOfMass(std::string_view name)
{
  return name == "CentreOfMass" || name == "CentreOfMassFloor";
}

} // namespace

std::vector<std::string> typeViconVirtualPoints(Take& take)
{
  std::unordered_map<std::string_view, Eigen::Index> markers;  // label → point, over the take's labels
  for (const Eigen::Index m : markerPoints(take))
    markers.emplace(take.label(m), m);
  std::vector<bool> typed(static_cast<std::size_t>(take.markerCount()), false);
  for (const Eigen::Index m : markerPoints(take)) {
    const std::string& label = take.label(m);
    const std::string_view name = withoutSubjectPrefix(label);
    if (name.size() != 4 || name[3] != kAxisPoints[0] || !isSegment(name.substr(0, 3)))
      continue;  // each segment once, from its origin
    const std::string segment = std::string(subjectPrefix(label)) + std::string(name.substr(0, 3));
    SegmentPoints points{};
    bool complete = true;
    for (std::size_t a = 0; a < points.size() && complete; ++a) {
      const auto found = markers.find(segment + kAxisPoints[a]);
      complete = found != markers.end();
      if (complete)
        points[a] = found->second;
    }
    if (complete && areAxes(take, points))
      for (const Eigen::Index p : points)
        typed[static_cast<std::size_t>(p)] = true;
  }
  const bool modelOutputFile = std::find(typed.begin(), typed.end(), true) != typed.end() ||
                               !modelOutputPoints(take).empty();
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const bool centreOfMass = modelOutputFile && isMarker(take, m) && isCentreOfMass(withoutSubjectPrefix(take.label(m)));
    if (!typed[static_cast<std::size_t>(m)] && !centreOfMass)
      continue;
    take.setPointType(m, PointType::Virtual);
    labels.push_back(take.label(m));
  }
  return labels;
}

} // namespace mocap
