#include "mocap/tracking/fragment_joining.h"

#include "mocap/base/error.h"
#include "mocap/model/valid_runs.h"

#include <algorithm>

namespace mocap {

std::vector<Fragment> fragmentsOfMarkers(const Take& take, const std::vector<Eigen::Index>& markers)
{
  std::vector<Fragment> fragments;
  for (const Eigen::Index m : markers) {
    if (m < 0 || m >= take.markerCount())
      throw InvalidArgument("fragments: marker index out of range");
    const auto trajectory = take.trajectory(m);
    for (const ValidRun& run : findValidRuns(take.valid().col(m))) {
      Fragment fragment;
      fragment.first = run.first;
      for (Eigen::Index f = run.first; f < run.first + run.length; ++f)
        fragment.positions.push_back(trajectory.row(f).transpose());
      fragments.push_back(std::move(fragment));
    }
  }
  return fragments;
}

Eigen::Index appendFragments(Take& take, const std::vector<Fragment>& fragments, const std::vector<Eigen::Index>& which)
{
  std::vector<Eigen::Index> order = which;
  for (const Eigen::Index k : order) {
    if (k < 0 || k >= static_cast<Eigen::Index>(fragments.size()))
      throw InvalidArgument("fragments: index out of range");
    const Fragment& f = fragments[static_cast<std::size_t>(k)];
    if (f.length() == 0 || f.first < 0 || f.last() >= take.frameCount())
      throw InvalidArgument("fragments: a fragment lies outside the take");
  }
  const auto first = [&](Eigen::Index k) { return fragments[static_cast<std::size_t>(k)].first; };
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return first(a) < first(b); });
  std::vector<Eigen::Index> columns;  // marker index of each added column
  std::vector<Eigen::Index> columnEnd;  // its last used frame
  for (const Eigen::Index k : order) {
    const Fragment& fragment = fragments[static_cast<std::size_t>(k)];
    std::size_t c = 0;
    while (c < columns.size() && columnEnd[c] + 1 >= fragment.first)  // keep a frame between: one run, one fragment
      ++c;
    if (c == columns.size()) {
      columns.push_back(take.addMarker("Unlabeled" + std::to_string(columns.size() + 1)));
      columnEnd.push_back(-1);
    }
    const Eigen::Index marker = columns[c];
    auto trajectory = take.trajectory(marker);
    auto valid = take.valid();
    auto residuals = take.residuals();
    for (Eigen::Index f = fragment.first; f <= fragment.last(); ++f) {
      trajectory.row(f) = fragment.at(f).transpose();
      valid(f, marker) = true;
      residuals(f, marker) = 0.0;
    }
    columnEnd[c] = fragment.last();
  }
  return static_cast<Eigen::Index>(columns.size());
}

void copyMarker(const Take& source, Eigen::Index from, Take& target, Eigen::Index to)
{
  if (source.frameCount() != target.frameCount() || from < 0 || from >= source.markerCount() || to < 0 ||
      to >= target.markerCount())
    throw InvalidArgument("copy marker: frame counts differ or a marker is out of range");
  target.setPointType(to, source.pointType(from));
  target.trajectory(to) = source.trajectory(from);
  target.valid().col(to) = source.valid().col(from);
  target.residuals().col(to) = source.residuals().col(from);
  target.cameraMasks().col(to) = source.cameraMasks().col(from);
  for (Eigen::Index f = 0; f < source.frameCount(); ++f)
    target.setState(f, to, source.state(f, from));
}

} // namespace mocap
