#pragma once

#include "mocap/model/take.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Unlabelled 3D points per frame, as a passive optical system delivers them before tracking
/// (paper §2): frame f holds points [frameStart[f], frameStart[f + 1]).
struct PointCloud
{
  double frameRate = 100.0;
  std::vector<Eigen::Index> frameStart{0};  ///< #frames + 1 offsets into `points`
  std::vector<Eigen::Vector3d> points;

  [[nodiscard]] Eigen::Index frameCount() const { return static_cast<Eigen::Index>(frameStart.size()) - 1; }
  [[nodiscard]] Eigen::Index pointCount(Eigen::Index frame) const
  {
    return frameStart[static_cast<std::size_t>(frame + 1)] - frameStart[static_cast<std::size_t>(frame)];
  }
  [[nodiscard]] const Eigen::Vector3d& point(Eigen::Index frame, Eigen::Index i) const
  {
    return points[static_cast<std::size_t>(frameStart[static_cast<std::size_t>(frame)] + i)];
  }
};

/// The valid samples of `markers` (indices into the take) as unlabelled points, frame by frame in
/// marker order, so `mocap track` can re-track a C3D whose markers are unlabelled fragments.
/// Throws InvalidArgument for a marker out of range or a valid sample that is not finite.
/// O(#frames · #markers).
[[nodiscard]] PointCloud pointCloudFromTake(const Take& take, const std::vector<Eigen::Index>& markers);

/// Raw points from CSV text: one point per line as `frame,x,y,z` (frame an integer, any order;
/// frames are counted from the smallest one); an optional header line whose first field is not a
/// number, blank lines and `#` comments are skipped. Throws FormatError(sourceName, "line N: ...")
/// for a line without four fields, a field that is not a finite number or a frame range over 10⁸.
/// O(text size + #frames).
[[nodiscard]] PointCloud parsePointCloudCsv(std::string_view text, const std::string& sourceName,
                                            double frameRate = 100.0);

/// parsePointCloudCsv on a file's content; throws IoError when it cannot be read.
[[nodiscard]] PointCloud readPointCloudCsv(const std::filesystem::path& path, double frameRate = 100.0);

} // namespace mocap
