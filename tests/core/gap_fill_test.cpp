#include "mocap/base/error.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/cleaning/fill/neighbour_propagation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace mocap {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Hides frames [first, first + length) of `marker`; the hidden positions become NaN so a method
// that read them would show it.
void hide(Take& take, Eigen::Index marker, Eigen::Index first, Eigen::Index length)
{
  for (Eigen::Index f = first; f < first + length; ++f) {
    take.valid()(f, marker) = false;
    take.residuals()(f, marker) = -1.0;
    take.setPosition(f, marker, Eigen::Vector3d::Constant(kNan));
  }
}

Take allValid(std::vector<std::string> labels, Eigen::Index frames)
{
  Take take(std::move(labels), frames, 100.0);
  take.valid().setConstant(true);
  take.residuals().setZero();
  return take;
}

// Six markers of a rigid body turning and travelling over 80 frames.
Take rigidCluster()
{
  Take take = allValid({"a", "b", "c", "d", "e", "f"}, 80);
  const Eigen::Matrix<double, 6, 3> shape =
      (Eigen::Matrix<double, 6, 3>() << 0, 0, 0, 30, 5, 2, -10, 40, 8, 25, 35, -6, 5, -30, 12, -35, 10, 4)
          .finished();
  for (Eigen::Index f = 0; f < 80; ++f) {
    const double t = 0.05 * static_cast<double>(f);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() =
        Eigen::AngleAxisd(1.2 * std::sin(t), Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
    pose.translation() = Eigen::Vector3d(50 * t, 10 * std::cos(2 * t), 900 + 5 * t * t);
    for (Eigen::Index m = 0; m < 6; ++m)
      take.setPosition(f, m, pose * Eigen::Vector3d(shape.row(m).transpose()));
  }
  return take;
}

// The one patch of a fill (by value: the result is a temporary).
SamplePatch onlyPatch(const FillResult& result)
{
  EXPECT_EQ(result.patches.size(), 1u);
  return result.patches.empty() ? SamplePatch{} : result.patches.front();
}

TEST(GapFill, MethodNamesRoundTrip)
{
  EXPECT_EQ(allFillMethods().size(), 9u);
  for (const FillMethod method : allFillMethods())
    EXPECT_EQ(parseFillMethod(fillMethodName(method)), method);
  EXPECT_EQ(parseFillMethod("lin-ouhyoung"), FillMethod::LinOuhyoung);
  EXPECT_EQ(parseFillMethod("zhang-n"), FillMethod::ZhangN);
  EXPECT_FALSE(parseFillMethod("Auto"));
  EXPECT_FALSE(parseFillMethod(""));
  EXPECT_FALSE(parseFillMethod("cubic"));
  EXPECT_EQ(FillOptions{}.method, FillMethod::Auto);
}

TEST(GapFill, RigidFillsARigidlyMovingClusterExactly)
{
  const Take truth = rigidCluster();
  for (const auto& [first, length] : {std::pair<Eigen::Index, Eigen::Index>{20, 35}, {0, 15}, {60, 20}}) {
    Take take = truth;
    hide(take, 0, first, length);
    FillOptions options{FillMethod::Rigid, 0, 4};
    options.extrapolate = true;  // {0, 15} is an edge gap
    const FillResult result = fillGaps(take, options);
    ASSERT_TRUE(result.gaps.front().filled) << result.gaps.front().reason;
    const SamplePatch patch = onlyPatch(result);
    for (Eigen::Index i = 0; i < length; ++i)
      EXPECT_LT((patch.positions.row(i).transpose() - truth.position(first + i, 0)).norm(), 1e-9)
          << first + i;
  }
}

TEST(GapFill, AutoFollowsARigidClusterToo)
{
  const Take truth = rigidCluster();
  Take take = truth;
  hide(take, 2, 30, 20);
  const SamplePatch patch = onlyPatch(fillGaps(take, {}));
  for (Eigen::Index i = 0; i < 20; ++i)
    EXPECT_LT((patch.positions.row(i).transpose() - truth.position(30 + i, 2)).norm(), 1e-6);
}

// Eqs 3-5 by hand. Frame 0: M (0,0,0), A (1,0,0), B (0,2,0), C (0,0,3), far D (10,10,10).
// Frame 1: M missing; A, B, C move by V = (1,0,0), (0,1,0), (0,0,1); D by (5,5,5).
// The three nearest are A, B, C: d = 1, 2, 3; d_all = 6 (eq 3).
// Eq 4: ω_A = [(1 + cos(π/6))/2]⁴ = (97 + 56√3)/256 ≈ 0.7577924, ω_B = [(1 + cos(π/3))/2]⁴ =
// 0.75⁴ = 0.31640625, ω_C = [(1 + cos(π/2))/2]⁴ = 0.0625.
// Eq 5: P' = (0,0,0) + Σ ωV = (0.7577924, 0.31640625, 0.0625); D plays no part.
TEST(GapFill, Zhang3MatchesEquations3To5ByHand)
{
  Take take = allValid({"M", "A", "B", "C", "D"}, 3);
  const Eigen::Vector3d start[] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {10, 10, 10}};
  const Eigen::Vector3d move[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  for (Eigen::Index m = 0; m < 5; ++m)
    for (Eigen::Index f = 0; f < 3; ++f)
      take.setPosition(f, m, start[m] + static_cast<double>(f) * move[m]);
  hide(take, 0, 1, 1);
  const SamplePatch patch = onlyPatch(fillGaps(take, {FillMethod::Zhang3, 0, 6}));
  const double wA = (97.0 + 56.0 * std::sqrt(3.0)) / 256.0;
  EXPECT_NEAR(patch.positions(0, 0), wA, 1e-12);
  EXPECT_NEAR(patch.positions(0, 1), 0.31640625, 1e-12);
  EXPECT_NEAR(patch.positions(0, 2), 0.0625, 1e-12);

  // Eqs 6-7 with n = 3 on the same frame: ω = cos((d − 1)/(3 − 1) · π/2.5) = 1, cos(π/5),
  // cos(2π/5); P' = Σ ωV / Σ ω.
  const double w2 = std::cos(3.14159265358979323846 / 5.0);
  const double w3 = std::cos(2.0 * 3.14159265358979323846 / 5.0);
  const SamplePatch n3 = onlyPatch(fillGaps(take, {FillMethod::ZhangN, 0, 3}));
  EXPECT_NEAR(n3.positions(0, 0), 1.0 / (1.0 + w2 + w3), 1e-12);
  EXPECT_NEAR(n3.positions(0, 1), w2 / (1.0 + w2 + w3), 1e-12);
  EXPECT_NEAR(n3.positions(0, 2), w3 / (1.0 + w2 + w3), 1e-12);
  // Guenter [2]: the plain average; Lin & Ouhyoung [1]: weights 1/d normalised (6/11, 3/11, 2/11).
  const SamplePatch guenter = onlyPatch(fillGaps(take, {FillMethod::Guenter, 0, 3}));
  EXPECT_LT((guenter.positions.row(0) - Eigen::RowVector3d::Constant(1.0 / 3.0)).norm(), 1e-12);
  const SamplePatch lin = onlyPatch(fillGaps(take, {FillMethod::LinOuhyoung, 0, 3}));
  EXPECT_LT((lin.positions.row(0) - Eigen::RowVector3d(6.0, 3.0, 2.0) / 11.0).norm(), 1e-12);
}

TEST(GapFill, WeightFormulas)
{
  EXPECT_NEAR(zhang3Weights({1, 2, 3})(0), (97.0 + 56.0 * std::sqrt(3.0)) / 256.0, 1e-15);
  EXPECT_TRUE(zhang3Weights({0, 0, 0}).isApprox(Eigen::Vector3d::Constant(0.31640625)));
  EXPECT_TRUE(zhangNWeights(Eigen::Vector2d(4, 4)).isApprox(Eigen::Vector2d::Ones()));
  EXPECT_TRUE(linOuhyoungWeights(Eigen::Vector3d(0, 1, 0)).isApprox(Eigen::Vector3d(0.5, 0, 0.5)));
}

TEST(GapFill, Zhang3UsesTheRecoveredPositionInsideTheGap)
{
  // Everything translates by (1, 2, 3) per frame: each step adds Σω·(1, 2, 3), with ω from the
  // distances to the recovered position, which stay those of frame 0.
  Take take = allValid({"M", "A", "B", "C"}, 6);
  const Eigen::Vector3d start[] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  for (Eigen::Index m = 0; m < 4; ++m)
    for (Eigen::Index f = 0; f < 6; ++f)
      take.setPosition(f, m, start[m] + static_cast<double>(f) * Eigen::Vector3d(1, 2, 3));
  hide(take, 0, 1, 4);
  const SamplePatch patch = onlyPatch(fillGaps(take, {FillMethod::Zhang3, 0, 6}));
  const double sum = zhang3Weights({1, 2, 3}).sum();  // ≈ 1.137: eq 4's weights only sum to about 1
  EXPECT_LT((patch.positions.row(0) - sum * Eigen::RowVector3d(1, 2, 3)).norm(), 1e-12);
  for (Eigen::Index i = 1; i < 4; ++i) {
    // Later steps add Σω'·V with ω' from the distances to the recovered position.
    const Eigen::RowVector3d step = patch.positions.row(i) - patch.positions.row(i - 1);
    EXPECT_LT((step.normalized() - Eigen::RowVector3d(1, 2, 3).normalized()).norm(), 1e-12);
    EXPECT_GT((step - sum * Eigen::RowVector3d(1, 2, 3)).norm(), 1e-6);  // the distances did change
  }
}

TEST(GapFill, LinearIsExactOnLinesAndSplineOnCubics)
{
  Take take = allValid({"line", "cubic"}, 60);
  for (Eigen::Index f = 0; f < 60; ++f) {
    const auto t = static_cast<double>(f);
    take.setPosition(f, 0, Eigen::Vector3d(2 * t - 5, 0.5 * t, 7));
    take.setPosition(f, 1,
                     Eigen::Vector3d(1e-3 * t * t * t - 0.1 * t * t + t, 3 - 2e-3 * t * t * t, 0.05 * t * t));
  }
  const Take truth = take;
  hide(take, 0, 20, 17);
  hide(take, 1, 25, 21);
  const FillResult linear = fillGaps(take, {FillMethod::Linear, 0, 6});
  ASSERT_TRUE(linear.gaps[0].filled);
  for (Eigen::Index i = 0; i < 17; ++i)
    EXPECT_LT((linear.patches[0].positions.row(i).transpose() - truth.position(20 + i, 0)).norm(), 1e-12);
  const FillResult spline = fillGaps(take, {FillMethod::Spline, 0, 6});
  ASSERT_TRUE(spline.gaps[1].filled);
  for (Eigen::Index i = 0; i < 21; ++i)
    EXPECT_LT((spline.patches[1].positions.row(i).transpose() - truth.position(25 + i, 1)).norm(), 1e-9);
}

// FillOptions that fill whatever the method can: every length, the edges, every marker.
FillOptions everything(FillMethod method)
{
  FillOptions options{method, 0, 6};
  options.maxGapSeconds = 0.0;
  options.extrapolate = true;
  options.minValidFraction = 0.0;
  return options;
}

// A smooth wave per marker, all valid, at 100 Hz (for gaps long enough to matter).
Take wavingMarkers(Eigen::Index frames)
{
  Take take = allValid({"a", "b", "c", "d", "e", "f"}, frames);
  for (Eigen::Index f = 0; f < frames; ++f)
    for (Eigen::Index m = 0; m < 6; ++m) {
      const double t = 0.01 * static_cast<double>(f);
      const auto k = static_cast<double>(m);
      take.setPosition(f, m, Eigen::Vector3d(20 * k + 5 * std::sin(2 * t + k), 10 * std::cos(1.3 * t), 3 * k + t));
    }
  return take;
}

TEST(GapFill, DefaultsLeaveGapsLongerThanHalfASecondOpen)
{
  Take take = wavingMarkers(400);
  hide(take, 0, 100, 100);  // 1 s at 100 Hz
  hide(take, 1, 100, 40);   // 0.4 s
  EXPECT_EQ(longestGapFrames(FillOptions{}, 100.0), 50);
  EXPECT_EQ(longestGapFrames(FillOptions{}, 60.0), 30);
  const FillResult defaults = fillGaps(take, FillOptions{});
  ASSERT_EQ(defaults.gaps.size(), 2u);
  EXPECT_FALSE(defaults.gaps[0].filled);
  EXPECT_EQ(defaults.gaps[0].cause, UnfilledCause::TooLong);
  EXPECT_NE(defaults.gaps[0].reason.find("50 frames, 0.5 s"), std::string::npos) << defaults.gaps[0].reason;
  EXPECT_TRUE(defaults.gaps[1].filled) << defaults.gaps[1].reason;
  EXPECT_EQ(defaults.gaps[1].cause, UnfilledCause::None);
  FillOptions unlimited;
  unlimited.maxGapSeconds = 0.0;
  EXPECT_EQ(longestGapFrames(unlimited, 100.0), 0);
  const FillResult all = fillGaps(take, unlimited);
  EXPECT_TRUE(all.gaps[0].filled) << all.gaps[0].reason;
  EXPECT_EQ(all.patches.size(), 2u);
  FillOptions frames;
  frames.maxGap = 120;  // an explicit frame count wins over the seconds
  EXPECT_EQ(longestGapFrames(frames, 100.0), 120);
  EXPECT_TRUE(fillGaps(take, frames).gaps[0].filled);
  frames.maxGap = 30;
  EXPECT_FALSE(fillGaps(take, frames).gaps[1].filled);
}

TEST(GapFill, EdgeGapsAreLeftOpenUnlessExtrapolating)
{
  Take take = rigidCluster();
  hide(take, 0, 0, 8);
  hide(take, 1, 70, 10);
  hide(take, 2, 30, 8);
  const FillResult defaults = fillGaps(take, FillOptions{});
  ASSERT_EQ(defaults.gaps.size(), 3u);
  for (const GapFillReport& report : defaults.gaps)
    if (report.gap.atEdge) {
      EXPECT_FALSE(report.filled);
      EXPECT_EQ(report.cause, UnfilledCause::EdgeGap);
      EXPECT_EQ(report.reason, "edge gap (extrapolation off)");
    } else {
      EXPECT_TRUE(report.filled) << report.reason;
    }
  EXPECT_EQ(defaults.patches.size(), 1u);
  FillOptions extrapolate;
  extrapolate.extrapolate = true;
  const FillResult all = fillGaps(take, extrapolate);
  for (const GapFillReport& report : all.gaps)
    EXPECT_TRUE(report.filled) << report.reason;
}

TEST(GapFill, RarelySeenMarkersAreSkippedUnlessNamed)
{
  Take take = wavingMarkers(200);
  hide(take, 3, 0, 20);
  hide(take, 3, 50, 150);  // 30 of 200 frames valid: 15 %
  hide(take, 4, 60, 20);   // 90 % valid
  const FillResult defaults = fillGaps(take, FillOptions{});
  ASSERT_EQ(defaults.gaps.size(), 3u);
  EXPECT_EQ(defaults.gaps[0].cause, UnfilledCause::RarelyValid);
  EXPECT_EQ(defaults.gaps[1].cause, UnfilledCause::RarelyValid);
  EXPECT_NE(defaults.gaps[0].reason.find("15 %"), std::string::npos) << defaults.gaps[0].reason;
  EXPECT_TRUE(defaults.gaps[2].filled) << defaults.gaps[2].reason;
  FillOptions named;
  named.fillAnyway = {3};
  named.extrapolate = true;
  named.maxGapSeconds = 0.0;
  const FillResult anyway = fillGaps(take, named);
  EXPECT_TRUE(anyway.gaps[0].filled) << anyway.gaps[0].reason;
  EXPECT_NE(anyway.gaps[1].cause, UnfilledCause::RarelyValid) << anyway.gaps[1].reason;  // judged by the method
  FillOptions lower;
  lower.minValidFraction = 0.1;
  EXPECT_NE(fillGaps(take, lower).gaps[0].cause, UnfilledCause::RarelyValid);
  EXPECT_EQ(unfilledCauseName(UnfilledCause::RarelyValid), "rarely_valid");
  EXPECT_EQ(unfilledCauseName(UnfilledCause::EdgeGap), "edge_gap");
  named.fillAnyway = {6};
  EXPECT_THROW((void)fillGaps(take, named), InvalidArgument);
  FillOptions bad;
  bad.minValidFraction = 1.5;
  EXPECT_THROW((void)fillGaps(take, bad), InvalidArgument);
  bad = FillOptions{};
  bad.maxGapSeconds = -1.0;
  EXPECT_THROW((void)fillGaps(take, bad), InvalidArgument);
}

// The rules alone (what the studio's Gaps dock shows before any fill) say of each gap exactly
// what a fill reports for the gaps it leaves open by rule, and nothing for the others.
TEST(GapFill, CheckFillRulesIsWhatAFillLeavesOpenByRule)
{
  Take take = wavingMarkers(400);
  hide(take, 0, 100, 100);  // too long
  hide(take, 1, 0, 10);     // at the start
  hide(take, 2, 0, 150);
  hide(take, 2, 170, 230);  // 20 of 400 frames seen: rarely valid
  hide(take, 3, 200, 20);   // fillable
  const std::vector<Gap> gaps = findGaps(take);
  const std::vector<GapFillReport> rules = checkFillRules(take, gaps, FillOptions{});
  const FillResult filled = fillGaps(take, gaps, FillOptions{});
  ASSERT_EQ(rules.size(), gaps.size());
  int refused = 0;
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    EXPECT_EQ(rules[i].gap.marker, gaps[i].marker);
    EXPECT_FALSE(rules[i].filled);
    if (rules[i].cause == UnfilledCause::None) {
      EXPECT_TRUE(filled.gaps[i].filled) << filled.gaps[i].reason;
      continue;
    }
    ++refused;
    EXPECT_EQ(filled.gaps[i].cause, rules[i].cause);
    EXPECT_EQ(filled.gaps[i].reason, rules[i].reason);
  }
  EXPECT_EQ(refused, 4);  // marker 0's, marker 1's and marker 2's two
  EXPECT_EQ(rules[0].cause, UnfilledCause::TooLong);
  EXPECT_EQ(rules[1].cause, UnfilledCause::EdgeGap);
  EXPECT_EQ(rules[2].cause, UnfilledCause::RarelyValid);
  FillOptions lax;
  lax.maxGapSeconds = 0.0;
  lax.extrapolate = true;
  lax.minValidFraction = 0.0;
  for (const GapFillReport& report : checkFillRules(take, gaps, lax))
    EXPECT_EQ(report.cause, UnfilledCause::None);
  const std::vector<Gap> outside{Gap{0, 395, 10, true}};
  EXPECT_THROW((void)checkFillRules(take, outside, FillOptions{}), InvalidArgument) << "outside the take";
}

