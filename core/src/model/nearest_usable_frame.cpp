#include "mocap/model/nearest_usable_frame.h"

namespace mocap {

bool usableSample(const Take& take, Eigen::Index frame, Eigen::Index marker)
{
  return take.isValid(frame, marker) && take.position(frame, marker).allFinite();
}

std::vector<Eigen::Index> nearestUsableFrames(const Take& take, Eigen::Index marker)
{
  const Eigen::Index frames = take.frameCount();
  std::vector<Eigen::Index> nearest(static_cast<std::size_t>(frames), -1);
  Eigen::Index last = -1;
  for (Eigen::Index f = 0; f < frames; ++f) {
    if (usableSample(take, f, marker))
      last = f;
    nearest[static_cast<std::size_t>(f)] = last;
  }
  Eigen::Index next = -1;
  for (Eigen::Index f = frames - 1; f >= 0; --f) {
    if (usableSample(take, f, marker))
      next = f;
    Eigen::Index& best = nearest[static_cast<std::size_t>(f)];
    if (next >= 0 && (best < 0 || next - f < f - best))
      best = next;
  }
  return nearest;
}

} // namespace mocap
