#include "mocap/layout/layout_planning.h"

#include "mocap/base/error.h"
#include "mocap/base/parallel_for.h"
#include "mocap/base/random.h"
#include "mocap/base/text.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/layout/layout_symmetry.h"
#include "mocap/model/marker_points.h"

#include "selection_units.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace mocap {

namespace {

using layout_internal::checkSymmetry;
using layout_internal::checkTraining;
using layout_internal::sizeReachable;

// The errors every set is scored by, against the full set: its blendshape basis from the given
// key poses, or from extreme training frames, and a neutral frame that is no key pose.
SubsetErrors planErrors(const LayoutFrames& frames, const LayoutPlanOptions& options)
{
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
  return SubsetErrors(frames.frames, frames.training, frames.test,
                      buildBlendshapeBasis(frames.frames, neutral, keyFrames), options.errors);
}

// PFA's set of each size: several k can give the same size, and the one that explains the
// training frames best is kept.
std::map<Eigen::Index, ScoredLayout> pfaLayoutsBySize(const PfaSweep& sweep, const SubsetErrors& errors)
{
  std::map<Eigen::Index, ScoredLayout> pfaBySize;
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
  return pfaBySize;
}

// Puts into plan.sizes every size below the full set (`markers`) that some method reaches, with
// PFA's set where it has one; returns the sizes the other methods reach (when they run).
std::vector<Eigen::Index> addSizes(LayoutPlan& plan, Eigen::Index markers, const MarkerSymmetry& symmetry,
                                   const std::map<Eigen::Index, ScoredLayout>& pfaBySize, bool runOthers)
{
  std::vector<Eigen::Index> otherSizes;
  for (Eigen::Index size = 1; size < markers; ++size) {
    const auto pfa = pfaBySize.find(size);
    const bool othersHave = runOthers && sizeReachable(symmetry, size);
    if (pfa == pfaBySize.end() && !othersHave)
      continue;
    LayoutSize entry;
    entry.markerCount = size;
    if (pfa != pfaBySize.end())
      entry.pfa = pfa->second;
    plan.sizes.push_back(std::move(entry));
    if (othersHave)
      otherSizes.push_back(size);
  }
  return otherSizes;
}

// The greedy set of each of `otherSizes`, started from PFA's sets too; false when cancelled.
bool addGreedyLayouts(LayoutPlan& plan, const SubsetErrors& errors, const MarkerSymmetry& symmetry,
                      const std::vector<Eigen::Index>& otherSizes,
                      const std::map<Eigen::Index, ScoredLayout>& pfaBySize, const JobControl& control)
{
  std::map<Eigen::Index, std::vector<Eigen::Index>> pfaStarts;
  for (const auto& [size, layout] : pfaBySize)
    pfaStarts.emplace(size, layout.markers);
  const auto greedy = selectGreedy(errors, symmetry, otherSizes, control, pfaStarts);
  if (greedy.size() != otherSizes.size())
    return false;
  for (std::size_t i = 0; i < otherSizes.size(); ++i)
    if (greedy[i])
      for (LayoutSize& entry : plan.sizes)
        if (entry.markerCount == otherSizes[i]) {
          entry.greedy = ScoredLayout{};
          entry.greedy->markers = *greedy[i];
        }
  return true;
}

// One set to score: of size plan.sizes[size], PFA's (kind 0), greedy's (1) or random set i (2 + i).
struct ScoringJob
{
  std::size_t size;
  int kind;
};

std::vector<ScoringJob> scoringJobs(const LayoutPlan& plan, const MarkerSymmetry& symmetry,
                                    const LayoutPlanOptions& options, bool runOthers)
{
  std::vector<ScoringJob> jobs;
  for (std::size_t s = 0; s < plan.sizes.size(); ++s) {
    if (plan.sizes[s].pfa)
      jobs.push_back({s, 0});
    if (plan.sizes[s].greedy)
      jobs.push_back({s, 1});
    if (runOthers && sizeReachable(symmetry, plan.sizes[s].markerCount))
      for (int i = 0; i < options.randomSubsets; ++i)
        jobs.push_back({s, 2 + i});
  }
  return jobs;
}

// The set of `job` with both its errors; nullopt when no random set of its size exists.
std::optional<ScoredLayout> scoreJob(const LayoutPlan& plan, const ScoringJob& job, const SubsetErrors& errors,
                                     const MarkerSymmetry& symmetry, std::uint64_t seed)
{
  const LayoutSize& entry = plan.sizes[job.size];
  ScoredLayout layout;
  if (job.kind == 0) {
    layout = *entry.pfa;
  } else if (job.kind == 1) {
    layout = *entry.greedy;
  } else {
    const auto set = selectRandom(symmetry, entry.markerCount,
                                  mixSeed(seed ^ 0x52414E444F4DULL, static_cast<std::uint64_t>(entry.markerCount),
                                          static_cast<std::uint64_t>(job.kind - 2)));
    if (set)
      layout.markers = *set;
  }
  if (layout.markers.empty())
    return std::nullopt;
  layout.blendshapeError = errors.blendshapeError(layout.markers);
  layout.reconstructionRmse = errors.reconstructionRmse(layout.markers);
  return layout;
}

// Scores every set of the plan and the random baseline of each size, in parallel; false when
// cancelled.
bool scoreLayouts(LayoutPlan& plan, const SubsetErrors& errors, const MarkerSymmetry& symmetry,
                  const LayoutPlanOptions& options, bool runOthers, const JobControl& control)
{
  const std::vector<ScoringJob> jobs = scoringJobs(plan, symmetry, options, runOthers);
  std::vector<std::optional<ScoredLayout>> scored(jobs.size());
  std::atomic<std::size_t> done{0};
  const auto body = [&](std::size_t j) {
    scored[j] = scoreJob(plan, jobs[j], errors, symmetry, options.pfa.seed);
    done.fetch_add(1, std::memory_order_relaxed);
  };
  const auto tick = [&] {
    control.report(static_cast<double>(done.load()) / static_cast<double>(std::max<std::size_t>(jobs.size(), 1)));
  };
  if (!parallelFor(jobs.size(), control.threads(), body, control.cancelFlag(), tick))
    return false;
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
  return true;
}

// The knee of the plan's method's curve, closed by the full set of `markers` (error 0).
void recommendSize(LayoutPlan& plan, Eigen::Index markers)
{
  std::vector<Eigen::Index> sizes;
  std::vector<double> blend, rmse;
  for (const LayoutSize& entry : plan.sizes)
    if (const ScoredLayout* layout = entry.layout(plan.method)) {
      sizes.push_back(entry.markerCount);
      blend.push_back(layout->blendshapeError);
      rmse.push_back(layout->reconstructionRmse);
    }
  sizes.push_back(markers);
  blend.push_back(0.0);
  rmse.push_back(0.0);
  plan.recommendedSize = sizes[chooseKnee(sizes, blend, rmse)];
  plan.recommendationRule = "knee of the " + std::string(selectionMethodName(plan.method)) +
                            " curve: both errors scaled by their largest value and averaged; the size "
                            "farthest below the straight line from "
                            "the smallest layout to the full set (Kneedle)";
}

} // namespace

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
                            const LayoutPlanOptions& options, const JobControl& control)
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
  const SubsetErrors errors = planErrors(frames, options);
  plan.basis = errors.basis();
  plan.motionRms = errors.motionRms();

  const bool runPfa = options.method == SelectionMethod::Pfa || options.compare;
  const bool runOthers = options.method == SelectionMethod::Greedy || options.compare;
  // Shares of the progress bar, roughly by cost.
  const double pfaEnd = runPfa ? (runOthers ? 0.55 : 0.9) : 0.0;
  const double greedyEnd = runOthers ? 0.9 : pfaEnd;
  control.reportNow(0.0);

  std::map<Eigen::Index, ScoredLayout> pfaBySize;
  if (runPfa) {
    const PfaSweep sweep = sweepPfa(training, symmetry, options.pfa, control.part(0.0, pfaEnd));
    plan.pfaSweep = sweep.selections;
    plan.pcaComponents = sweep.components;
    plan.explainedVariance = sweep.explainedVariance;
    if (sweep.cancelled) {
      plan.cancelled = true;
      return plan;
    }
    pfaBySize = pfaLayoutsBySize(sweep, errors);
  }
  const std::vector<Eigen::Index> otherSizes = addSizes(plan, markers, symmetry, pfaBySize, runOthers);
  if ((runOthers && !addGreedyLayouts(plan, errors, symmetry, otherSizes, pfaBySize,
                                      control.part(pfaEnd, greedyEnd))) ||
      !scoreLayouts(plan, errors, symmetry, options, runOthers, control.part(greedyEnd, 1.0))) {
    plan.cancelled = true;
    plan.sizes.clear();
    return plan;
  }
  recommendSize(plan, markers);
  control.reportNow(1.0);
  return plan;
}

