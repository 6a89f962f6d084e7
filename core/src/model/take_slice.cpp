#include "mocap/model/take_slice.h"

#include "mocap/base/error.h"

namespace mocap {

Take sliceFrames(const Take& take, Eigen::Index begin, Eigen::Index end)
{
  if (begin < 0 || begin >= end || end > take.frameCount())
    throw InvalidArgument("sliceFrames: frames [" + std::to_string(begin) + ", " + std::to_string(end) +
                          ") are not inside a take of " + std::to_string(take.frameCount()) + " frames");
  const Eigen::Index count = end - begin;
  Take slice(take.labels(), count, take.frameRate());
  slice.setUnits(take.units());
  slice.setFirstFrame(take.firstFrame() + begin);
  slice.valid() = take.valid().middleRows(begin, count);
  slice.residuals() = take.residuals().middleRows(begin, count);
  slice.cameraMasks() = take.cameraMasks().middleRows(begin, count);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    slice.setPointType(m, take.pointType(m));
    slice.trajectory(m) = take.trajectory(m).middleRows(begin, count);
    for (Eigen::Index f = 0; f < count; ++f)
      slice.setState(f, m, take.state(begin + f, m));
  }
  return slice;
}

} // namespace mocap
