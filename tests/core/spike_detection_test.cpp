#include "mocap/cleaning/spike_detection.h"

#include "mocap/io/c3d_reader.h"
#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/model/sample_patch.h"
#include "mocap/evaluation/spike_evaluation.h"
#include "mocap/io/trc_io.h"
#include "nose_mocap_fixture.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace mocap {
namespace {

using Frames = std::vector<Eigen::Index>;
using Xyz = Eigen::Matrix<double, Eigen::Dynamic, 3>;

SpikeOptions paper(double factor = 1.5)
{
  SpikeOptions options;
  options.method = SpikeMethod::Paper;
  options.factor = factor;
  return options;
}

SpikeOptions robust()
{
  return {};
}

ValidMask allValid(Eigen::Index frames)
{
  return ValidMask::Constant(frames, true);
}

// A marker moving at 1 unit per frame along x.
Xyz straightLine(Eigen::Index frames)
{
  Xyz xyz = Xyz::Zero(frames, 3);
  for (Eigen::Index f = 0; f < frames; ++f)
    xyz(f, 0) = static_cast<double>(f);
  return xyz;
}

// Fast motion at 60 Hz: a 1.5 Hz, 30 mm swing (up to 4.7 mm per frame, faster than any marker of
// the real 60 Hz takes) plus a slower drift.
Xyz fastMotion(Eigen::Index frames)
{
  Xyz xyz(frames, 3);
  const double pi = 3.14159265358979323846;
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / 60.0;
    xyz.row(f) << 30.0 * std::sin(2.0 * pi * 1.5 * t), 10.0 * std::cos(2.0 * pi * 0.7 * t), 5.0 * t;
  }
  return xyz;
}

Frames framesOf(const std::vector<SpikeFlag>& flags, Eigen::Index marker)
{
  Frames frames;
  for (const SpikeFlag& flag : flags)
    if (flag.marker == marker)
      frames.push_back(flag.frame);
  return frames;
}

TEST(SpikeDetection, MethodNamesRoundTrip)
{
  EXPECT_EQ(parseSpikeMethod("paper"), SpikeMethod::Paper);
  EXPECT_EQ(parseSpikeMethod("robust"), SpikeMethod::Robust);
  EXPECT_FALSE(parseSpikeMethod("Robust"));
  EXPECT_FALSE(parseSpikeMethod(""));
  EXPECT_EQ(spikeMethodName(SpikeMethod::Paper), "paper");
  EXPECT_EQ(spikeMethodName(SpikeMethod::Robust), "robust");
}

TEST(SpikeDetection, PaperFlagsExactlyTheBadPointOfEq9)
{
  // P_0..P_6 step 1 along x; P_3 is lifted 4 in y. Segments: 1, 1, √17, √17, 1, 1, so
  // eq 8: k = (4 + 2√17) / 6 = 2.0409 and 1.5k = 3.0614. Only P_3 has both segments (√17 = 4.123)
  // above it; P_2 and P_4 have one long and one short segment.
  Xyz xyz = straightLine(7);
  xyz(3, 1) = 4.0;
  EXPECT_EQ(detectSpikes(xyz, allValid(7), paper()), Frames{3});
  // factor 2.1: 2.1k = 4.286 > √17, nothing is bad any more.
  EXPECT_TRUE(detectSpikes(xyz, allValid(7), paper(2.1)).empty());
  // A lower factor lets short segments count: 0.4k = 0.816 < 1, so every interior point is bad.
  EXPECT_EQ(detectSpikes(xyz, allValid(7), paper(0.4)), (Frames{1, 2, 3, 4, 5}));
}

