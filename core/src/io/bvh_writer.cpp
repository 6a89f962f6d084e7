#include "mocap/io/bvh_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"
#include "mocap/base/file_io.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/nearest_usable_frame.h"

#include <charconv>
#include <cmath>

namespace mocap {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;


// Three space-separated numbers. O(1).
void appendVector(std::string& out, const Eigen::Vector3d& v)
{
  for (Eigen::Index i = 0; i < 3; ++i) {
    if (i > 0)
      out += ' ';
    appendNumber(out, v[i]);
  }
}

// BVH readers split on whitespace and braces, so those cannot appear in a joint name; the root's
// name is reserved so a marker called "Head" does not collide with it. O(total label length).
std::vector<std::string> jointNames(const std::vector<std::string>& labels)
{
  std::vector<std::string> names;
  names.reserve(labels.size() + 1);
  names.emplace_back("Head");
  for (std::string label : labels) {
    for (char& c : label) {
      const auto u = static_cast<unsigned char>(c);
      if (u <= ' ' || u == 0x7f || c == '{' || c == '}')
        c = '_';
    }
    names.push_back(std::move(label));
  }
  makeLabelsUnique(names);
  names.erase(names.begin());
  return names;
}

} // namespace

Eigen::Vector3d zxyEulerDegrees(const Eigen::Matrix3d& r)
{
  // Rz(z)·Rx(x)·Ry(y) has row 2 = (−cos x sin y, sin x, cos x cos y). atan2 keeps x accurate near
  // ±90°, where y from row 2 is ill-conditioned (and undefined in gimbal lock, so 0 there); z then
  // comes from R·Ry(−y), whose column 0 is (cos z, sin z, 0) for any x, so errors in y are absorbed.
  const double cosX = std::hypot(r(2, 0), r(2, 2));
  const double x = std::atan2(r(2, 1), cosX);
  const double y = cosX > 1e-12 ? std::atan2(-r(2, 0), r(2, 2)) : 0.0;
  const double cosY = std::cos(y);
  const double sinY = std::sin(y);
  const double z = std::atan2(cosY * r(1, 0) + sinY * r(1, 2), cosY * r(0, 0) + sinY * r(0, 2));
  return Eigen::Vector3d(z, x, y) * kDegreesPerRadian;
}

Eigen::Matrix3d zxyRotation(const Eigen::Vector3d& zxyDegrees)
{
  const Eigen::Vector3d a = zxyDegrees / kDegreesPerRadian;
  return (Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

std::string formatBvh(const Take& take, const BvhOptions& options)
{
  if (const std::optional<Take> markers = withoutModelOutputs(take, "a BVH file"))
    return formatBvh(*markers, options);
  const Eigen::Index frames = take.frameCount();
  const Eigen::Index markers = take.markerCount();
  const bool moving = !options.headPoses.empty();
  if (moving && static_cast<Eigen::Index>(options.headPoses.size()) != frames)
    throw InvalidArgument("BVH export: " + std::to_string(options.headPoses.size()) + " head poses for " +
                          std::to_string(frames) + " frames");

  std::vector<Eigen::Isometry3d> toHead;
  if (moving) {
    toHead.reserve(options.headPoses.size());
    for (const Eigen::Isometry3d& pose : options.headPoses)
      toHead.push_back(pose.inverse(Eigen::Isometry));
  }

  // Head-space positions, #frames × 3·#markers, gaps filled from the nearest usable sample.
  Eigen::MatrixXd local = Eigen::MatrixXd::Zero(frames, 3 * markers);
  Eigen::MatrixXd offsets = Eigen::MatrixXd::Zero(markers, 3);
  for (Eigen::Index m = 0; m < markers; ++m) {
    const std::vector<Eigen::Index> nearest = nearestUsableFrames(take, m);
    if (frames == 0 || nearest.front() < 0)
      continue;
    for (Eigen::Index f = 0; f < frames; ++f) {
      if (nearest[static_cast<std::size_t>(f)] != f)
        continue;
      const Eigen::Vector3d p = take.position(f, m);
      local.block<1, 3>(f, 3 * m) = (moving ? toHead[static_cast<std::size_t>(f)] * p : p).transpose();
    }
    for (Eigen::Index f = 0; f < frames; ++f) {
      const Eigen::Index source = nearest[static_cast<std::size_t>(f)];
      if (source != f)
        local.block<1, 3>(f, 3 * m) = local.block<1, 3>(source, 3 * m);
    }
    // Before its first usable frame a marker's nearest usable frame is that first one.
    offsets.row(m) = local.block<1, 3>(nearest.front(), 3 * m);
  }

  std::string out;
  out.reserve(static_cast<std::size_t>(256 + 160 * markers + frames * (64 + 30 * markers)));
  out += "HIERARCHY\nROOT Head\n{\n  OFFSET 0 0 0\n"
         "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  const std::vector<std::string> names = jointNames(take.labels());
  for (Eigen::Index m = 0; m < markers; ++m) {
    out += "  JOINT " + names[static_cast<std::size_t>(m)] + "\n  {\n    OFFSET ";
    appendVector(out, offsets.row(m).transpose());
    out += "\n    CHANNELS 3 Xposition Yposition Zposition\n"
           "    End Site\n    {\n      OFFSET 0 0 0\n    }\n  }\n";
  }
  if (markers == 0)
    out += "  End Site\n  {\n    OFFSET 0 0 0\n  }\n";
  out += "}\nMOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: ";
  appendNumber(out, 1.0 / take.frameRate());
  out += '\n';

  for (Eigen::Index f = 0; f < frames; ++f) {
    if (moving) {
      const Eigen::Isometry3d& pose = options.headPoses[static_cast<std::size_t>(f)];
      appendVector(out, pose.translation());
      out += ' ';
      appendVector(out, zxyEulerDegrees(pose.linear()));
    } else {
      out += "0 0 0 0 0 0";
    }
    for (Eigen::Index m = 0; m < markers; ++m) {
      out += ' ';
      appendVector(out, local.block<1, 3>(f, 3 * m).transpose());
    }
    out += '\n';
  }
  return out;
}

void writeBvh(const Take& take, const std::filesystem::path& path, const BvhOptions& options)
{
  writeFileAtomically(path, formatBvh(take, options));
}

} // namespace mocap
