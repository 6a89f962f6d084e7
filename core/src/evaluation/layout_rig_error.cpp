#include "mocap/evaluation/layout_rig_error.h"

#include "mocap/base/error.h"
#include "mocap/base/job_control.h"
#include "mocap/base/parallel_for.h"
#include "mocap/base/random.h"
#include "mocap/base/stopwatch.h"
#include "mocap/deform/retarget.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <set>

namespace mocap {

namespace {

/// Every `step`-th frame of `take` from `phase` on, as a take of its own at the rate over step;
/// point types, positions and validity only (what the solver reads). O(#frames / step · #markers).
Take everyNthFrame(const Take& take, Eigen::Index phase, Eigen::Index step)
{
  const Eigen::Index count = (take.frameCount() - phase + step - 1) / step;
  Take picked(take.labels(), count, take.frameRate() / static_cast<double>(step));
  picked.setUnits(take.units());
  picked.setFirstFrame(take.firstFrame() + phase);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    picked.setPointType(m, take.pointType(m));
  for (Eigen::Index i = 0; i < count; ++i)
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      picked.setPosition(i, m, take.position(phase + i * step, m));
      picked.valid()(i, m) = take.isValid(phase + i * step, m);
    }
  return picked;
}

/// One take made ready: head motion removed, frames picked, the solver set up and the weights
/// solved from every bound marker.
struct SolvedTake
{
  Take take;
  std::unique_ptr<BlendshapeSolver> solver;
  BlendshapeSolveResult full;
};

SolvedTake prepareTake(const Take& source, const BlendshapeRig& rig, const MeshBinding& binding,
                       const LayoutRigErrorOptions& options, const JobControl& control)
{
  SolvedTake prepared;
  Take take = source;
  (void)stabilizeTake(take, options.stabilizeLabels);
  // The neutral frame of the whole take, so picking frames cannot move it.
  const Eigen::Index neutral =
      bindTake(binding, take, rig.neutral.vertices, options.solve.neutralFrame, options.solve.scale).neutral;
  const Eigen::Index step =
      options.maxFrames > 0 ? std::max<Eigen::Index>(1, (take.frameCount() + options.maxFrames - 1) / options.maxFrames)
                            : 1;
  prepared.take = step > 1 ? everyNthFrame(take, neutral % step, step) : std::move(take);
  BlendshapeSolveOptions solve = options.solve;
  solve.neutralFrame = prepared.take.firstFrame() + neutral / step;
  prepared.solver = std::make_unique<BlendshapeSolver>(rig, binding, prepared.take, solve);
  prepared.full = prepared.solver->solve(prepared.take, {}, control);
  return prepared;
}

/// prepareTake for every take, each its share of `control`'s progress; false when cancelled.
bool prepareTakes(const std::vector<Take>& takes, const BlendshapeRig& rig, const MeshBinding& binding,
                  const LayoutRigErrorOptions& options, const JobControl& control, std::vector<SolvedTake>& solved)
{
  const auto count = static_cast<double>(takes.size());
  try {
    for (std::size_t t = 0; t < takes.size(); ++t)
      solved.push_back(prepareTake(takes[t], rig, binding, options,
                                   control.part(static_cast<double>(t) / count, static_cast<double>(t + 1) / count)));
  } catch (const JobCancelled&) {
    return false;
  }
  return true;
}

/// Which of the solver's bound markers `labels` names.
std::vector<bool> useMask(const BlendshapeSolver& solver, const std::vector<std::string>& labels)
{
  const std::set<std::string> named(labels.begin(), labels.end());
  std::vector<bool> use;
  for (const std::string& label : solver.labels())
    use.push_back(named.count(label) != 0);
  return use;
}

/// Squared weight differences over the frames both solves solved, added to `sum` and `frames`.
void accumulate(const BlendshapeSolveResult& full, const BlendshapeSolveResult& layout, double& sum,
                Eigen::Index& frames)
{
  for (Eigen::Index f = 0; f < full.weights.rows(); ++f) {
    const auto i = static_cast<std::size_t>(f);
    if (full.held[i] || layout.held[i])
      continue;
    sum += (layout.weights.row(f) - full.weights.row(f)).squaredNorm();
    ++frames;
  }
}

RigLayoutError judgeLayout(const std::vector<SolvedTake>& takes, const std::vector<std::string>& labels,
                           const JobControl& control)
{
  RigLayoutError error;
  const std::vector<bool> use = useMask(*takes.front().solver, labels);
  error.boundMarkers = static_cast<Eigen::Index>(std::count(use.begin(), use.end(), true));
  if (error.boundMarkers < kMinimumRigLayoutMarkers)
    return error;
  double sum = 0.0;
  for (const SolvedTake& take : takes)
    accumulate(take.full, take.solver->solve(take.take, use, control), sum, error.frames);
  const Eigen::Index shapes = takes.front().full.weights.cols();
  if (error.frames > 0)
    error.mse = sum / static_cast<double>(error.frames * shapes);
  return error;
}

} // namespace