TEST(SpikeDetection, PaperComputesKPerRun)
{
  // Run 0..5 moves 1 per frame with P_2 lifted 3 in y; run 7..12 moves 10 per frame. Sharing k
  // would make 1.5k ≈ 7 and hide the first spike. Per run: segments 1, √10, √10, 1, 1 give
  // k = (3 + 2√10) / 5 = 1.865, 1.5k = 2.80 < √10 = 3.16, so P_2 is bad; the fast run is even.
  Xyz xyz = Xyz::Zero(13, 3);
  for (Eigen::Index f = 0; f < 6; ++f)
    xyz(f, 0) = static_cast<double>(f);
  xyz(2, 1) = 3.0;
  for (Eigen::Index f = 7; f < 13; ++f)
    xyz(f, 0) = 100.0 + 10.0 * static_cast<double>(f);
  ValidMask valid = allValid(13);
  valid(6) = false;
  xyz(6, 0) = std::numeric_limits<double>::quiet_NaN();  // an invalid sample is never read
  EXPECT_EQ(detectSpikes(xyz, valid, paper()), Frames{2});
  EXPECT_EQ(detectSpikes(xyz, valid, robust()), Frames{2});
}

TEST(SpikeDetection, NeverFlagsAcrossAGap)
{
  // The marker comes back 50 mm away after a gap: each run is smooth on its own.
  for (const SpikeOptions& options : {paper(), robust()}) {
    Xyz xyz = fastMotion(200);
    ValidMask valid = allValid(200);
    valid.segment(100, 10) = false;
    xyz.bottomRows(90).col(2).array() += 50.0;
    xyz.middleRows(100, 10).setConstant(1e9);
    const Frames flags = detectSpikes(xyz, valid, options);
    if (options.method == SpikeMethod::Robust) {
      EXPECT_TRUE(flags.empty());
    }
    for (Eigen::Index f : flags) {
      EXPECT_TRUE(valid(f));
      EXPECT_TRUE(f < 98 || f > 111) << f;
    }
  }
}

TEST(SpikeDetection, ShortAndStillRunsAreNotJudged)
{
  Xyz xyz = straightLine(15);
  ValidMask valid = allValid(15);
  valid(2) = false;
  valid(7) = false;
  xyz(1, 1) = 5.0;   // run 0..1: too short for either method
  xyz(5, 1) = 5.0;   // run 3..6: too short for Robust; in 4 samples eq 9 can never flag one spike
                     // (segments 1, s, s: 1.5k = 0.5 + s > s)
  xyz(10, 1) = 5.0;  // run 8..14: segments 1, 1, s, s, 1, 1 with s = √26 = 5.10: 1.5k = 3.05
  EXPECT_EQ(detectSpikes(xyz, valid, paper()), Frames{10});
  EXPECT_EQ(detectSpikes(xyz, valid, robust()), Frames{10});
  // A marker that never moves: k = 0, nothing stands out.
  EXPECT_TRUE(detectSpikes(Xyz::Ones(20, 3), allValid(20), paper()).empty());
  EXPECT_TRUE(detectSpikes(Xyz::Ones(20, 3), allValid(20), robust()).empty());
}

TEST(SpikeDetection, RobustLeavesSmoothMotionAloneAndFindsSpikesInIt)
{
  Xyz xyz = fastMotion(300);
  EXPECT_TRUE(detectSpikes(xyz, allValid(300), robust()).empty());
  EXPECT_TRUE(detectSpikes(straightLine(50), allValid(50), robust()).empty());
  // 5 mm spikes, at 60, 120 and 0 where the marker moves fastest (4.7 mm per frame): single,
  // double, triple, and at both run ends.
  const Eigen::RowVector3d offset(0.0, 3.0, 4.0);
  xyz.row(0) += offset;
  xyz.row(60) += offset;
  xyz.middleRows(120, 2).rowwise() += offset;
  xyz.middleRows(195, 3).rowwise() += offset;
  xyz.row(299) += offset;
  EXPECT_EQ(detectSpikes(xyz, allValid(300), robust()), (Frames{0, 60, 120, 121, 195, 196, 197, 299}));
}

