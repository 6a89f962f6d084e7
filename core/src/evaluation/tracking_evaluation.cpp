#include "mocap/evaluation/tracking_evaluation.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/tracking/fragment_joining.h"
#include "mocap/model/valid_runs.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace mocap {

namespace {

constexpr int kAttemptsPerSwap = 200;
constexpr Eigen::Index kSwapNeighbours = 3;
constexpr Eigen::Index kSwapMargin = 3;  // valid frames either side of a swap, so it is observable

void checkTrackingEvaluationOptions(const Take& take, const TrackingEvaluationOptions& options)
{
  if (take.empty())
    throw InvalidArgument("tracking evaluation: the take is empty");
  if (options.meanFragmentLength < 1 || options.meanFragmentLength > 1000000)
    throw InvalidArgument("tracking evaluation: the mean fragment length must be in 1..10^6 frames");
  if (options.maxCutGap < 0 || options.maxCutGap > 1000)
    throw InvalidArgument("tracking evaluation: the gap at a cut must be in 0..1000 frames");
  if (options.swaps < 0 || options.swaps > 1000)
    throw InvalidArgument("tracking evaluation: swaps must be in 0..1000");
  if (options.minSwapLength < 1 || options.maxSwapLength < options.minSwapLength)
    throw InvalidArgument("tracking evaluation: swap lengths must satisfy 1 ≤ min ≤ max");
}

std::vector<Eigen::Index> labelledMarkers(const Take& take)
{
  std::vector<Eigen::Index> markers;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (!isUnlabelledLabel(take.label(m)))
      markers.push_back(m);
  return markers;
}

// Marker `m` cut into random pieces; dropped frames are cleared in `kept`.
void cutMarker(const Take& take, Eigen::Index m, const TrackingEvaluationOptions& options, Random& random,
               std::vector<Fragment>& pieces, SampleMask& kept)
{
  const auto trajectory = take.trajectory(m);
  for (const ValidRun& run : findValidRuns(take.valid().col(m))) {
    Eigen::Index f = run.first;
    const Eigen::Index end = run.first + run.length;
    while (f < end) {
      const Eigen::Index length = std::min(end - f, 1 + random.index(2 * options.meanFragmentLength));
      Fragment piece;
      piece.first = f;
      for (Eigen::Index g = f; g < f + length; ++g) {
        piece.positions.push_back(trajectory.row(g).transpose());
        kept(g, m) = true;
      }
      pieces.push_back(std::move(piece));
      f += length + random.index(options.maxCutGap + 1);
    }
  }
}

bool validThrough(const Take& take, Eigen::Index m, Eigen::Index first, Eigen::Index end)
{
  return first >= 0 && end <= take.frameCount() && take.valid().col(m).segment(first, end - first).all();
}

} // namespace

