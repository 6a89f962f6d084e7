#include "mocap/layout/marker_selection.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/base/parallel_for.h"
#include "mocap/base/random.h"
#include "mocap/math/pca.h"
#include "mocap/layout/subset_error.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>

namespace mocap {

namespace {

using Clock = std::chrono::steady_clock;

int threadCount(const RunControl& control)
{
  if (control.threads > 0)
    return control.threads;
  return hardwareThreads();
}

// Rate-limited progress on the calling thread.
class ProgressReporter
{
public:
  explicit ProgressReporter(const RunControl& control) : m_control(control) {}
  void report(double fraction, bool force = false)
  {
    if (!m_control.progress)
      return;
    const auto now = Clock::now();
    if (!force && now - m_last < std::chrono::milliseconds(50))
      return;
    m_last = now;
    m_control.progress(std::clamp(fraction, 0.0, 1.0));
  }

private:
  const RunControl& m_control;
  Clock::time_point m_last = Clock::now() - std::chrono::seconds(1);
};

void checkSymmetry(const MarkerSymmetry& symmetry, Eigen::Index markers)
{
  if (symmetry.markerCount() != markers)
    throw InvalidArgument("marker selection: the symmetry covers " + std::to_string(symmetry.markerCount()) +
                          " markers, the frames " + std::to_string(markers));
}

void checkTraining(const Eigen::Ref<const Eigen::MatrixXd>& training)
{
  if (training.cols() < 6 || training.cols() % 3 != 0)
    throw InvalidArgument("marker selection needs at least two markers (3 coordinates each), got " +
                          std::to_string(training.cols()) + " coordinates");
  if (!training.allFinite())
    throw InvalidArgument("marker selection: a training value is not finite");
}

std::vector<Eigen::Index> markersOfUnits(const MarkerSymmetry& symmetry, const std::vector<bool>& selected)
{
  std::vector<Eigen::Index> markers;
  for (std::size_t u = 0; u < selected.size(); ++u)
    if (selected[u])
      for (const Eigen::Index m : symmetry.units()[u])
        markers.push_back(m);
  std::sort(markers.begin(), markers.end());
  return markers;
}

bool sizeReachable(const MarkerSymmetry& symmetry, Eigen::Index size)
{
  Eigen::Index pairs = 0, singles = 0;
  for (const auto& unit : symmetry.units())
    (unit.size() == 2 ? pairs : singles) += 1;
  for (Eigen::Index a = 0; a <= pairs; ++a)
    if (size - 2 * a >= 0 && size - 2 * a <= singles)
      return true;
  return false;
}

} // namespace

namespace {

constexpr EnumTable<SelectionMethod, 2> kSelectionMethods{{{
    {SelectionMethod::Pfa, "pfa"},
    {SelectionMethod::Greedy, "greedy"},
}}};

} // namespace

std::string_view selectionMethodName(SelectionMethod method)
{
  return kSelectionMethods.name(method, "greedy");
}

std::string selectionMethodNames()
{
  return kSelectionMethods.names();
}

std::optional<SelectionMethod> parseSelectionMethod(std::string_view name)
{
  return kSelectionMethods.parse(name);
}

PfaSweep sweepPfa(const Eigen::Ref<const Eigen::MatrixXd>& training, const MarkerSymmetry& symmetry,
                  const PfaOptions& options, const RunControl& control)
{
  checkTraining(training);
  const Eigen::Index features = training.cols();
  const Eigen::Index markers = features / 3;
  checkSymmetry(symmetry, markers);
  if (training.rows() < features + 1)
    throw InvalidArgument("PFA: " + std::to_string(training.rows()) + " frames for " +
                          std::to_string(features) + " features; need at least " +
                          std::to_string(features + 1));
  if (options.restarts < 1)
    throw InvalidArgument("PFA: restarts must be at least 1, not " + std::to_string(options.restarts));
  const bool automatic = options.minK == 0 && options.maxK == 0;
  const Eigen::Index lowK = options.minK == 0 ? 1 : options.minK;
  const Eigen::Index highK = automatic ? markers : (options.maxK == 0 ? features : options.maxK);
  if (lowK < 1 || highK > features || lowK > highK)
    throw InvalidArgument("PFA: k must satisfy 1 ≤ min ≤ max ≤ " + std::to_string(features) +
                          " (the number of features, 3 per marker), got " + std::to_string(lowK) + ":" +
                          std::to_string(highK));

  const PrincipalComponents pca = computePca(training, options.varianceFraction);
  // Lu et al. 2007 cluster |Vᵢ|: an eigenvector's sign is arbitrary, and a coordinate moving
  // against another (a left mouth corner against the right one) is as redundant as one moving with it.
  const KMeansPoints points(pca.components.cwiseAbs());
  PfaSweep sweep;
  sweep.components = pca.count();
  sweep.explainedVariance = pca.explainedFraction();

  const auto& units = symmetry.units();
  const std::size_t unitCount = units.size();
  const auto restarts = static_cast<std::size_t>(options.restarts);
  // Work of a restart grows with k; progress counts k per restart.
  double totalWork = 0.0;
  for (Eigen::Index k = lowK; k <= highK; ++k)
    totalWork += static_cast<double>(k) * static_cast<double>(restarts);
  double doneBefore = 0.0;
  std::atomic<std::size_t> doneRestarts{0};
  ProgressReporter reporter(control);
  const int threads = threadCount(control);

  std::vector<std::uint8_t> chosen;  // restarts × units, 1 when the restart selected the unit
  for (Eigen::Index k = lowK; k <= highK; ++k) {
    chosen.assign(restarts * unitCount, 0);
    doneRestarts = 0;
    const auto body = [&](std::size_t r) {
      const KMeansResult clusters =
          kMeans(points, k, mixSeed(options.seed, static_cast<std::uint64_t>(k), r), options.kMeans);
      std::uint8_t* row = chosen.data() + r * unitCount;
      for (const Eigen::Index feature : clusters.representatives)
        if (feature >= 0)
          row[static_cast<std::size_t>(symmetry.unitOf(feature / 3))] = 1;
      doneRestarts.fetch_add(1, std::memory_order_relaxed);
    };
    const auto tick = [&] {
      reporter.report((doneBefore + static_cast<double>(k) * static_cast<double>(doneRestarts.load())) /
                      totalWork);
    };
    if (!parallelFor(restarts, threads, body, control.cancel, tick)) {
      sweep.cancelled = true;
      break;
    }
    doneBefore += static_cast<double>(k) * static_cast<double>(restarts);

    PfaSelection selection;
    selection.k = k;
    selection.unitFrequency.assign(unitCount, 0.0);
    for (std::size_t r = 0; r < restarts; ++r)
      for (std::size_t u = 0; u < unitCount; ++u)
        selection.unitFrequency[u] += chosen[r * unitCount + u];
    for (double& f : selection.unitFrequency)
      f /= static_cast<double>(restarts);
    // The most stable restart: highest Σ frequency of its units; the first one on ties.
    std::size_t best = 0;
    double bestScore = -1.0;
    for (std::size_t r = 0; r < restarts; ++r) {
      double score = 0.0;
      for (std::size_t u = 0; u < unitCount; ++u)
        if (chosen[r * unitCount + u])
          score += selection.unitFrequency[u];
      if (score > bestScore) {
        bestScore = score;
        best = r;
      }
    }
    std::vector<bool> selected(unitCount);
    for (std::size_t u = 0; u < unitCount; ++u)
      selected[u] = chosen[best * unitCount + u] != 0;
    selection.markers = markersOfUnits(symmetry, selected);
    selection.stability = bestScore;
    const bool complete = static_cast<Eigen::Index>(selection.markers.size()) == markers;
    sweep.selections.push_back(std::move(selection));
    if (automatic && complete)
      break;
  }
  if (!sweep.cancelled)
    reporter.report(1.0, true);
  return sweep;
}

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
                                                                   const RunControl& control,
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
  ProgressReporter reporter(control);
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
    reporter.report(static_cast<double>(done.load()) / static_cast<double>(sizes.size()));
  };
  if (!parallelFor(sizes.size(), threadCount(control), body, control.cancel, tick))
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
  reporter.report(1.0, true);
  return result;
}