TEST(SpikeDetection, RobustLeavesSharpTurnsOfNoiselessMotionAlone)
{
  // A noiseless or smoothed trajectory (a solver's skeleton, ART's filtered 6DOF bodies) leaves the
  // local scale at its floor, and a centred quadratic cannot follow a sharp turn of the motion: the
  // corner, the sample where a stop or a start happens, both edges of a step, were flagged as bad
  // points, inviting a "repair" that invents a sample. One side's trajectory leads to each of them;
  // a spike is missed from both sides, and is still found right beside the turn.
  static constexpr Eigen::Index kFrames = 80, kTurn = 40;
  const auto shape = [](auto position) {
    Xyz xyz(kFrames, 3);
    for (Eigen::Index f = 0; f < kFrames; ++f)
      xyz.row(f) = position(static_cast<double>(f - kTurn));
    return xyz;
  };
  const std::vector<std::pair<const char*, Xyz>> turns{
      {"corner", shape([](double t) { return Eigen::RowVector3d(3.0 * std::min(t, 0.0), 3.0 * std::max(t, 0.0), 0.0); })},
      {"stop", shape([](double t) { return Eigen::RowVector3d(5.0 * std::min(t, 0.0), 0.0, 0.0); })},
      {"start", shape([](double t) { return Eigen::RowVector3d(5.0 * std::max(t, 0.0), 0.0, 0.0); })},
      {"step", shape([](double t) { return Eigen::RowVector3d(t < 0.0 ? 0.0 : 10.0, 0.0, 0.0); })},
  };
  for (const auto& [name, clean] : turns) {
    EXPECT_EQ(detectSpikes(clean, allValid(kFrames), robust()), Frames{}) << name;
    Xyz spiked = clean;
    spiked.row(kTurn + 5) += Eigen::RowVector3d(0.0, 3.0, 4.0);
    spiked.middleRows(kTurn - 12, 2).rowwise() += Eigen::RowVector3d(0.0, -3.0, 4.0);
    EXPECT_EQ(detectSpikes(spiked, allValid(kFrames), robust()), (Frames{kTurn - 12, kTurn - 11, kTurn + 5})) << name;
  }
}

TEST(SpikeDetection, RobustFlagsNothingOnASmoothTakeWithFineNoise)
{
  // 40 markers swinging smoothly (2-40 mm, 0.2-3 Hz per axis) with 0.01 mm of noise, at the rates
  // of facial and body systems. At 30, 60, 100 and 120 Hz, 3, 12, 1 and 1 samples moving 5-10 mm
  // per frame were flagged 0.36 to 1.7 mm off the fit: above six times the 0.05 mm floor, a small
  // share of the motion. A 5 mm spike put into each marker's motion is still found (from 60 Hz:
  // at 30 Hz a 3 Hz swing has 10 samples a period, too few for the 9-sample fit either way).
  const double pi = 3.14159265358979323846;
  for (const double rate : {30.0, 60.0, 100.0, 120.0}) {
    Random random(7);
    const auto frames = static_cast<Eigen::Index>(20.0 * rate);
    Take take(std::vector<std::string>(40, "M"), frames, rate);
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      Eigen::Array3d amplitude, frequency, phase;
      for (Eigen::Index a = 0; a < 3; ++a) {
        amplitude(a) = 2.0 + 38.0 * random.uniform();
        frequency(a) = 0.2 + 2.8 * random.uniform();
        phase(a) = 2.0 * pi * random.uniform();
      }
      for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = static_cast<double>(f) / rate;
        Eigen::Vector3d position;
        for (Eigen::Index a = 0; a < 3; ++a)
          position(a) = 500.0 * static_cast<double>(a + 1) +
                        amplitude(a) * std::sin(2.0 * pi * frequency(a) * t + phase(a)) + 0.01 * random.normal();
        take.setPosition(f, m, position);
      }
    }
    take.valid().setConstant(true);
    take.residuals().setConstant(0.5);
    const std::vector<SpikeFlag> flags = detectSpikes(take, robust());
    EXPECT_TRUE(flags.empty()) << rate << " Hz: " << flags.size() << " flags, e.g. marker " << flags.front().marker
                               << " frame " << flags.front().frame;
    if (rate < 60.0)
      continue;
    std::vector<SpikeFlag> spikes;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const Eigen::Index frame = 10 + (m * 37) % (frames - 20);
      take.setPosition(frame, m, take.position(frame, m) + Eigen::Vector3d(0.0, 3.0, -4.0));
      spikes.push_back({m, frame});
    }
    const std::vector<SpikeFlag> found = detectSpikes(take, robust());
    for (const SpikeFlag& spike : spikes)
      EXPECT_NE(std::find(found.begin(), found.end(), spike), found.end())
          << rate << " Hz: marker " << spike.marker << " frame " << spike.frame;
  }
}