namespace {

using Field = LayoutRequestError::Field;

// The planned markers: the patterns' matches among the marker points (model outputs are never
// planned) or the default set, without the excluded ones.
std::vector<std::string> plannedLabels(const Take& first, const LayoutRequest& request)
{
  std::vector<std::string> planned = request.markerPatterns.empty()
                                         ? defaultPlannedLabels(first, request.stabilizeLabels)
                                         : labelsMatching(markerLabels(first), request.markerPatterns, Field::Markers);
  if (!request.excludePatterns.empty()) {
    const std::vector<std::string> excluded = labelsMatching(first.labels(), request.excludePatterns, Field::Exclude);
    const auto isExcluded = [&](const std::string& label) {
      return std::find(excluded.begin(), excluded.end(), label) != excluded.end();
    };
    planned.erase(std::remove_if(planned.begin(), planned.end(), isExcluded), planned.end());
  }
  return planned;
}

std::string keyPoseName(const KeyPose& pose)
{
  return pose.take == 0 ? std::to_string(pose.frame) : std::to_string(pose.take + 1) + ":" + std::to_string(pose.frame);
}

// Rows of `frames` of the key poses; each must be a frame every planned marker has, once.
std::vector<Eigen::Index> keyPoseRows(const std::vector<Take>& takes, const LayoutFrames& frames,
                                      const std::vector<KeyPose>& poses)
{
  std::vector<Eigen::Index> rows;
  for (const KeyPose& pose : poses) {
    if (pose.take >= takes.size())
      throw LayoutRequestError(Field::KeyPoses, "there is no take " + std::to_string(pose.take + 1));
    const Take& take = takes[pose.take];
    const long long index = pose.frame - take.firstFrame();
    const Eigen::Index row =
        index >= 0 && index < take.frameCount() ? frames.rowOf(pose.take, static_cast<Eigen::Index>(index)) : -1;
    if (row < 0)
      throw LayoutRequestError(Field::KeyPoses,
                               "frame " + keyPoseName(pose) + " is outside the take or lacks a planned marker");
    if (std::find(rows.begin(), rows.end(), row) != rows.end())
      throw LayoutRequestError(Field::KeyPoses, "frame " + keyPoseName(pose) + " is given twice");
    rows.push_back(row);
  }
  return rows;
}

// A whole decimal number (optionally signed), or nullopt.
std::optional<long long> wholeNumber(std::string_view text)
{
  const std::string copy(text);
  std::size_t used = 0;
  try {
    const long long value = std::stoll(copy, &used);
    if (used == copy.size() && !copy.empty() && copy.find_first_of(" \t+") == std::string::npos)
      return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

} // namespace

std::vector<KeyPose> parseKeyPoses(std::string_view text)
{
  const std::string_view trimmed = trim(text);
  if (trimmed.empty() || trimmed == "auto")
    return {};
  std::vector<KeyPose> poses;
  for (const std::string_view rawField : split(trimmed, ',')) {
    const std::string_view field = trim(rawField);
    KeyPose pose;
    std::string_view frameText = field;
    if (const std::size_t colon = field.find(':'); colon != std::string_view::npos) {
      const std::string_view takeText = field.substr(0, colon);
      const auto take = wholeNumber(takeText);
      if (!take || *take < 1 || takeText.find_first_not_of("0123456789") != std::string_view::npos)
        throw LayoutRequestError(Field::KeyPoses, "bad take number in '" + std::string(field) + "'");
      pose.take = static_cast<std::size_t>(*take - 1);
      frameText = field.substr(colon + 1);
    }
    const auto frame = wholeNumber(frameText);
    if (!frame)
      throw LayoutRequestError(Field::KeyPoses, "expected auto or frame numbers, not '" + std::string(field) + "'");
    pose.frame = *frame;
    poses.push_back(pose);
  }
  return poses;
}

std::vector<std::string> labelsMatching(const std::vector<std::string>& labels,
                                        const std::vector<std::string>& patterns, Field field)
{
  std::set<std::string> found;
  for (const std::string& pattern : patterns) {
    bool any = false;
    for (const std::string& label : labels)
      if (globMatch(pattern, label)) {
        found.insert(label);
        any = true;
      }
    if (!any)
      throw LayoutRequestError(field, "no marker matches '" + pattern + "'");
  }
  std::vector<std::string> ordered;
  for (const std::string& label : labels)
    if (found.count(label) != 0)
      ordered.push_back(label);
  return ordered;
}

LayoutResult planLayout(const std::vector<Take>& takes, const LayoutRequest& request, const JobControl& control)
{
  if (takes.empty())
    throw InvalidArgument("layout planning needs at least one take");
  LayoutResult result;
  result.stabilizeLabels = request.stabilizeLabels;
  LayoutFramesOptions frameOptions;
  frameOptions.stabilizeLabels = request.stabilizeLabels;
  frameOptions.markers = plannedLabels(takes.front(), request);
  result.frames = collectLayoutFrames(takes, frameOptions);

  LayoutPlanOptions options = request.plan;
  options.keyFrames = keyPoseRows(takes, result.frames, request.keyPoses);
  if (request.pairsFile.empty()) {
    result.detection = detectLayoutPairs(result.frames, options.keyFrames);
    result.symmetry = result.detection->symmetry;
  } else {
    result.symmetry = readMarkerPairs(request.pairsFile, result.frames.labels);
  }
  result.plan = planMarkerLayout(result.frames, result.symmetry, options, control);
  return result;
}

std::vector<std::string> LayoutResult::labelsOf(const std::vector<Eigen::Index>& markers) const
{
  std::vector<std::string> labels;
  for (const Eigen::Index m : markers)
    labels.push_back(frames.labels[static_cast<std::size_t>(m)]);
  return labels;
}

const ScoredLayout* LayoutResult::layout(Eigen::Index markerCount) const
{
  const LayoutSize* entry = plan.size(markerCount);
  return entry ? entry->layout(plan.method) : nullptr;
}

std::vector<std::string> LayoutResult::captureLabels(const ScoredLayout* chosen) const
{
  std::vector<std::string> labels = chosen ? labelsOf(chosen->markers) : frames.labels;
  labels.insert(labels.end(), stabilizeLabels.begin(), stabilizeLabels.end());
  return labels;
}

} // namespace mocap