LayoutRigErrors layoutRigErrors(const std::vector<Take>& takes, const BlendshapeRig& rig, const MeshBinding& binding,
                                const std::vector<std::vector<std::string>>& layouts,
                                const LayoutRigErrorOptions& options, const JobControl& control)
{
  const Stopwatch clock;
  if (takes.empty())
    throw InvalidArgument("rig layout error: no takes");
  if (options.maxFrames < 0)
    throw InvalidArgument("rig layout error: the frame limit must be ≥ 0 (0: every frame)");
  LayoutRigErrors result;
  result.layouts.resize(layouts.size());
  const JobControl cancelOnly = control.silent();
  // The full-set solves are a share of the work like one layout each.
  const double total = static_cast<double>(takes.size() * (layouts.size() + 1));
  std::vector<SolvedTake> solved;
  if (!prepareTakes(takes, rig, binding, options, control.part(0.0, static_cast<double>(takes.size()) / total),
                    solved)) {
    result.cancelled = true;
    return result;
  }
  result.boundMarkers = static_cast<Eigen::Index>(solved.front().solver->markers().size());
  for (const SolvedTake& take : solved)
    result.frames += static_cast<Eigen::Index>(std::count(take.full.held.begin(), take.full.held.end(), false));

  std::atomic<std::size_t> done{0};
  const auto body = [&](std::size_t i) {
    result.layouts[i] = judgeLayout(solved, layouts[i], cancelOnly);
    done.fetch_add(1, std::memory_order_relaxed);
  };
  // On the calling thread, between layouts; parallelFor itself stops on a cancel.
  const auto tick = [&] { control.report(static_cast<double>(takes.size() * (1 + done.load())) / total); };
  try {
    result.cancelled = !parallelFor(layouts.size(), control.threads(), body, control.cancelFlag(), tick);
  } catch (const JobCancelled&) {
    result.cancelled = true;
  }
  if (!result.cancelled)
    control.reportNow(1.0);
  result.seconds = clock.seconds();
  return result;
}

const LayoutSizeRigErrors* PlanRigErrors::size(Eigen::Index markerCount) const
{
  for (const LayoutSizeRigErrors& entry : sizes)
    if (entry.markerCount == markerCount)
      return &entry;
  return nullptr;
}

PlanRigErrors planRigErrors(const std::vector<Take>& takes, const LayoutResult& result, const BlendshapeRig& rig,
                            const MeshBinding& binding, const LayoutRigErrorOptions& options,
                            const JobControl& control)
{
  if (options.randomSubsets < 0)
    throw InvalidArgument("rig layout error: the random layout count must be ≥ 0");
  // The layouts in a fixed order: all planned markers, then per size PFA, greedy, random ones.
  enum Kind { Pfa, Greedy, Random };
  struct Job
  {
    std::size_t size;
    Kind kind;
  };
  std::vector<std::vector<std::string>> layouts{result.frames.labels};
  std::vector<Job> jobs;
  const auto add = [&](std::size_t size, Kind kind, const std::vector<Eigen::Index>& markers) {
    layouts.push_back(result.labelsOf(markers));
    jobs.push_back({size, kind});
  };
  const std::vector<LayoutSize>& sizes = result.plan.sizes;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    if (sizes[s].pfa)
      add(s, Pfa, sizes[s].pfa->markers);
    if (sizes[s].greedy)
      add(s, Greedy, sizes[s].greedy->markers);
    for (int r = 0; r < options.randomSubsets; ++r)
      if (const auto set = selectRandom(result.symmetry, sizes[s].markerCount,
                                        mixSeed(options.seed, static_cast<std::uint64_t>(sizes[s].markerCount),
                                                static_cast<std::uint64_t>(r))))
        add(s, Random, *set);
  }
  LayoutRigErrorOptions withPlan = options;
  withPlan.stabilizeLabels = result.stabilizeLabels;
  const LayoutRigErrors judged = layoutRigErrors(takes, rig, binding, layouts, withPlan, control);

  PlanRigErrors plan;
  plan.boundMarkers = judged.boundMarkers;
  plan.frames = judged.frames;
  plan.seconds = judged.seconds;
  plan.cancelled = judged.cancelled;
  plan.planned = judged.layouts.empty() ? RigLayoutError{} : judged.layouts.front();
  plan.sizes.resize(sizes.size());
  for (std::size_t s = 0; s < sizes.size(); ++s)
    plan.sizes[s].markerCount = sizes[s].markerCount;
  std::vector<double> randomSums(sizes.size(), 0.0);
  for (std::size_t j = 0; j < jobs.size() && !judged.layouts.empty(); ++j) {
    const RigLayoutError& error = judged.layouts[j + 1];
    LayoutSizeRigErrors& entry = plan.sizes[jobs[j].size];
    if (jobs[j].kind == Pfa)
      entry.pfa = error;
    else if (jobs[j].kind == Greedy)
      entry.greedy = error;
    else if (error.judged()) {
      randomSums[jobs[j].size] += error.mse;
      ++entry.randomCount;
    }
  }
  for (std::size_t s = 0; s < sizes.size(); ++s)
    if (plan.sizes[s].randomCount > 0)
      plan.sizes[s].randomMse = randomSums[s] / plan.sizes[s].randomCount;
  return plan;
}

} // namespace mocap