TEST(GapFill, MaxGapIsRespected)
{
  Take take = rigidCluster();
  hide(take, 0, 10, 5);
  hide(take, 0, 30, 20);
  for (const FillMethod method : allFillMethods()) {
    const FillResult result = fillGaps(take, {method, 10, 6});
    ASSERT_EQ(result.gaps.size(), 2u);
    EXPECT_TRUE(result.gaps[0].filled) << fillMethodName(method) << ": " << result.gaps[0].reason;
    EXPECT_FALSE(result.gaps[1].filled);
    EXPECT_NE(result.gaps[1].reason.find("longer"), std::string::npos);
    EXPECT_EQ(result.patches.size(), 1u);
  }
}

TEST(GapFill, EdgeGapsAreExtrapolatedOnlyByMethodsThatCan)
{
  Take take = rigidCluster();
  hide(take, 0, 0, 8);
  hide(take, 1, 70, 10);
  for (const FillMethod method : allFillMethods()) {
    FillOptions options{method, 0, 6};
    options.extrapolate = true;
    const FillResult result = fillGaps(take, options);
    ASSERT_EQ(result.gaps.size(), 2u);
    const bool interpolates = method == FillMethod::Linear || method == FillMethod::Spline;
    for (const GapFillReport& report : result.gaps) {
      EXPECT_TRUE(report.gap.atEdge);
      EXPECT_EQ(report.filled, !interpolates) << fillMethodName(method) << ": " << report.reason;
      EXPECT_FALSE(report.filled ? report.method.empty() : report.reason.empty());
    }
    for (const SamplePatch& patch : result.patches)
      EXPECT_TRUE(patch.positions.allFinite());
  }
}