TEST(SpikeDetection, RobustFlagsFewSamplesOfSmoothForeignTakes)
{
  // ART's filtered 6DOF body (every sample valid, integer storage) and an OptiTrack solver's
  // skeleton (mocap36) had 631 and 808 samples flagged (1.5 % and 1.9 %): corners of the motion,
  // foot strikes, the edges of steps. What is left are samples neither side's trajectory leads to.
  for (const char* file : {"c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d", "c3d/btk_others/mocap36.c3d"}) {
    const Take take = readC3d(test::dataFile(file));
    const auto flags = static_cast<double>(detectSpikes(take, robust()).size());
    EXPECT_LT(flags, 0.007 * static_cast<double>(take.valid().count())) << file << ": " << flags << " flags";
  }
}

TEST(SpikeDetection, RobustCatchesWhatEq9Misses)
{
  const Take& take = test::noseMoCapTake();
  const Eigen::Index marker = *take.markerIndex("NoseHead");
  Xyz xyz = take.trajectory(marker);
  ValidMask valid = take.valid().col(marker);
  ASSERT_TRUE(detectSpikes(xyz, valid, robust()).empty());
  // A 2-sample spike (the segment between its samples is short) and a spike on the last sample
  // before a gap (eq 9 needs a segment on both sides).
  const Eigen::RowVector3d offset(3.0, 0.0, -4.0);
  xyz.middleRows(300, 2).rowwise() += offset;
  valid.segment(601, 10) = false;
  xyz.row(600) += offset;
  EXPECT_EQ(detectSpikes(xyz, valid, robust()), (Frames{300, 301, 600}));
  const Frames paperAfter = detectSpikes(xyz, valid, paper());
  for (Eigen::Index f : {300, 301, 600})
    EXPECT_EQ(std::count(paperAfter.begin(), paperAfter.end(), f), 0) << f;
}

TEST(SpikeDetection, RunsAreJudgedAloneInATakeWithGaps)
{
  // Flags on a whole trajectory are exactly the flags of each valid run cut out on its own.
  const Take take = readC3d(test::sampleTake());
  for (const SpikeOptions& options : {paper(), robust()}) {
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const auto valid = take.valid().col(m);
      Frames perRun;
      for (Eigen::Index f = 0; f < take.frameCount();) {
        if (!valid(f)) {
          ++f;
          continue;
        }
        Eigen::Index end = f;
        while (end < take.frameCount() && valid(end))
          ++end;
        for (Eigen::Index g :
             detectSpikes(take.trajectory(m).middleRows(f, end - f), allValid(end - f), options))
          perRun.push_back(f + g);
        f = end;
      }
      ASSERT_EQ(detectSpikes(take.trajectory(m), valid, options), perRun) << take.label(m);
    }
  }
}

