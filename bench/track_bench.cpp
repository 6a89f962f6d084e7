// Tracking and labelling on a long synthetic facial take: 40 markers × 10 000 frames at 100 Hz
// (head motion, expression modes), 2 % of the samples missing in gaps of 3-30 frames, made
// unlabelled and cut into ~1 300 fragments (makeUnlabelledCopy). Target (issue 8): tracked and
// labelled in under a second. BM_TrackAndLabel is the whole `mocap track` work (points, gated
// Hungarian tracking, template labelling); BM_TrackHungarian and the reference BM_TrackGreedy
// compare the tracking step alone against greedy nearest-neighbour assignment in the same run.
// The "recovered" counter is the fraction of samples back under their true label.
#include "mocap/base/random.h"
#include "mocap/tracking/take_tracking.h"
#include "mocap/evaluation/tracking_evaluation.h"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace {

constexpr Eigen::Index kMarkers = 40;
constexpr Eigen::Index kFrames = 10000;

mocap::Take syntheticTake()
{
  const double rate = 100.0;
  mocap::Random random(23);
  std::vector<std::string> labels;
  for (Eigen::Index m = 0; m < kMarkers; ++m)
    labels.push_back("face" + std::to_string(m));
  mocap::Take take(labels, kFrames, rate);
  // Rest shape: an 8 × 5 grid 22 mm apart, jittered by ±4 mm, on a curved face patch.
  Eigen::Matrix3Xd rest(3, kMarkers);
  for (Eigen::Index m = 0; m < kMarkers; ++m) {
    const double x = 22.0 * static_cast<double>(m % 8 - 4) + 8.0 * (random.uniform() - 0.5);
    const double y = 22.0 * static_cast<double>(m / 8 - 2) + 8.0 * (random.uniform() - 0.5);
    rest.col(m) = Eigen::Vector3d(x, y, 60.0 - 0.004 * x * x - 0.003 * y * y);
  }
  std::vector<double> phase(kMarkers + 4);
  for (auto& p : phase)
    p = 6.283 * random.uniform();
  for (Eigen::Index f = 0; f < kFrames; ++f) {
    const double t = static_cast<double>(f) / rate;
    const Eigen::Matrix3d head = (Eigen::AngleAxisd(0.25 * std::sin(0.3 * t + phase[0]), Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(0.1 * std::sin(0.5 * t + phase[1]), Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix();
    const Eigen::Vector3d shift(40.0 * std::sin(0.2 * t + phase[2]), 20.0 * std::sin(0.35 * t + phase[3]), 1000.0);
    for (Eigen::Index m = 0; m < kMarkers; ++m) {
      const double a = std::sin(1.1 * t + phase[static_cast<std::size_t>(4 + m)]);
      const Eigen::Vector3d local = rest.col(m) + Eigen::Vector3d(0.0, 3.0 * a, 1.5 * a);
      take.setPosition(f, m, head * local + shift);
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.5;
    }
  }
  const auto target = static_cast<Eigen::Index>(0.02 * static_cast<double>(kFrames * kMarkers));
  for (Eigen::Index hidden = 0; hidden < target;) {
    const auto m = random.below(kMarkers);
    const auto length = 3 + random.below(Eigen::Index{28});
    const auto start = random.below(kFrames - length);
    for (Eigen::Index f = start; f < start + length; ++f) {
      hidden += take.isValid(f, m) ? 1 : 0;
      take.valid()(f, m) = false;
    }
  }
  return take;
}

struct Fixture
{
  mocap::Take truth = syntheticTake();
  mocap::UnlabelledCopy copy = mocap::makeUnlabelledCopy(truth, options());
  mocap::MarkerSet set = mocap::markerSetFromTake(truth);
  mocap::PointCloud cloud = mocap::pointCloudFromTake(copy.take, allMarkers(copy.take));

  static mocap::TrackingEvaluationOptions options()
  {
    mocap::TrackingEvaluationOptions o;
    o.meanFragmentLength = 300;
    o.maxCutGap = 5;
    return o;
  }
  static std::vector<Eigen::Index> allMarkers(const mocap::Take& take)
  {
    std::vector<Eigen::Index> markers(static_cast<std::size_t>(take.markerCount()));
    for (std::size_t i = 0; i < markers.size(); ++i)
      markers[i] = static_cast<Eigen::Index>(i);
    return markers;
  }
};

const Fixture& fixture()
{
  static const Fixture instance;
  return instance;
}

void BM_TrackAndLabel(benchmark::State& state)
{
  const Fixture& data = fixture();
  double recovered = 0.0;
  for (auto _ : state) {
    mocap::Take labelled = mocap::trackTake(data.copy.take, &data.set);
    benchmark::DoNotOptimize(labelled.positionData());
    state.PauseTiming();
    recovered = mocap::labelAgreement(data.truth, labelled, data.copy.kept);
    state.ResumeTiming();
  }
  state.counters["recovered"] = recovered;
  state.counters["fragments"] = static_cast<double>(data.copy.fragments);
}
BENCHMARK(BM_TrackAndLabel)->Unit(benchmark::kMillisecond);

void BM_TrackHungarian(benchmark::State& state)
{
  const Fixture& data = fixture();
  std::size_t fragments = 0;
  for (auto _ : state) {
    const mocap::TrackingResult result = mocap::trackPoints(data.cloud);
    fragments = result.fragments.size();
    benchmark::DoNotOptimize(fragments);
  }
  state.counters["fragments"] = static_cast<double>(fragments);
}
BENCHMARK(BM_TrackHungarian)->Unit(benchmark::kMillisecond);

// Reference: each frame, accept (track, point) pairs nearest first within the same gate.
std::size_t trackGreedy(const mocap::PointCloud& cloud, double gate)
{
  std::vector<mocap::Fragment> fragments;
  std::vector<std::size_t> live;
  std::vector<std::size_t> next;
  std::vector<std::tuple<double, Eigen::Index, Eigen::Index>> pairs;
  for (Eigen::Index f = 0; f < cloud.frameCount(); ++f) {
    pairs.clear();
    for (std::size_t t = 0; t < live.size(); ++t) {
      const auto& p = fragments[live[t]].positions;
      const Eigen::Vector3d predicted = p.size() >= 2 ? Eigen::Vector3d(2.0 * p.back() - p[p.size() - 2]) : p.back();
      for (Eigen::Index i = 0; i < cloud.pointCount(f); ++i) {
        const double d = (cloud.point(f, i) - predicted).squaredNorm();
        if (d <= gate * gate)
          pairs.emplace_back(d, static_cast<Eigen::Index>(t), i);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> trackUsed(live.size(), false);
    std::vector<bool> pointUsed(static_cast<std::size_t>(cloud.pointCount(f)), false);
    next.clear();
    for (const auto& [d, t, i] : pairs) {
      if (trackUsed[static_cast<std::size_t>(t)] || pointUsed[static_cast<std::size_t>(i)])
        continue;
      trackUsed[static_cast<std::size_t>(t)] = pointUsed[static_cast<std::size_t>(i)] = true;
      fragments[live[static_cast<std::size_t>(t)]].positions.push_back(cloud.point(f, i));
      next.push_back(live[static_cast<std::size_t>(t)]);
    }
    for (Eigen::Index i = 0; i < cloud.pointCount(f); ++i) {
      if (pointUsed[static_cast<std::size_t>(i)])
        continue;
      next.push_back(fragments.size());
      fragments.push_back({f, {cloud.point(f, i)}});
    }
    live.swap(next);
  }
  return fragments.size();
}

void BM_TrackGreedy(benchmark::State& state)
{
  const Fixture& data = fixture();
  const double gate = mocap::automaticGate(data.cloud);
  std::size_t fragments = 0;
  for (auto _ : state) {
    fragments = trackGreedy(data.cloud, gate);
    benchmark::DoNotOptimize(fragments);
  }
  state.counters["fragments"] = static_cast<double>(fragments);
}
BENCHMARK(BM_TrackGreedy)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