TEST(GapFill, AMarkerMissingEverywhereIsReportedNotInvented)
{
  Take take = rigidCluster();
  hide(take, 3, 0, 80);
  for (const FillMethod method : allFillMethods()) {
    const FillResult result = fillGaps(take, {method, 0, 6});
    ASSERT_EQ(result.gaps.size(), 1u);
    EXPECT_FALSE(result.gaps[0].filled) << fillMethodName(method);
    EXPECT_FALSE(result.gaps[0].reason.empty());
    EXPECT_TRUE(result.patches.empty());
  }
}

TEST(GapFill, FilledSamplesAreMarkedAndOtherInvalidSamplesUntouched)
{
  Take take = rigidCluster();
  hide(take, 0, 20, 10);
  hide(take, 1, 25, 10);
  hide(take, 2, 40, 30);  // longer than maxGap: stays a gap
  const Take before = take;
  for (const FillMethod method : allFillMethods()) {
    Take filled = before;
    const FillResult result = fillGaps(filled, {method, 12, 6});
    for (const SamplePatch& patch : result.patches) {
      EXPECT_NE(patch.marker, 2);
      for (const SampleState state : patch.states)
        EXPECT_EQ(state, SampleOrigin::Filled);
    }
    (void)applyPatches(filled, result.patches);
    for (Eigen::Index m = 0; m < 6; ++m)
      for (Eigen::Index f = 0; f < 80; ++f) {
        const bool inGap = (m == 0 && f >= 20 && f < 30) || (m == 1 && f >= 25 && f < 35);
        if (inGap) {
          EXPECT_TRUE(filled.isValid(f, m));
          EXPECT_EQ(filled.state(f, m), SampleOrigin::Filled);
          EXPECT_EQ(filled.residuals()(f, m), 0.0);
          EXPECT_TRUE(filled.position(f, m).allFinite());
        } else {
          EXPECT_EQ(filled.isValid(f, m), before.isValid(f, m));
          EXPECT_EQ(filled.state(f, m), before.state(f, m));
          const Eigen::Vector3d a = filled.position(f, m);
          const Eigen::Vector3d b = before.position(f, m);
          EXPECT_TRUE(a == b || (a.hasNaN() && b.hasNaN())) << fillMethodName(method) << " " << m << " " << f;
        }
      }
  }
}

