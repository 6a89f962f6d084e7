#include "mocap/model/valid_runs.h"

namespace mocap {

std::vector<ValidRun> findValidRuns(const Eigen::Ref<const ValidMask>& valid)
{
  std::vector<ValidRun> runs;
  const Eigen::Index n = valid.size();
  Eigen::Index f = 0;
  while (f < n) {
    while (f < n && !valid(f))
      ++f;
    const Eigen::Index first = f;
    while (f < n && valid(f))
      ++f;
    if (f > first)
      runs.push_back({first, f - first});
  }
  return runs;
}

} // namespace mocap