TEST(SpikeDetection, InjectedSpikeInCleanRealDataIsFoundAndRestored)
{
  const Take& clean = test::noseMoCapTake();
  ASSERT_EQ(clean.markerCount(), 41);
  ASSERT_EQ(clean.frameCount(), 962);
  const std::vector<SpikeFlag> before = detectSpikes(clean, robust());
  // Well under 0.1 % of this clean take is flagged.
  EXPECT_LT(static_cast<double>(before.size()), 0.001 * static_cast<double>(clean.valid().count()));
  const Eigen::Index marker = *clean.markerIndex("Mouth_Lend");
  ASSERT_TRUE(framesOf(before, marker).empty());
  for (const Eigen::Index frame : {Eigen::Index{0}, Eigen::Index{480}, Eigen::Index{961}}) {
    Take take = clean;
    take.setPosition(frame, marker, clean.position(frame, marker) + Eigen::Vector3d(0.0, -5.0, 0.0));
    const std::vector<SpikeFlag> flags = detectSpikes(take, robust());
    EXPECT_EQ(framesOf(flags, marker), Frames{frame});
    const std::vector<SamplePatch> patches = replaceSpikes(take, {{marker, frame}});
    ASSERT_EQ(patches.size(), 1u);
    applyPatches(take, patches);
    // Restored within the take's own noise and motion per frame (tenths of a millimetre).
    EXPECT_LT((take.position(frame, marker) - clean.position(frame, marker)).norm(), 0.3) << frame;
  }
}

TEST(SpikeDetection, FlagsAreTheSameInAnyUnit)
{
  Take metres = test::noseMoCapTake();
  const Eigen::Index marker = *metres.markerIndex("Chin_L1");
  metres.setPosition(500, marker, metres.position(500, marker) + Eigen::Vector3d(4.0, 3.0, 0.0));
  const std::vector<SpikeFlag> millimetreFlags = detectSpikes(metres, robust());
  EXPECT_EQ(framesOf(millimetreFlags, marker), Frames{500});
  EXPECT_GT(millimetreFlags.size(), 1u);  // a few fast samples of other markers too: they must match
  metres.convertUnits(LengthUnit::Metre);
  const std::vector<SpikeFlag> metreFlags = detectSpikes(metres, robust());
  EXPECT_EQ(metreFlags, millimetreFlags);
}

TEST(SpikeDetection, ReplacementIsEq10AndLinearAcrossBlocks)
{
  // Marker a: P_f = (f², f, 0), valid except frame 9 (a gap), frames 12..13 a run of their own.
  Take take({"a", "b"}, 14, 100.0);
  for (Eigen::Index f = 0; f < 14; ++f) {
    const auto t = static_cast<double>(f);
    take.setPosition(f, 0, {t * t, t, 0.0});
    take.valid()(f, 0) = f != 9 && f != 11;
    take.residuals()(f, 0) = take.valid()(f, 0) ? 0.5 : -1.0;
  }
  const auto row = [](double t) { return Eigen::RowVector3d(t * t, t, 0.0); };
  const std::vector<SpikeFlag> flags = {{0, 3}, {0, 5}, {0, 6}, {0, 12}, {0, 13}, {0, 3}, {0, 9}, {1, 4}};
  const std::vector<SamplePatch> patches = replaceSpikes(take, flags);
  // Marker b is never valid and frame 9 of a is in a gap: those flags are ignored. Run 12..13 is
  // all flagged: nothing to rebuild it from, so it is left alone.
  ASSERT_EQ(patches.size(), 1u);
  const SamplePatch& patch = patches[0];
  EXPECT_EQ(patch.marker, 0);
  ASSERT_EQ(patch.frames, (Frames{3, 5, 6}));
  // Eq 10: the mid-value of the neighbours 2 and 4.
  EXPECT_EQ(patch.positions.row(0), 0.5 * (row(2.0) + row(4.0)));
  // Block 5..6: on the straight line from 4 to 7.
  EXPECT_LT((patch.positions.row(1) - (2.0 * row(4.0) + row(7.0)) / 3.0).norm(), 1e-12);
  EXPECT_LT((patch.positions.row(2) - (row(4.0) + 2.0 * row(7.0)) / 3.0).norm(), 1e-12);
  for (SampleState state : patch.states)
    EXPECT_EQ(state, SampleOrigin::Edited);
  EXPECT_TRUE(patch.valid.all());
  EXPECT_TRUE((patch.residuals == 0.0).all());
}