std::optional<std::vector<Eigen::Index>> selectRandom(const MarkerSymmetry& symmetry, Eigen::Index size,
                                                      std::uint64_t seed)
{
  if (size < 1 || size > symmetry.markerCount())
    throw InvalidArgument("random selection: the size must be between 1 and " +
                          std::to_string(symmetry.markerCount()) + ", not " + std::to_string(size));
  if (!sizeReachable(symmetry, size))
    return std::nullopt;
  const auto& units = symmetry.units();
  std::vector<std::size_t> order(units.size());
  Random random(seed);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    for (std::size_t u = 0; u < order.size(); ++u)
      order[u] = u;
    random.shuffle(order.begin(), order.end());
    std::vector<bool> selected(units.size(), false);
    Eigen::Index count = 0;
    for (const std::size_t u : order) {
      const auto width = static_cast<Eigen::Index>(units[u].size());
      if (count + width <= size) {
        selected[u] = true;
        count += width;
      }
    }
    if (count == size)
      return markersOfUnits(symmetry, selected);
  }
  return std::nullopt;
}

std::size_t chooseKnee(const std::vector<Eigen::Index>& sizes, const std::vector<double>& errorA,
                       const std::vector<double>& errorB)
{
  if (sizes.empty())
    throw InvalidArgument("knee: there are no points");
  if (errorA.size() != sizes.size() || errorB.size() != sizes.size())
    throw InvalidArgument("knee: the sizes and errors differ in length");
  for (std::size_t i = 0; i < sizes.size(); ++i)
    if (!std::isfinite(errorA[i]) || !std::isfinite(errorB[i]))
      throw InvalidArgument("knee: an error is not finite");
  if (sizes.size() < 3)
    return 0;
  const double maxA = *std::max_element(errorA.begin(), errorA.end());
  const double maxB = *std::max_element(errorB.begin(), errorB.end());
  std::vector<double> y(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i)
    y[i] = 0.5 * ((maxA > 0.0 ? errorA[i] / maxA : 0.0) + (maxB > 0.0 ? errorB[i] / maxB : 0.0));
  const auto first = static_cast<double>(sizes.front());
  const double span = std::max(1.0, static_cast<double>(sizes.back()) - first);
  std::size_t knee = 0;
  double deepest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const double x = (static_cast<double>(sizes[i]) - first) / span;
    const double chord = y.front() + (y.back() - y.front()) * x;
    if (chord - y[i] > deepest) {
      deepest = chord - y[i];
      knee = i;
    }
  }
  return knee;
}

