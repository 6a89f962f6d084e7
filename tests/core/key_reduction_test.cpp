#include "mocap/math/key_reduction.h"

#include "nose_mocap_fixture.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <set>

namespace mocap {
namespace {

Eigen::VectorXd framesAt(Eigen::Index count, double rate)
{
  return Eigen::VectorXd::LinSpaced(count, 0.0, static_cast<double>(count - 1) / rate);
}

/// Ramer–Douglas–Peucker on time and value, per the usual vertical-distance variant: keep the
/// ends, split at the sample farthest from their line while it is beyond the tolerance. The method
/// reduceKeys is measured against.
std::vector<Eigen::Index> douglasPeucker(const Eigen::VectorXd& times, const Eigen::MatrixXd& values, double tolerance)
{
  std::set<Eigen::Index> keys = {0, values.rows() - 1};
  const std::function<void(Eigen::Index, Eigen::Index)> split = [&](Eigen::Index a, Eigen::Index b) {
    double worst = 0.0;
    Eigen::Index at = -1;
    for (Eigen::Index k = a + 1; k < b; ++k) {
      const double t = (times(k) - times(a)) / (times(b) - times(a));
      const double error = ((1.0 - t) * values.row(a) + t * values.row(b) - values.row(k)).cwiseAbs().maxCoeff();
      if (error > worst)
        worst = error, at = k;
    }
    if (worst > tolerance) {
      keys.insert(at);
      split(a, at);
      split(at, b);
    }
  };
  split(0, values.rows() - 1);
  return {keys.begin(), keys.end()};
}

/// The fewest keys by trying every step (O(n³)): the optimum reduceKeys must reach, held runs
/// aside (the curves it is used on have none).
std::size_t fewestKeysByBruteForce(const Eigen::VectorXd& times, const Eigen::MatrixXd& values, double tolerance)
{
  const Eigen::Index n = values.rows();
  std::vector<std::size_t> best(static_cast<std::size_t>(n), static_cast<std::size_t>(n) + 1);
  best[0] = 1;
  for (Eigen::Index j = 1; j < n; ++j)
    for (Eigen::Index i = 0; i < j; ++i)
      if (keyInterpolationError(times.segment(i, j - i + 1), values.middleRows(i, j - i + 1), {0, j - i}) <=
          tolerance)
        best[static_cast<std::size_t>(j)] = std::min(best[static_cast<std::size_t>(j)], best[static_cast<std::size_t>(i)] + 1);
  return best.back();
}

/// Marker `m` of NoseMoCap as three channels (x, y, z in mm) over its first `frames` frames.
Eigen::MatrixXd noseMarker(Eigen::Index m, Eigen::Index frames)
{
  const Take& take = test::noseMoCapTake();
  Eigen::MatrixXd xyz(frames, 3);
  for (Eigen::Index f = 0; f < frames; ++f)
    xyz.row(f) = take.position(f, m).transpose();
  return xyz;
}

TEST(KeyReduction, AStraightLineNeedsItsEndsOnly)
{
  const Eigen::VectorXd times = framesAt(100, 100.0);
  const Eigen::MatrixXd values = 3.0 * times.array() - 1.0;
  const KeyReduction reduced = reduceKeys(times, values, 1e-6);
  EXPECT_EQ(reduced.keys, (std::vector<Eigen::Index>{0, 99}));
  EXPECT_LT(reduced.maxError, 1e-9);
}

TEST(KeyReduction, ZeroToleranceKeepsEveryDistinctValueAndTheEndsOfHolds)
{
  const Eigen::VectorXd times = framesAt(9, 30.0);
  Eigen::MatrixXd values(9, 1);
  values << 0.0, 0.5, 1.0, 1.0, 1.0, 1.0, 2.0, 2.5, 3.0;  // a ramp, a hold of four, a ramp
  const KeyReduction reduced = reduceKeys(times, values, 0.0);
  EXPECT_EQ(reduced.keys, (std::vector<Eigen::Index>{0, 1, 2, 5, 6, 7, 8})) << "only the inside of the hold goes";
  EXPECT_EQ(reduced.maxError, 0.0);
}

TEST(KeyReduction, AHoldKeepsItsFirstAndLastKeyWhateverTheTolerance)
{
  const Eigen::VectorXd times = framesAt(8, 30.0);
  Eigen::MatrixXd values(8, 1);
  values << 0.0, 0.1, 0.2, 0.2, 0.2, 0.2, 0.3, 0.4;
  const KeyReduction reduced = reduceKeys(times, values, 10.0);
  EXPECT_EQ(reduced.keys, (std::vector<Eigen::Index>{0, 2, 5, 7}));
}

TEST(KeyReduction, ChannelsShareTheKeysAndEachStaysWithinTheTolerance)
{
  const Eigen::VectorXd times = framesAt(200, 100.0);
  Eigen::MatrixXd values(200, 2);
  values.col(0) = times.array() * 2.0;                 // a line: alone, two keys
  values.col(1) = (times.array() * 7.0).sin() * 0.5;   // a wave: many
  const KeyReduction line = reduceKeys(times, values.col(0), 0.01);
  const KeyReduction both = reduceKeys(times, values, 0.01);
  EXPECT_EQ(line.keys.size(), 2u);
  EXPECT_GT(both.keys.size(), 10u);
  EXPECT_LE(both.maxError, 0.01);
  EXPECT_EQ(both.maxError, keyInterpolationError(times, values, both.keys));
}

TEST(KeyReduction, ReachesTheFewestKeysOnNoisyCurves)
{
  Random random(7);
  for (int trial = 0; trial < 8; ++trial) {
    const Eigen::VectorXd times = framesAt(40, 60.0);
    Eigen::MatrixXd values(40, 1);
    double walk = 0.0;
    for (Eigen::Index f = 0; f < 40; ++f)
      values(f, 0) = walk += random.normal();
    for (const double tolerance : {0.3, 1.0, 3.0}) {
      const KeyReduction reduced = reduceKeys(times, values, tolerance);
      EXPECT_EQ(reduced.keys.size(), fewestKeysByBruteForce(times, values, tolerance))
          << "trial " << trial << ", tolerance " << tolerance;
      EXPECT_LE(reduced.maxError, tolerance);
    }
  }
}

TEST(KeyReduction, HoldsTheBoundOnARealTakeWithFewerKeysThanDouglasPeucker)
{
  const Eigen::VectorXd times = framesAt(900, 60.0);
  std::size_t ours = 0, peucker = 0;
  for (const Eigen::Index marker : {0, 12, 28, 36}) {
    const Eigen::MatrixXd xyz = noseMarker(marker, 900);
    ASSERT_TRUE(xyz.allFinite()) << "marker " << marker << " has a gap in its first 900 frames";
    for (const double tolerance : {0.05, 0.2, 1.0}) {  // mm
      const KeyReduction reduced = reduceKeys(times, xyz, tolerance);
      EXPECT_LE(reduced.maxError, tolerance) << "marker " << marker;
      EXPECT_LT(reduced.keys.size(), 900u);
      const std::vector<Eigen::Index> reference = douglasPeucker(times, xyz, tolerance);
      EXPECT_LE(keyInterpolationError(times, xyz, reference), tolerance);
      EXPECT_LE(reduced.keys.size(), reference.size()) << "marker " << marker << ", tolerance " << tolerance;
      ours += reduced.keys.size();
      peucker += reference.size();
    }
  }
  EXPECT_LT(ours, peucker) << "fewer keys in all than Ramer–Douglas–Peucker";
  std::cout << "[ key counts ] NoseMoCap, 4 markers × 3 tolerances: " << ours << " keys, Ramer–Douglas–Peucker "
            << peucker << ", of " << 12 * 900 << " samples\n";
}

TEST(KeyReduction, BadInputIsAClearError)
{
  const Eigen::VectorXd times = framesAt(5, 30.0);
  const Eigen::MatrixXd values = Eigen::MatrixXd::Zero(5, 2);
  EXPECT_THROW((void)reduceKeys(times, values, -1.0), InvalidArgument);
  EXPECT_THROW((void)reduceKeys(times, values, std::nan("")), InvalidArgument);
  EXPECT_THROW((void)reduceKeys(times.head(4), values, 0.1), InvalidArgument);
  Eigen::MatrixXd gap = values;
  gap(2, 1) = std::nan("");
  EXPECT_THROW((void)reduceKeys(times, gap, 0.1), InvalidArgument);
  Eigen::VectorXd backwards = times;
  backwards(3) = backwards(1);
  EXPECT_THROW((void)reduceKeys(backwards, values, 0.1), InvalidArgument);
  EXPECT_TRUE(reduceKeys(Eigen::VectorXd(0), Eigen::MatrixXd(0, 2), 0.1).keys.empty());
  EXPECT_EQ(reduceKeys(times.head(1), values.topRows(1), 0.1).keys, (std::vector<Eigen::Index>{0}));
}

} // namespace
} // namespace mocap
