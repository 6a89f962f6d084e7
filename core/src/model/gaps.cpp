#include "mocap/model/gaps.h"

#include "mocap/model/marker_points.h"

namespace mocap {

std::vector<Gap> findGaps(const Eigen::Ref<const ValidMask>& valid, Eigen::Index marker)
{
  std::vector<Gap> gaps;
  const Eigen::Index frames = valid.size();
  Eigen::Index f = 0;
  while (f < frames) {
    if (valid(f)) {
      ++f;
      continue;
    }
    const Eigen::Index start = f;
    while (f < frames && !valid(f))
      ++f;
    gaps.push_back({marker, start, f - start, start == 0 || f == frames});
  }
  return gaps;
}

std::vector<Gap> findGaps(const Take& take)
{
  return findGaps(take, markerPoints(take));
}

std::vector<Gap> findGaps(const Take& take, const std::vector<Eigen::Index>& points)
{
  std::vector<Gap> gaps;
  for (const Eigen::Index m : points) {
    const auto markerGaps = findGaps(take.valid().col(m), m);
    gaps.insert(gaps.end(), markerGaps.begin(), markerGaps.end());
  }
  return gaps;
}

} // namespace mocap