TEST(GapFill, PcaRecoversSeveralMarkersMissingAtOnce)
{
  // Eight markers driven by two latent signals: an exactly low-rank take.
  Take take = allValid({"a", "b", "c", "d", "e", "f", "g", "h"}, 200);
  for (Eigen::Index f = 0; f < 200; ++f) {
    const double t = 0.07 * static_cast<double>(f);
    const double u = std::sin(t);
    const double v = std::cos(1.7 * t + 0.3);
    for (Eigen::Index m = 0; m < 8; ++m) {
      const auto k = static_cast<double>(m);
      take.setPosition(f, m, Eigen::Vector3d(10 * k + u * (1 + k), 5 * k - v * (2 - 0.2 * k), k * u + v));
    }
  }
  const Take truth = take;
  hide(take, 1, 50, 40);
  hide(take, 4, 60, 40);
  hide(take, 6, 70, 30);
  const FillResult result = fillGaps(take, {FillMethod::Pca, 0, 6});
  ASSERT_EQ(result.patches.size(), 3u);
  for (const SamplePatch& patch : result.patches)
    for (std::size_t i = 0; i < patch.frames.size(); ++i)
      EXPECT_LT((patch.positions.row(static_cast<Eigen::Index>(i)).transpose() -
                 truth.position(patch.frames[i], patch.marker))
                    .norm(),
                1e-6);
}