const ScoredLayout* LayoutSize::layout(SelectionMethod method) const
{
  const auto& chosen = method == SelectionMethod::Pfa ? pfa : greedy;
  return chosen ? &*chosen : nullptr;
}

const LayoutSize* LayoutPlan::size(Eigen::Index markerCount) const
{
  for (const LayoutSize& entry : sizes)
    if (entry.markerCount == markerCount)
      return &entry;
  return nullptr;
}

LayoutPlan planMarkerLayout(const LayoutFrames& frames, const MarkerSymmetry& symmetry,
                            const LayoutPlanOptions& options, const RunControl& control)
{
  const Eigen::Index markers = frames.markerCount();
  if (markers < 2)
    throw InvalidArgument("layout planning needs at least two markers, got " + std::to_string(markers));
  if (frames.frames.cols() != 3 * markers)
    throw InvalidArgument("layout planning: the frames do not hold 3 values per marker");
  checkSymmetry(symmetry, markers);
  if (options.randomSubsets < 0)
    throw InvalidArgument("layout planning: randomSubsets must be ≥ 0");
  const Eigen::MatrixXd training = frames.frames(frames.training, Eigen::all);
  checkTraining(training);

  LayoutPlan plan;
  plan.method = options.method;
  // Blendshape basis from the full set: given key poses, or extreme training frames.
  std::vector<Eigen::Index> neutralCandidates;
  for (const Eigen::Index r : frames.training)
    if (std::find(options.keyFrames.begin(), options.keyFrames.end(), r) == options.keyFrames.end())
      neutralCandidates.push_back(r);
  if (neutralCandidates.empty())
    throw InvalidArgument("layout planning: every training frame is a key pose; no neutral frame left");
  const Eigen::Index neutral = findNeutralFrame(frames.frames, neutralCandidates);
  const std::vector<Eigen::Index> keyFrames =
      options.keyFrames.empty()
          ? chooseKeyPoses(frames.frames, neutral, options.keyPoseCount, frames.training)
          : options.keyFrames;
  const SubsetErrors errors(frames.frames, frames.training, frames.test,
                            buildBlendshapeBasis(frames.frames, neutral, keyFrames), options.errors);
  plan.basis = errors.basis();
  plan.motionRms = errors.motionRms();

  const bool runPfa = options.method == SelectionMethod::Pfa || options.compare;
  const bool runOthers = options.method == SelectionMethod::Greedy || options.compare;
  // Shares of the progress bar, roughly by cost.
  const double pfaEnd = runPfa ? (runOthers ? 0.55 : 0.9) : 0.0;
  const double greedyEnd = runOthers ? 0.9 : pfaEnd;
  ProgressReporter reporter(control);
  reporter.report(0.0, true);
  const auto stage = [&](double from, double to) {
    RunControl sub = control;
    sub.progress = control.progress ? std::function<void(double)>([&reporter, from, to](double f) {
      reporter.report(from + (to - from) * f);
    })
                                    : std::function<void(double)>();
    return sub;
  };

  std::map<Eigen::Index, ScoredLayout> pfaBySize;
  if (runPfa) {
    const PfaSweep sweep = sweepPfa(training, symmetry, options.pfa, stage(0.0, pfaEnd));
    plan.pfaSweep = sweep.selections;
    plan.pcaComponents = sweep.components;
    plan.explainedVariance = sweep.explainedVariance;
    if (sweep.cancelled) {
      plan.cancelled = true;
      return plan;
    }
    // Several k can give the same size: keep the one that explains the training frames best.
    std::map<Eigen::Index, double> residualBySize;
    for (const PfaSelection& selection : sweep.selections) {
      const auto size = static_cast<Eigen::Index>(selection.markers.size());
      const double residual = errors.trainingResidual(selection.markers);
      const auto it = residualBySize.find(size);
      if (it != residualBySize.end() && it->second <= residual)
        continue;
      residualBySize[size] = residual;
      ScoredLayout layout;
      layout.markers = selection.markers;
      layout.k = selection.k;
      layout.unitFrequency = selection.unitFrequency;
      layout.stability = selection.stability;
      pfaBySize[size] = std::move(layout);
    }
  }

  // Every size below the full set that some method reaches.
  std::vector<Eigen::Index> otherSizes;
  for (Eigen::Index size = 1; size < markers; ++size) {
    const bool pfaHas = pfaBySize.count(size) != 0;
    const bool othersHave = runOthers && sizeReachable(symmetry, size);
    if (!pfaHas && !othersHave)
      continue;
    LayoutSize entry;
    entry.markerCount = size;
    if (pfaHas)
      entry.pfa = pfaBySize[size];
    plan.sizes.push_back(std::move(entry));
    if (othersHave)
      otherSizes.push_back(size);
  }
  if (runOthers) {
    std::map<Eigen::Index, std::vector<Eigen::Index>> pfaStarts;
    for (const auto& [size, layout] : pfaBySize)
      pfaStarts.emplace(size, layout.markers);
    const auto greedy = selectGreedy(errors, symmetry, otherSizes, stage(pfaEnd, greedyEnd), pfaStarts);
    if (greedy.size() != otherSizes.size()) {
      plan.cancelled = true;
      plan.sizes.clear();
      return plan;
    }
    for (std::size_t i = 0; i < otherSizes.size(); ++i)
      if (greedy[i])
        for (LayoutSize& entry : plan.sizes)
          if (entry.markerCount == otherSizes[i]) {
            entry.greedy = ScoredLayout{};
            entry.greedy->markers = *greedy[i];
          }
  }

  // Scoring jobs: per size the PFA set, the greedy set and the random sets, in parallel.
  struct Job
  {
    std::size_t size;
    int kind;  // 0 PFA, 1 greedy, 2 + i random i
  };
  std::vector<Job> jobs;
  for (std::size_t s = 0; s < plan.sizes.size(); ++s) {
    if (plan.sizes[s].pfa)
      jobs.push_back({s, 0});
    if (plan.sizes[s].greedy)
      jobs.push_back({s, 1});
    if (runOthers && sizeReachable(symmetry, plan.sizes[s].markerCount))
      for (int i = 0; i < options.randomSubsets; ++i)
        jobs.push_back({s, 2 + i});
  }
  std::vector<std::optional<ScoredLayout>> scored(jobs.size());
  std::atomic<std::size_t> done{0};
  const auto body = [&](std::size_t j) {
    const Job& job = jobs[j];
    const LayoutSize& entry = plan.sizes[job.size];
    ScoredLayout layout;
    if (job.kind == 0) {
      layout = *entry.pfa;
    } else if (job.kind == 1) {
      layout = *entry.greedy;
    } else {
      const auto set = selectRandom(symmetry, entry.markerCount,
                                    mixSeed(options.pfa.seed ^ 0x52414E444F4DULL,
                                            static_cast<std::uint64_t>(entry.markerCount),
                                            static_cast<std::uint64_t>(job.kind - 2)));
      if (set)
        layout.markers = *set;
    }
    if (!layout.markers.empty()) {
      layout.blendshapeError = errors.blendshapeError(layout.markers);
      layout.reconstructionRmse = errors.reconstructionRmse(layout.markers);
      scored[j] = std::move(layout);
    }
    done.fetch_add(1, std::memory_order_relaxed);
  };
  const auto tick = [&] {
    reporter.report(greedyEnd + (1.0 - greedyEnd) * static_cast<double>(done.load()) /
                                    static_cast<double>(std::max<std::size_t>(jobs.size(), 1)));
  };
  if (!parallelFor(jobs.size(), threadCount(control), body, control.cancel, tick)) {
    plan.cancelled = true;
    plan.sizes.clear();
    return plan;
  }
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    LayoutSize& entry = plan.sizes[jobs[j].size];
    if (!scored[j])
      continue;
    if (jobs[j].kind == 0) {
      entry.pfa = std::move(scored[j]);
    } else if (jobs[j].kind == 1) {
      entry.greedy = std::move(scored[j]);
    } else {
      entry.randomBlendshapeError += scored[j]->blendshapeError;
      entry.randomReconstructionRmse += scored[j]->reconstructionRmse;
      ++entry.randomCount;
    }
  }
  for (LayoutSize& entry : plan.sizes)
    if (entry.randomCount > 0) {
      entry.randomBlendshapeError /= entry.randomCount;
      entry.randomReconstructionRmse /= entry.randomCount;
    }

  // The knee of the chosen method's curve, closed by the full set (error 0).
  std::vector<Eigen::Index> sizes;
  std::vector<double> blend, rmse;
  for (const LayoutSize& entry : plan.sizes)
    if (const ScoredLayout* layout = entry.layout(options.method)) {
      sizes.push_back(entry.markerCount);
      blend.push_back(layout->blendshapeError);
      rmse.push_back(layout->reconstructionRmse);
    }
  sizes.push_back(markers);
  blend.push_back(0.0);
  rmse.push_back(0.0);
  plan.recommendedSize = sizes[chooseKnee(sizes, blend, rmse)];
  plan.recommendationRule = "knee of the " + std::string(selectionMethodName(options.method)) +
                            " curve: both errors scaled by their largest value and averaged; the size "
                            "farthest below the straight line from "
                            "the smallest layout to the full set (Kneedle)";
  reporter.report(1.0, true);
  return plan;
}

} // namespace mocap
