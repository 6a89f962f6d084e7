// The robust spike detector's noise scale: the local robust standard deviation of a residual,
// and its floor at run ends (spike_detection.h, step 3).

#include "spike_detector_parts.h"
#include "spike_lanes.h"
#include "median_networks.h"

#include <algorithm>
#include <array>

namespace mocap::spikes {

namespace {

// Median length of a 3-D vector of independent unit normals: turns a median residual length
// into a per-axis standard deviation.
constexpr double kMedianLengthPerSigma = 1.5382;

} // namespace

// Within 4 samples of a run end the prediction extrapolates, and in fast motion its error grows
// far beyond that of the interior samples the local scale comes from. So the same lopsided
// prediction is also made for the sample's (up to 8) inward neighbours, and the median of those
// residuals, at half weight, is a floor for its scale. Full weight leaves clean run ends alone in
// any motion but hides more real spikes next to gaps; half weight keeps fast swings of a few mm per
// frame unflagged while losing few spikes (measured on the takes named in the header).
void runEndSigma(const Trajectory& xyz, const Run& run, RobustWork& work)
{
  const Eigen::Index n = run.size();
  const Eigen::Index references = std::min<Eigen::Index>(kWindow - 1, n - kWindow);
  if (references < 1)
    return;
  std::array<double, kWindow - 1> residual{};
  for (Eigen::Index offset = 0; offset < kQuadraticHalfWidth; ++offset) {
    for (const bool atStart : {true, false}) {
      const Eigen::Index i = atStart ? run.first + offset : run.last - offset;
      for (Eigen::Index k = 1; k <= references; ++k) {
        const Eigen::Index j = atStart ? i + k : i - k;
        const Run w = atStart ? Run{run.first + k, run.first + k + kWindow - 1}
                              : Run{run.last - k - kWindow + 1, run.last - k};
        residual[static_cast<std::size_t>(k - 1)] = predictionResidual(xyz, run, j, w, work);
      }
      const double scale = kRunEndScaleWeight * smallMedian(residual.data(), residual.data() + references) /
                           kMedianLengthPerSigma;
      double& sigma = work.sigma(i - run.first);
      sigma = std::max(sigma, scale);
    }
  }
}

// The fixed floor (SpikeOptions::noiseFloor) is what a capture system resolves of a marker at rest.
// A moving marker is resolved less well, and stage 2's quadratic over 9 samples follows its motion
// only to within a share of the distance it moves per frame, a larger one where it extrapolates (a
// run's first and last 4 samples): on smooth takes, samples moving 5-10 mm per frame were flagged
// 0.3-1.7 mm off the fit, six or more floors but a small share of the motion. So the scale is also
// at least 3 % of the speed (4 % at run ends), measured as the chord of stage 2's window: a spike
// inside the window moves neither end, so it cannot raise its own floor. Measured (spikes: seeds
// 1-10 × 200): a take of 40 markers swinging 2-40 mm at 0.2-3 Hz with 0.01 mm noise had 3, 12, 1
// and 1 flags at 30, 60, 100 and 120 Hz, now none (3 % at run ends too left 1 at 30 and 60 Hz);
// NoseMoCap and CheeksMoCap are unchanged (16 and 2 flags, recall as before); Facial-Sing has 163
// flags instead of 198 (5 mm recall 99.34 % instead of 99.40 %), ART's filtered body 118 instead
// of 258, an OptiTrack skeleton 160 instead of 169. 4 % everywhere took Facial-Sing's 5 mm recall
// to 99.20 % and left too few 0.8 mm spikes in fast motion (InteriorFlagsDoNotDependOnWhereTheRunStarts).
void motionFloor(const Trajectory& xyz, const Run& run, RobustWork& work)
{
  for (Eigen::Index i = run.first; i <= run.last; ++i) {
    const bool atRunEnd = i < run.first + kQuadraticHalfWidth || i > run.last - kQuadraticHalfWidth;
    const Run w = windowAround(run, i, kQuadraticHalfWidth);
    const double speed = (xyz.row(w.last) - xyz.row(w.first)).norm() / static_cast<double>(w.size() - 1);
    double& sigma = work.sigma(i - run.first);
    sigma = std::max(sigma, (atRunEnd ? kRunEndMotionFloorShare : kMotionFloorShare) * speed);
  }
}

// Robust standard deviation around each sample: the median of `r` over 11 samples (shifted
// inward at the ends) divided by the median length of a 3-D unit normal vector, at least `floor`.
void localSigma(const Eigen::VectorXd& r, double floor, Eigen::VectorXd& sigma)
{
  constexpr Eigen::Index width = 2 * kScaleHalfWidth + 1;
  const auto toSigma = [floor](double median) { return std::max(floor, median / kMedianLengthPerSigma); };
  const Eigen::Index n = r.size();
  std::array<double, width> values{};
  if (n < width) {  // one window for the whole run
    std::copy(r.data(), r.data() + n, values.data());
    sigma.setConstant(n, toSigma(smallMedian(values.data(), values.data() + n)));
    return;
  }
  sigma.resize(n);
  Eigen::Index centre = kScaleHalfWidth;
  // Four windows at a time: the windows at c and c + 1 share 10 samples, so one middle pair of
  // those 10 gives both medians (medianWithMiddlePair), half the comparisons of two median11
  // networks. Lane 0 takes the windows at c, c + 1, lane 1 those at c + 2, c + 3.
  static_assert(kLanes == 2, "two pairs of windows");
  for (; centre + 3 < n - kScaleHalfWidth; centre += 4) {
    const double* x = r.data() + centre;
    std::array<Lanes, width - 1> shared;
    unrolled<width - 1>([&](auto k) {
      const auto at = static_cast<Eigen::Index>(k()) - (kScaleHalfWidth - 1);
      shared[k] = makeLanes(x[at], x[at + 2]);
    });
    middlePairOf10(shared.data());
    const Lanes left = medianWithMiddlePair(shared[4], shared[5], makeLanes(x[-kScaleHalfWidth], x[2 - kScaleHalfWidth]));
    const Lanes right =
        medianWithMiddlePair(shared[4], shared[5], makeLanes(x[1 + kScaleHalfWidth], x[3 + kScaleHalfWidth]));
    sigma(centre) = toSigma(lane(left, 0));
    sigma(centre + 1) = toSigma(lane(right, 0));
    sigma(centre + 2) = toSigma(lane(left, 1));
    sigma(centre + 3) = toSigma(lane(right, 1));
  }
  for (; centre + kLanes - 1 < n - kScaleHalfWidth; centre += kLanes) {
    // kLanes neighbouring windows at once, one per lane.
    const double* x = r.data() + centre - kScaleHalfWidth;
    std::array<Lanes, width> lanes;
    unrolled<width>([&](auto k) { lanes[k] = loadLanes(x + k); });
    const Lanes median = median11(lanes.data());
    for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); ++l)
      sigma(centre + static_cast<Eigen::Index>(l)) = toSigma(lane(median, l));
  }
  for (; centre < n - kScaleHalfWidth; ++centre) {
    std::copy(r.data() + centre - kScaleHalfWidth, r.data() + centre + kScaleHalfWidth + 1, values.data());
    sigma(centre) = toSigma(median11(values.data()));
  }
  sigma.head(kScaleHalfWidth).setConstant(sigma(kScaleHalfWidth));
  sigma.tail(kScaleHalfWidth).setConstant(sigma(n - 1 - kScaleHalfWidth));
}

} // namespace mocap::spikes
