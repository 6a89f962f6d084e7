// Greedy forward selection with exchange passes (selectGreedy, marker_selection.h).

#include "mocap/layout/marker_selection.h"

#include "mocap/base/error.h"
#include "mocap/base/parallel_for.h"

#include "selection_units.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>

namespace mocap {

using layout_internal::checkSymmetry;
using layout_internal::markersOfUnits;
using layout_internal::sizeReachable;

namespace {

// The objective of a unit selection, memoised: greedy runs for neighbouring sizes walk the same
// forward steps, so they share most evaluations. Thread-safe; values do not depend on who computes them.
class ObjectiveCache
{
public:
  ObjectiveCache(const SubsetErrors& errors, const MarkerSymmetry& symmetry)
      : m_errors(errors), m_symmetry(symmetry)
  {}

  double operator()(const std::vector<bool>& selected)
  {
    std::string key(selected.size(), '0');
    for (std::size_t u = 0; u < selected.size(); ++u)
      key[u] = selected[u] ? '1' : '0';
    {
      const std::lock_guard<std::mutex> lock(m_mutex);
      const auto it = m_values.find(key);
      if (it != m_values.end())
        return it->second;
    }
    const double value = m_errors.trainingObjective(markersOfUnits(m_symmetry, selected));
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_values.emplace(std::move(key), value);
    return value;
  }

private:
  const SubsetErrors& m_errors;
  const MarkerSymmetry& m_symmetry;
  std::mutex m_mutex;
  std::unordered_map<std::string, double> m_values;
};

// Exchange: swap a selected unit for an unselected one of the same width while that lowers the
// objective (first improvement, units in order, at most two passes), undoing forward steps taken
// too early or improving a set found another way. `current` is the objective of `selected`.
void exchangeUnits(ObjectiveCache& objective, const MarkerSymmetry& symmetry, std::vector<bool>& selected,
                   double current)
{
  const auto& units = symmetry.units();
  const auto width = [&](std::size_t u) { return units[u].size(); };
  for (int pass = 0; pass < 2; ++pass) {
    bool improved = false;
    for (std::size_t out = 0; out < units.size(); ++out) {
      if (!selected[out])
        continue;
      for (std::size_t in = 0; in < units.size() && selected[out]; ++in) {
        if (selected[in] || width(in) != width(out))
          continue;
        selected[out] = false;
        selected[in] = true;
        const double value = objective(selected);
        if (value < current - 1e-9 * std::abs(current)) {
          current = value;
          improved = true;
        } else {
          selected[in] = false;
          selected[out] = true;
        }
      }
    }
    if (!improved)
      break;
  }
}

std::optional<std::vector<Eigen::Index>> greedyForSize(ObjectiveCache& objective,
                                                       const MarkerSymmetry& symmetry, Eigen::Index size)
{
  if (!sizeReachable(symmetry, size))
    return std::nullopt;
  const auto& units = symmetry.units();
  std::vector<bool> selected(units.size(), false);
  const auto width = [&](std::size_t u) { return static_cast<Eigen::Index>(units[u].size()); };
  // Whether `remaining` markers can still be made of the unselected units.
  const auto fillable = [&](Eigen::Index remaining) {
    Eigen::Index pairs = 0, singles = 0;
    for (std::size_t u = 0; u < units.size(); ++u)
      if (!selected[u])
        (width(u) == 2 ? pairs : singles) += 1;
    for (Eigen::Index a = 0; a <= pairs; ++a)
      if (remaining - 2 * a >= 0 && remaining - 2 * a <= singles)
        return true;
    return false;
  };

  // Forward: add the unit that lowers the objective most, keeping the size reachable.
  Eigen::Index count = 0;
  double current = 0.0;
  while (count < size) {
    std::size_t best = units.size();
    double bestValue = std::numeric_limits<double>::infinity();
    for (std::size_t u = 0; u < units.size(); ++u) {
      if (selected[u] || count + width(u) > size)
        continue;
      selected[u] = true;
      if (fillable(size - count - width(u))) {
        const double value = objective(selected);
        if (value < bestValue) {
          bestValue = value;
          best = u;
        }
      }
      selected[u] = false;
    }
    if (best == units.size())
      return std::nullopt;
    selected[best] = true;
    count += width(best);
    current = bestValue;
  }

  exchangeUnits(objective, symmetry, selected, current);
  return markersOfUnits(symmetry, selected);
}

void checkGreedySize(const SubsetErrors& errors, const MarkerSymmetry& symmetry, Eigen::Index size)
{
  checkSymmetry(symmetry, errors.markerCount());
  if (size < 1 || size > errors.markerCount())
    throw InvalidArgument("greedy selection: the size must be between 1 and " +
                          std::to_string(errors.markerCount()) + ", not " + std::to_string(size));
}

} // namespace

std::optional<std::vector<Eigen::Index>> selectGreedy(const SubsetErrors& errors,
                                                      const MarkerSymmetry& symmetry, Eigen::Index size)
{
  checkGreedySize(errors, symmetry, size);
  ObjectiveCache objective(errors, symmetry);
  return greedyForSize(objective, symmetry, size);
}

std::vector<std::optional<std::vector<Eigen::Index>>> selectGreedy(const SubsetErrors& errors,
                                                                   const MarkerSymmetry& symmetry,
                                                                   const std::vector<Eigen::Index>& sizes,
                                                                   const JobControl& control,
                                                                   const std::map<Eigen::Index, std::vector<Eigen::Index>>& starts)
{
  for (const Eigen::Index size : sizes)
    checkGreedySize(errors, symmetry, size);
  ObjectiveCache objective(errors, symmetry);
  const auto& units = symmetry.units();
  const auto selectionOf = [&](const std::vector<Eigen::Index>& markers) {
    std::vector<bool> selected(units.size(), false);
    for (const Eigen::Index m : markers)
      selected[static_cast<std::size_t>(symmetry.unitOf(m))] = true;
    return selected;
  };
  std::vector<std::optional<std::vector<Eigen::Index>>> result(sizes.size());
  std::atomic<std::size_t> done{0};
  const auto body = [&](std::size_t i) {
    result[i] = greedyForSize(objective, symmetry, sizes[i]);
    // A given start (another method's set of this size) improved by exchange replaces the greedy
    // set when it scores better: the search then never ends worse than that method on the objective.
    const auto start = starts.find(sizes[i]);
    if (start != starts.end() && static_cast<Eigen::Index>(start->second.size()) == sizes[i]) {
      std::vector<bool> selected = selectionOf(start->second);
      exchangeUnits(objective, symmetry, selected, objective(selected));
      if (!result[i] || objective(selected) < objective(selectionOf(*result[i])))
        result[i] = markersOfUnits(symmetry, selected);
    }
    done.fetch_add(1, std::memory_order_relaxed);
  };
  const auto tick = [&] {
    control.report(static_cast<double>(done.load()) / static_cast<double>(sizes.size()));
  };
  if (!parallelFor(sizes.size(), control.threads(), body, control.cancelFlag(), tick))
    return {};

  // Sizes searched independently can come out worse than a smaller size plus one unit. In
  // ascending order, a size takes the set one smaller plus a single unit, or two smaller plus a
  // pair, whenever that scores better.
  std::map<Eigen::Index, std::size_t> indexOfSize;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    indexOfSize.emplace(sizes[i], i);
  for (const auto& [size, index] : indexOfSize) {
    std::optional<std::vector<bool>> best;
    double bestValue = std::numeric_limits<double>::infinity();
    if (result[index]) {
      best = selectionOf(*result[index]);
      bestValue = objective(*best);
    }
    for (const Eigen::Index width : {Eigen::Index{1}, Eigen::Index{2}}) {
      const auto smaller = indexOfSize.find(size - width);
      if (smaller == indexOfSize.end() || !result[smaller->second])
        continue;
      std::vector<bool> selected = selectionOf(*result[smaller->second]);
      for (std::size_t u = 0; u < units.size(); ++u) {
        if (selected[u] || static_cast<Eigen::Index>(units[u].size()) != width)
          continue;
        selected[u] = true;
        const double value = objective(selected);
        if (value < bestValue) {
          bestValue = value;
          best = selected;
        }
        selected[u] = false;
      }
    }
    if (best)
      result[index] = markersOfUnits(symmetry, *best);
  }
  control.reportNow(1.0);
  return result;
}

} // namespace mocap