TEST(GapFill, BadInputIsRejected)
{
  Take take = rigidCluster();
  hide(take, 0, 10, 5);
  EXPECT_THROW((void)fillGaps(take, {FillMethod::Auto, -1, 6}), InvalidArgument);
  EXPECT_THROW((void)fillGaps(take, {FillMethod::Auto, 0, 0}), InvalidArgument);
  EXPECT_THROW((void)fillGaps(take, {FillMethod::Auto, 0, 100000}), InvalidArgument);
  EXPECT_THROW((void)fillGaps(take, {static_cast<FillMethod>(42), 0, 6}), InvalidArgument);
  Take broken = take;
  broken.setPosition(3, 2, Eigen::Vector3d(1, kNan, 2));  // a valid sample that is not a number
  EXPECT_THROW((void)fillGaps(broken, FillOptions{}), InvalidArgument);
  broken.setPosition(3, 2, Eigen::Vector3d(1, std::numeric_limits<double>::infinity(), 2));
  EXPECT_THROW((void)fillGaps(broken, FillOptions{}), InvalidArgument);
  // A "gap" of valid samples, or outside the take.
  EXPECT_THROW((void)fillGaps(take, std::vector<Gap>{{1, 10, 5, false}}, FillOptions{}), InvalidArgument);
  EXPECT_THROW((void)fillGaps(take, std::vector<Gap>{{0, 78, 5, false}}, FillOptions{}), InvalidArgument);
  EXPECT_THROW((void)fillGaps(take, std::vector<Gap>{{9, 10, 5, false}}, FillOptions{}), InvalidArgument);
  // Nothing to do is not an error.
  EXPECT_TRUE(fillGaps(Take(), FillOptions{}).gaps.empty());
  EXPECT_TRUE(fillGaps(rigidCluster(), FillOptions{}).gaps.empty());
  const Take single = [] {
    Take lonely({"only"}, 10, 100.0);
    lonely.valid().topRows(3).setConstant(true);
    return lonely;
  }();
  for (const FillMethod method : allFillMethods()) {
    const FillResult result = fillGaps(single, everything(method));
    ASSERT_EQ(result.gaps.size(), 1u);
    EXPECT_FALSE(result.gaps[0].filled) << fillMethodName(method);  // no neighbours, edge gap
  }
}

} // namespace
} // namespace mocap