TEST(SpikeDetection, ReplacementExtrapolatesAtRunEnds)
{
  // A straight line, so the least-squares line through the nearest unflagged samples is exact.
  Take take({"a"}, 12, 100.0);
  for (Eigen::Index f = 0; f < 12; ++f) {
    const auto t = static_cast<double>(f);
    take.setPosition(f, 0, {2.0 * t, 1.0, -t});
    take.valid()(f, 0) = f != 8;
  }
  const Take truth = take;
  take.setPosition(0, 0, {9.0, 9.0, 9.0});  // first sample of the take
  take.setPosition(3, 0, {9.0, 9.0, 9.0});
  for (Eigen::Index f = 5; f < 8; ++f)  // a block of 3 ending at the gap at 8
    take.setPosition(f, 0, {-9.0, 9.0, 9.0});
  const std::vector<SamplePatch> patches = replaceSpikes(take, {{0, 0}, {0, 3}, {0, 5}, {0, 6}, {0, 7}});
  ASSERT_EQ(patches.size(), 1u);
  ASSERT_EQ(patches[0].frames, (Frames{0, 3, 5, 6, 7}));
  for (std::size_t i = 0; i < patches[0].frames.size(); ++i) {
    const Eigen::Index f = patches[0].frames[i];
    EXPECT_LT((patches[0].positions.row(static_cast<Eigen::Index>(i)) - truth.trajectory(0).row(f)).norm(),
              1e-12)
        << f;
  }
  // With one unflagged neighbour only, the block takes its position.
  Take pair({"a"}, 3, 100.0);
  pair.valid().col(0).setConstant(true);
  pair.setPosition(0, 0, {1.0, 2.0, 3.0});
  const auto single = replaceSpikes(pair, {{0, 1}, {0, 2}});
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].positions.row(1), Eigen::RowVector3d(1.0, 2.0, 3.0));
}

TEST(SpikeDetection, ReplacingChangesOnlyTheFlaggedSamples)
{
  Take take = readC3d(test::sampleTake());
  const Take original = take;
  const std::vector<SpikeFlag> flags = detectSpikes(take, robust());
  ASSERT_FALSE(flags.empty());  // this take has real glitches
  for (const SpikeFlag& flag : flags)
    ASSERT_TRUE(take.isValid(flag.frame, flag.marker));
  applyPatches(take, replaceSpikes(take, flags));
  SampleMask flagged = SampleMask::Constant(take.frameCount(), take.markerCount(), false);
  for (const SpikeFlag& flag : flags)
    flagged(flag.frame, flag.marker) = true;
  EXPECT_TRUE((take.valid() == original.valid()).all());
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      if (flagged(f, m)) {
        ASSERT_EQ(take.state(f, m), SampleOrigin::Edited);
        ASSERT_EQ(take.residuals()(f, m), 0.0);
        continue;
      }
      ASSERT_EQ(take.state(f, m), original.state(f, m));
      ASSERT_EQ(take.residuals()(f, m), original.residuals()(f, m));
      ASSERT_EQ(take.position(f, m), original.position(f, m)) << m << " " << f;
    }
}