UnlabelledCopy makeUnlabelledCopy(const Take& take, const TrackingEvaluationOptions& options)
{
  checkTrackingEvaluationOptions(take, options);
  Random random(mixSeed(options.seed, 0x7261636bULL, 1));
  UnlabelledCopy copy;
  copy.kept = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  std::vector<Fragment> pieces;
  for (const Eigen::Index m : labelledMarkers(take))
    cutMarker(take, m, options, random, pieces, copy.kept);
  std::vector<Eigen::Index> strays;  // the take's own unlabelled markers: points to ignore
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    if (isUnlabelledLabel(take.label(m)))
      strays.push_back(m);
  for (Fragment& piece : fragmentsOfMarkers(take, strays))
    pieces.push_back(std::move(piece));
  random.shuffle(pieces.begin(), pieces.end());  // no order reveals the label
  copy.fragments = static_cast<Eigen::Index>(pieces.size());  // strays included
  copy.take = Take({}, take.frameCount(), take.frameRate());
  copy.take.setUnits(take.units());
  copy.take.setFirstFrame(take.firstFrame());
  std::vector<Eigen::Index> all(pieces.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    all[i] = static_cast<Eigen::Index>(i);
  (void)appendFragments(copy.take, pieces, all);
  return copy;
}

Take makeSwappedCopy(const Take& take, const TrackingEvaluationOptions& options, std::vector<InjectedSwap>& swaps)
{
  checkTrackingEvaluationOptions(take, options);
  swaps.clear();
  Take copy = take;
  const std::vector<Eigen::Index> markers = labelledMarkers(take);
  if (markers.size() < 2 || options.swaps == 0)
    return copy;
  const MarkerSet set = markerSetFromTake(take);
  Random random(mixSeed(options.seed, 0x73776170ULL, 2));
  SampleMask busy = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  for (int attempt = 0; attempt < kAttemptsPerSwap * options.swaps && static_cast<int>(swaps.size()) < options.swaps;
       ++attempt) {
    const Eigen::Index a = random.index(set.size());
    std::vector<std::pair<double, Eigen::Index>> near;
    for (Eigen::Index j = 0; j < set.size(); ++j)
      if (j != a)
        near.emplace_back((set.neutral.row(j) - set.neutral.row(a)).squaredNorm(), j);
    std::sort(near.begin(), near.end());
    const Eigen::Index b = near[static_cast<std::size_t>(random.index(std::min<Eigen::Index>(kSwapNeighbours, set.size() - 1)))].second;
    const Eigen::Index ma = *take.markerIndex(set.labels[static_cast<std::size_t>(a)]);
    const Eigen::Index mb = *take.markerIndex(set.labels[static_cast<std::size_t>(b)]);
    const Eigen::Index length = options.minSwapLength + random.index(options.maxSwapLength - options.minSwapLength + 1);
    if (length + 2 * kSwapMargin >= take.frameCount())
      continue;
    const Eigen::Index begin = kSwapMargin + random.index(take.frameCount() - length - 2 * kSwapMargin);
    const Eigen::Index from = begin - kSwapMargin;
    const Eigen::Index to = begin + length + kSwapMargin;
    if (!validThrough(take, ma, from, to) || !validThrough(take, mb, from, to) ||
        busy.col(ma).segment(from, to - from).any() || busy.col(mb).segment(from, to - from).any())
      continue;
    busy.col(ma).segment(from, to - from).setConstant(true);
    busy.col(mb).segment(from, to - from).setConstant(true);
    exchangeMarkersFrom(copy, ma, mb, begin);
    exchangeMarkersFrom(copy, ma, mb, begin + length);
    swaps.push_back({std::min(ma, mb), std::max(ma, mb), begin, begin + length});
  }
  std::sort(swaps.begin(), swaps.end(), [](const InjectedSwap& x, const InjectedSwap& y) { return x.begin < y.begin; });
  return copy;
}

SampleMask trustworthySamples(const Take& take, const SwapOptions& options)
{
  const SampleMask jumps = findJumps(take, options);
  SampleMask trusted = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (const ValidRun& run : findValidRuns(take.valid().col(m)))
      if (!jumps.col(m).segment(run.first, run.length).any())
        trusted.col(m).segment(run.first, run.length).setConstant(true);
  return trusted;
}

double labelAgreement(const Take& truth, const Take& result, const SampleMask& scored, Eigen::Index* recoveredOut,
                      Eigen::Index* samplesOut)
{
  if (result.frameCount() != truth.frameCount() ||
      (scored.size() > 0 && (scored.rows() != truth.frameCount() || scored.cols() != truth.markerCount())))
    throw InvalidArgument("label agreement: the takes and the mask must have the same frames and markers");
  Eigen::Index samples = 0;
  Eigen::Index recovered = 0;
  for (const Eigen::Index m : labelledMarkers(truth)) {
    const auto r = result.markerIndex(truth.label(m));
    for (Eigen::Index f = 0; f < truth.frameCount(); ++f) {
      if (!(scored.size() > 0 ? scored(f, m) : truth.isValid(f, m)))
        continue;
      ++samples;
      if (r && result.isValid(f, *r) && result.position(f, *r) == truth.position(f, m))
        ++recovered;
    }
  }
  if (recoveredOut)
    *recoveredOut = recovered;
  if (samplesOut)
    *samplesOut = samples;
  return samples > 0 ? static_cast<double>(recovered) / static_cast<double>(samples) : 1.0;
}

TrackingEvaluation evaluateTracking(const Take& take, const TrackingEvaluationOptions& options)
{
  checkTrackingEvaluationOptions(take, options);
  if (labelledMarkers(take).size() < 4)
    throw InvalidArgument("tracking evaluation needs at least four labelled markers");
  TrackingEvaluation evaluation;
  evaluation.seed = options.seed;
  evaluation.frames = take.frameCount();
  evaluation.markers = static_cast<Eigen::Index>(labelledMarkers(take).size());

  const UnlabelledCopy copy = makeUnlabelledCopy(take, options);
  evaluation.fragments = copy.fragments;
  const MarkerSet set = markerSetFromTake(take);
  const Take labelled = trackTake(copy.take, &set, options.track, &evaluation.track);
  evaluation.labelRecovery = labelAgreement(take, labelled, copy.kept, &evaluation.recovered, &evaluation.samples);
  const SampleMask clean = copy.kept && trustworthySamples(take, options.swapDetection);
  evaluation.cleanLabelRecovery =
      labelAgreement(take, labelled, clean, &evaluation.cleanRecovered, &evaluation.cleanSamples);

  std::vector<InjectedSwap> injected;
  Take swapped = makeSwappedCopy(take, options, injected);
  evaluation.swapsInjected = static_cast<int>(injected.size());
  evaluation.swappedAgreement = labelAgreement(take, swapped, {});
  const std::vector<LabelSwap> found = repairSwaps(swapped, options.swapDetection);
  evaluation.repairedAgreement = labelAgreement(take, swapped, {});
  std::set<std::tuple<Eigen::Index, Eigen::Index, Eigen::Index>> events;
  for (const LabelSwap& swap : found)
    events.emplace(swap.frame, swap.first, swap.second);
  std::set<std::tuple<Eigen::Index, Eigen::Index, Eigen::Index>> boundaries;
  for (const InjectedSwap& swap : injected) {
    const bool start = events.count({swap.begin, swap.first, swap.second}) > 0;
    const bool end = swap.end >= take.frameCount() || events.count({swap.end, swap.first, swap.second}) > 0;
    evaluation.swapsFound += start && end ? 1 : 0;
    boundaries.emplace(swap.begin, swap.first, swap.second);
    boundaries.emplace(swap.end, swap.first, swap.second);
  }
  for (const auto& event : events)
    evaluation.falseAlarms += boundaries.count(event) == 0 ? 1 : 0;
  evaluation.swapsInOriginal = static_cast<int>(detectSwaps(take, options.swapDetection).size());
  return evaluation;
}

} // namespace mocap