TEST(SpikeDetection, BadInput)
{
  // Empty takes and never-valid markers: no flags, no patches.
  EXPECT_TRUE(detectSpikes(Take(), robust()).empty());
  EXPECT_TRUE(replaceSpikes(Take(), {}).empty());
  const Take invalid({"a", "b"}, 50, 100.0);
  EXPECT_TRUE(detectSpikes(invalid, robust()).empty());
  EXPECT_TRUE(detectSpikes(invalid, paper()).empty());
  EXPECT_TRUE(detectSpikes(Xyz(0, 3), ValidMask(0), robust()).empty());
  // NaN in a valid sample.
  Take nan({"a", "b"}, 20, 100.0);
  nan.valid().setConstant(true);
  nan.setPosition(7, 1, {0.0, std::numeric_limits<double>::quiet_NaN(), 0.0});
  for (const SpikeOptions& options : {paper(), robust()}) {
    try {
      (void)detectSpikes(nan, options);
      ADD_FAILURE() << "no exception";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("marker b"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("frame 7"), std::string::npos) << e.what();
    }
  }
  nan.valid()(7, 1) = false;  // invalid samples may hold anything
  EXPECT_NO_THROW((void)detectSpikes(nan, robust()));
  // Options out of range.
  const Xyz xyz = straightLine(10);
  for (double factor :
       {-1.5, 0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW((void)detectSpikes(xyz, allValid(10), paper(factor)), InvalidArgument) << factor;
  SpikeOptions options = robust();
  options.threshold = -6.0;
  EXPECT_THROW((void)detectSpikes(xyz, allValid(10), options), InvalidArgument);
  options.threshold = 6.0;
  options.noiseFloor = -0.1;
  EXPECT_THROW((void)detectSpikes(xyz, allValid(10), options), InvalidArgument);
  EXPECT_THROW((void)detectSpikes(test::noseMoCapTake(), paper(-1.0)), InvalidArgument);
  EXPECT_THROW(checkSpikeOptions(paper(-1.0)), InvalidArgument);
  // Sizes that disagree, flags outside the take.
  EXPECT_THROW((void)detectSpikes(xyz, allValid(9), robust()), InvalidArgument);
  EXPECT_THROW((void)replaceSpikes(invalid, {{2, 0}}), InvalidArgument);
  EXPECT_THROW((void)replaceSpikes(invalid, {{0, 50}}), InvalidArgument);
  EXPECT_THROW((void)replaceSpikes(invalid, {{0, -1}}), InvalidArgument);
}

TEST(SpikeDetection, InteriorFlagsDoNotDependOnWhereTheRunStarts)
{
  // The detector works through a run's interior several windows at a time (one per vector lane,
  // and for the local scale pairs of windows sharing samples), from the run's first sample. A run
  // that starts 1-3 samples earlier puts each interior sample in another lane and pair, so its
  // flags far from the run's ends must not change, at every threshold: low thresholds flag noise
  // samples whose verdict hangs on the exact local scale.
  constexpr Eigen::Index kFrames = 600, kEnds = 40;
  Random random(3);
  const Xyz base = fastMotion(kFrames + 3);
  Xyz noisy = base;
  for (Eigen::Index f = 0; f < noisy.rows(); ++f)
    for (Eigen::Index c = 0; c < 3; ++c)
      noisy(f, c) += 0.05 * random.normal() * (1.0 + static_cast<double>((f / 50) % 4));  // the scale varies
  for (Eigen::Index f = 60; f < kFrames; f += 37)
    noisy(f, f % 3) += 0.8;
  for (const double threshold : {2.0, 3.0, 4.5, 6.0}) {
    SpikeOptions options = robust();
    options.threshold = threshold;
    Frames reference;
    for (Eigen::Index start = 3; start >= 0; --start) {
      const Xyz run = noisy.bottomRows(kFrames + start);  // `start` more samples before frame 3
      Frames interior;
      for (Eigen::Index f : detectSpikes(run, allValid(run.rows()), options))
        if (f - start >= kEnds && f - start < kFrames - kEnds)
          interior.push_back(f - start);
      if (start == 3)
        reference = interior;
      else
        EXPECT_EQ(interior, reference) << "threshold " << threshold << ", run starting " << start << " earlier";
    }
    EXPECT_GE(reference.size(), 4u) << threshold;  // 0.8 mm in noise of up to 0.2 mm per axis: few at 6
  }
}

TEST(SpikeDetection, RepairedSpikesAreNotFlaggedAgain)
{
  // The sample take has real glitches; a spike can hide a smaller one beside it. Detecting,
  // repairing and detecting again with the same settings must find (next to) nothing new.
  Take take = readC3d(test::sampleTake());
  SpikeOptions settle = robust();
  settle.maxPasses = 100;
  const std::vector<SpikeFlag> first = detectSpikes(take, settle);
  ASSERT_GT(first.size(), 100u);
  applyPatches(take, replaceSpikes(take, first));
  const std::vector<SpikeFlag> second = detectSpikes(take, settle);
  EXPECT_LE(second.size(), first.size() / 50) << first.size() << " then " << second.size();  // 213 then 4
  // One pass (the default): the repair uncovers dozens more.
  SpikeOptions onePass = robust();
  onePass.maxPasses = 1;
  Take again = readC3d(test::sampleTake());
  const std::vector<SpikeFlag> single = detectSpikes(again, onePass);
  applyPatches(again, replaceSpikes(again, single));
  EXPECT_GT(detectSpikes(again, onePass).size(), 10u);
  onePass.maxPasses = 0;
  EXPECT_THROW((void)detectSpikes(again, onePass), InvalidArgument);
}

TEST(SpikeEvaluation, RobustMeetsTheTargetOnCleanRealData)
{
  // The target at 5 mm: recall >= 99 % with at most 1 % false alarms.
  const std::vector<SpikeEvaluation> results = evaluateSpikes(test::noseMoCapTake(), {});
  ASSERT_EQ(results.size(), 2u);
  const SpikeEvaluation& paperResult = results[0];
  const SpikeEvaluation& robustResult = results[1];
  EXPECT_EQ(paperResult.method, "paper");
  EXPECT_EQ(robustResult.method, "robust");
  EXPECT_GE(robustResult.injected, 200 + 200 / 3);  // a third of the spikes are 2-3 samples long
  EXPECT_EQ(robustResult.injected, paperResult.injected);
  EXPECT_GE(robustResult.recall, 0.99);
  EXPECT_LE(robustResult.falseAlarmRate, 0.01);
  EXPECT_LT(robustResult.restoredRmse, 0.5);
  // Eq 9 misses blocks and run ends: it cannot reach the target.
  EXPECT_LT(paperResult.recall, 0.6);
  EXPECT_EQ(robustResult.recall,
            static_cast<double>(robustResult.detected) / static_cast<double>(robustResult.injected));
}

TEST(SpikeEvaluation, IsReproducibleAndChecksItsOptions)
{
  SpikeEvaluationOptions options;
  options.count = 30;
  options.seed = 7;
  const auto first = evaluateSpikes(test::noseMoCapTake(), options);
  const auto second = evaluateSpikes(test::noseMoCapTake(), options);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].injected, second[i].injected);
    EXPECT_EQ(first[i].detected, second[i].detected);
    EXPECT_EQ(first[i].falseAlarms, second[i].falseAlarms);
  }
  options.count = 0;
  EXPECT_THROW((void)evaluateSpikes(test::noseMoCapTake(), options), InvalidArgument);
  options.count = 10;
  options.amplitude = -5.0;
  EXPECT_THROW((void)evaluateSpikes(test::noseMoCapTake(), options), InvalidArgument);
  options.amplitude = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)evaluateSpikes(test::noseMoCapTake(), options), InvalidArgument);
  options.amplitude = 5.0;
  options.detector.factor = -1.0;
  EXPECT_THROW((void)evaluateSpikes(test::noseMoCapTake(), options), InvalidArgument);
  EXPECT_THROW((void)evaluateSpikes(Take({"a"}, 10, 100.0), {}), InvalidArgument);
  EXPECT_THROW((void)evaluateSpikes(Take(), {}), InvalidArgument);
}

} // namespace
} // namespace mocap
