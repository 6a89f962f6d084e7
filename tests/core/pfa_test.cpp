// Marker layout planning (Wellein et al. 2007): PFA, greedy selection, random baselines and the
// layout sweep, on synthetic takes with known structure and on the real AnimFace take.
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/layout/layout_frames.h"
#include "mocap/layout/layout_planning.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/io/take_io.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <cmath>
#include <random>
#include <map>
#include <set>

namespace mocap {
namespace {

// A take whose markers all move; marker m follows `motion(frame, m)`.
template <typename Motion>
Take makeTake(const std::vector<std::string>& labels, Eigen::Index frames, Motion motion)
{
  Take take(labels, frames, 100.0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < frames; ++f) {
      take.setPosition(f, m, motion(f, m));
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 0.0;
    }
  return take;
}

// Smooth random 3-D motion of a few independent "driver" markers.
struct Drivers
{
  explicit Drivers(int count, unsigned seed = 3)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> frequency(0.2, 3.0), phase(0.0, 6.28), amplitude(1.0, 6.0);
    for (int d = 0; d < count; ++d)
      for (int axis = 0; axis < 3; ++axis)
        for (int s = 0; s < 3; ++s)
          terms.push_back({d, axis, frequency(random), phase(random), amplitude(random)});
  }
  [[nodiscard]] Eigen::Vector3d at(Eigen::Index frame, int driver) const
  {
    Eigen::Vector3d p(40.0 * driver, 10.0 * driver, 800.0);
    const double t = static_cast<double>(frame) / 100.0;
    for (const Term& term : terms)
      if (term.driver == driver)
        p(term.axis) += term.amplitude * std::sin(term.frequency * t + term.phase);
    return p;
  }
  struct Term
  {
    int driver, axis;
    double frequency, phase, amplitude;
  };
  std::vector<Term> terms;
};

std::vector<std::string> numberedLabels(const std::string& stem, Eigen::Index count)
{
  std::vector<std::string> labels;
  for (Eigen::Index i = 0; i < count; ++i)
    labels.push_back(stem + std::to_string(i));
  return labels;
}

// 4 drivers, each with 3 copies (translated, or mapped by a fixed linear transform): marker m
// belongs to group m % 4.
Take copiesTake(bool linearCopies)
{
  const Drivers drivers(4);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<Eigen::Matrix3d> maps;
  for (int c = 0; c < 16; ++c)
    maps.push_back(c < 4 || !linearCopies
                       ? Eigen::Matrix3d::Identity()
                       : Eigen::Matrix3d(Eigen::Matrix3d::Identity() +
                                         0.4 * Eigen::Matrix3d::NullaryExpr([&] { return entry(random); })));
  return makeTake(numberedLabels("m", 16), 1200, [&](Eigen::Index f, Eigen::Index m) {
    const Eigen::Vector3d offset(5.0 * static_cast<double>(m), -3.0 * static_cast<double>(m), 2.0);
    return Eigen::Vector3d(maps[static_cast<std::size_t>(m)] * drivers.at(f, static_cast<int>(m % 4)) +
                           offset);
  });
}

std::set<Eigen::Index> groupsOf(const std::vector<Eigen::Index>& markers)
{
  std::set<Eigen::Index> groups;
  for (const Eigen::Index m : markers)
    groups.insert(m % 4);
  return groups;
}

SubsetErrors errorsFor(const LayoutFrames& frames, double ridge)
{
  const Eigen::Index neutral = findNeutralFrame(frames.frames, frames.training);
  SubsetErrorOptions options;
  options.ridge = ridge;
  return SubsetErrors(frames.frames, frames.training, frames.test,
                      buildBlendshapeBasis(frames.frames, neutral,
                                           chooseKeyPoses(frames.frames, neutral, 6, frames.training)),
                      options);
}

TEST(MarkerSelection, PfaOnExactCopiesSelectsEveryDriverGroupAndReconstructsTheRest)
{
  const LayoutFrames frames = collectLayoutFrames({copiesTake(false)}, {});
  PfaOptions options;
  options.varianceFraction = 0.999999;  // keep all 12 independent directions
  options.restarts = 50;
  options.minK = options.maxK = 12;  // one cluster per driver coordinate
  const PfaSweep sweep = sweepPfa(frames.frames(frames.training, Eigen::all), MarkerSymmetry(16), options);
  ASSERT_EQ(sweep.selections.size(), 1u);
  EXPECT_EQ(sweep.components, 12);
  const std::vector<Eigen::Index>& selected = sweep.selections[0].markers;
  EXPECT_EQ(groupsOf(selected).size(), 4u) << "every driver (or a copy) must be selected";
  EXPECT_LT(errorsFor(frames, 0.0).reconstructionRmse(selected), 1e-6);
}

TEST(MarkerSelection, GreedyOnLinearCopiesPicksOneMarkerPerDriverWithZeroError)
{
  const LayoutFrames frames = collectLayoutFrames({copiesTake(true)}, {});
  const SubsetErrors errors = errorsFor(frames, 0.0);
  const auto selected = selectGreedy(errors, MarkerSymmetry(16), 4);
  ASSERT_TRUE(selected);
  EXPECT_EQ(groupsOf(*selected).size(), 4u);
  EXPECT_LT(errors.reconstructionRmse(*selected), 1e-6);
  EXPECT_GT(errors.reconstructionRmse({0, 4, 8}), 0.5) << "a missing driver group cannot be reconstructed";
}

// A face-like layout mirrored about a tilted mid-sagittal plane: pairs (2i, 2i+1), then 3 midline markers.
struct MirroredFace
{
  MirroredFace()
  {
    const Eigen::Matrix3d tilt =
        (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitZ()))
            .toRotationMatrix();
    const Drivers drivers(3, 5);
    const std::vector<Eigen::Vector3d> half = {
        {30, 40, 10}, {45, 0, 0}, {25, -30, 15}, {55, 20, -10}, {15, -55, 20}};
    for (std::size_t i = 0; i < half.size(); ++i) {
      labels.push_back("Left" + std::to_string(i));
      labels.push_back("Right" + std::to_string(i));
    }
    for (int i = 0; i < 3; ++i)
      labels.push_back("Mid" + std::to_string(i));
    take = makeTake(labels, 900, [&](Eigen::Index f, Eigen::Index m) {
      Eigen::Vector3d p;
      if (m < 10) {
        const auto i = static_cast<std::size_t>(m / 2);
        Eigen::Vector3d motion = drivers.at(f, 0) - drivers.at(0, 0);
        motion += (static_cast<double>(i) * 0.3) * (drivers.at(f, 1) - drivers.at(0, 1));
        p = half[i] + motion;
        if (m % 2 == 1)
          p.x() = -p.x();  // the mirror image, moving mirrored
      } else {
        p = Eigen::Vector3d(0.0, 50.0 - 40.0 * static_cast<double>(m - 10), 25.0) +
            (drivers.at(f, 2) - drivers.at(0, 2));
        p.x() = 0.05 * (drivers.at(f, 2) - drivers.at(0, 2)).x();
      }
      return Eigen::Vector3d(tilt * p + Eigen::Vector3d(100, 700, 30));
    });
  }
  std::vector<std::string> labels;
  Take take;
};

TEST(MarkerPairs, MirrorMatchingFindsThePairsAndTheMidlineAboutATiltedPlane)
{
  const MirroredFace face;
  Eigen::MatrixX3d neutral(13, 3);
  for (Eigen::Index m = 0; m < 13; ++m)
    neutral.row(m) = face.take.position(0, m).transpose();
  PairDetectionOptions options;
  options.useLabels = false;
  const PairDetection detection = detectMarkerPairs(neutral, face.labels, options);
  ASSERT_EQ(detection.pairs.size(), 5u);
  for (const DetectedPair& pair : detection.pairs) {
    EXPECT_EQ(pair.first % 2, 0);
    EXPECT_EQ(pair.second, pair.first + 1);
    EXPECT_LT(pair.mismatch, 1e-6);
  }
  EXPECT_EQ(detection.midline, (std::vector<Eigen::Index>{10, 11, 12}));
  EXPECT_TRUE(detection.unpaired.empty());
}

TEST(MarkerPairs, LabelConventionsNamePartners)
{
  const auto has = [](const std::string& label, const std::string& partner) {
    const auto candidates = mirroredLabelCandidates(label);
    return std::find(candidates.begin(), candidates.end(), partner) != candidates.end();
  };
  EXPECT_TRUE(has("Leye_Up", "Reye_Up"));
  EXPECT_TRUE(has("Chin_L1", "Chin_R1"));
  EXPECT_TRUE(has("Mouth_UpL1", "Mouth_UpR1"));
  EXPECT_TRUE(has("ForeHead_L", "ForeHead_R"));
  EXPECT_TRUE(has("LeftBrow", "RightBrow"));
  EXPECT_TRUE(has("l_cheek", "r_cheek"));
  EXPECT_FALSE(has("Eyebrow_Center", "Eyebrow_Center"));
  EXPECT_TRUE(mirroredLabelCandidates("lip").empty()) << "a lower-case letter inside a word is no side";

  const std::vector<std::string> labels = {"Leye_Up", "Reye_Up", "Nose", "Chin_L1", "Chin_R1"};
  const PairDetection detection = detectMarkerPairs(Eigen::MatrixX3d::Random(5, 3), labels);
  EXPECT_EQ(detection.symmetry.mirror(0), 1);
  EXPECT_EQ(detection.symmetry.mirror(3), 4);
  EXPECT_TRUE(detection.pairs[0].fromLabels);
}

TEST(MarkerPairs, ParsedPairsAndTheirErrors)
{
  const std::vector<std::string> labels = {"a", "b", "c", "d"};
  const MarkerSymmetry symmetry = parseMarkerPairs("# pairs\na b\n\nc,d  # comment\n", labels, "pairs.txt");
  EXPECT_EQ(symmetry.pairs(), (std::vector<std::pair<Eigen::Index, Eigen::Index>>{{0, 1}, {2, 3}}));
  EXPECT_EQ(symmetry.symmetricClosure({2}), (std::vector<Eigen::Index>{2, 3}));
  const auto fails = [&](const std::string& text, const std::string& message) {
    try {
      (void)parseMarkerPairs(text, labels, "pairs.txt");
      ADD_FAILURE() << "no error for: " << text;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  fails("a x\n", "line 1: no marker 'x'");
  fails("a b\nb c\n", "line 2: marker 'b' is in two pairs");
  fails("a a\n", "paired with itself");
  fails("a b c\n", "expected two marker labels");
}

TEST(MarkerSelection, EverySelectionHoldsBothMarkersOfEachPair)
{
  const MirroredFace face;
  const LayoutFrames frames = collectLayoutFrames({face.take}, {});
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
  for (Eigen::Index i = 0; i < 5; ++i)
    pairs.emplace_back(2 * i, 2 * i + 1);
  const MarkerSymmetry symmetry(13, pairs);
  const auto symmetric = [&](const std::vector<Eigen::Index>& markers) {
    return symmetry.symmetricClosure(markers) == markers;
  };
  PfaOptions options;
  options.restarts = 30;
  for (const PfaSelection& selection :
       sweepPfa(frames.frames(frames.training, Eigen::all), symmetry, options).selections)
    EXPECT_TRUE(symmetric(selection.markers)) << "k = " << selection.k;
  const SubsetErrors errors = errorsFor(frames, 1e-3);
  for (Eigen::Index size = 1; size < 13; ++size) {
    const auto greedy = selectGreedy(errors, symmetry, size);
    ASSERT_TRUE(greedy) << size;
    EXPECT_EQ(static_cast<Eigen::Index>(greedy->size()), size);
    EXPECT_TRUE(symmetric(*greedy)) << size;
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      const auto random = selectRandom(symmetry, size, seed);
      ASSERT_TRUE(random);
      EXPECT_EQ(static_cast<Eigen::Index>(random->size()), size);
      EXPECT_TRUE(symmetric(*random));
    }
  }
  // With no single markers left, an odd size cannot be symmetric.
  EXPECT_FALSE(selectRandom(MarkerSymmetry(2, {{0, 1}}), 1, 0));
}

TEST(MarkerSelection, GreedyStartedFromAnotherSetNeverEndsWorseThanIt)
{
  const MirroredFace face;
  const LayoutFrames frames = collectLayoutFrames({face.take}, {});
  const MarkerSymmetry symmetry(13, {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {8, 9}});
  const SubsetErrors errors = errorsFor(frames, 1e-3);
  std::vector<Eigen::Index> sizes;
  std::map<Eigen::Index, std::vector<Eigen::Index>> starts;
  for (Eigen::Index size = 2; size < 13; ++size) {
    sizes.push_back(size);
    starts.emplace(size, *selectRandom(symmetry, size, static_cast<std::uint64_t>(size)));
  }
  const auto started = selectGreedy(errors, symmetry, sizes, {}, starts);
  ASSERT_EQ(started.size(), sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    ASSERT_TRUE(started[i]);
    const double value = errors.trainingObjective(*started[i]);
    EXPECT_LE(value, errors.trainingObjective(starts.at(sizes[i])) + 1e-12) << sizes[i];
    EXPECT_EQ(symmetry.symmetricClosure(*started[i]), *started[i]);
  }
}

TEST(MarkerSelection, SameResultOnAnyThreadCountAndCancellation)
{
  const LayoutFrames frames = collectLayoutFrames({readTake(test::dataFile("trc/NoseMoCap.trc"))}, {});
  const Eigen::MatrixXd training = frames.frames(frames.training, Eigen::all);
  PfaOptions options;
  options.restarts = 60;
  options.minK = 6;
  options.maxK = 9;
  std::vector<double> progress;
  const JobControl one = JobControl().withThreads(1);
  const JobControl two = JobControl([&](double f) { progress.push_back(f); }).withThreads(2);
  const PfaSweep a = sweepPfa(training, MarkerSymmetry(41), options, one);
  const PfaSweep b = sweepPfa(training, MarkerSymmetry(41), options, two);
  ASSERT_EQ(a.selections.size(), 4u);
  ASSERT_EQ(b.selections.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.selections[i].markers, b.selections[i].markers);
    EXPECT_EQ(a.selections[i].unitFrequency, b.selections[i].unitFrequency);
  }
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);

  auto cancel = std::make_shared<std::atomic<bool>>(false);
  const JobControl cancelling(
      [&](double f) {
        if (f > 0.0)  // the first report comes after the first restart
          *cancel = true;
      },
      cancel);
  const PfaSweep stopped = sweepPfa(training, MarkerSymmetry(41), options, cancelling);
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_LT(stopped.selections.size(), 4u);
}

void expectInvalid(const std::function<void()>& run, const std::string& message)
{
  try {
    run();
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(MarkerSelection, BadInputGivesAClearError)
{
  const Drivers drivers(2);
  const auto moving = [&](Eigen::Index f, Eigen::Index m) { return drivers.at(f, static_cast<int>(m % 2)); };
  LayoutFramesOptions one;
  one.markers = {"m0"};
  expectInvalid([&] { (void)collectLayoutFrames({makeTake(numberedLabels("m", 3), 500, moving)}, one); },
                "at least two markers");
  expectInvalid([&] { (void)collectLayoutFrames({makeTake(numberedLabels("m", 10), 25, moving)}, {}); },
                "training frames for 30 features");
  Take withNan = makeTake(numberedLabels("m", 3), 500, moving);
  withNan.setPosition(17, 1, Eigen::Vector3d(1.0, std::nan(""), 2.0));
  expectInvalid([&] { (void)collectLayoutFrames({withNan}, {}); }, "non-finite");
  const LayoutFrames frames = collectLayoutFrames({makeTake(numberedLabels("m", 3), 500, moving)}, {});
  PfaOptions tooMany;
  tooMany.minK = 2;
  tooMany.maxK = 10;
  expectInvalid(
      [&] { (void)sweepPfa(frames.frames(frames.training, Eigen::all), MarkerSymmetry(3), tooMany); },
      "number of features");
  expectInvalid([&] { (void)sweepPfa(frames.frames.topRows(5), MarkerSymmetry(3)); },
                "5 frames for 9 features");
  expectInvalid([&] { (void)sweepPfa(frames.frames(frames.training, Eigen::all), MarkerSymmetry(4)); },
                "symmetry");
  LayoutFramesOptions unknown;
  unknown.markers = {"m0", "nose"};
  expectInvalid([&] { (void)collectLayoutFrames({makeTake(numberedLabels("m", 3), 500, moving)}, unknown); },
                "'nose' is not in take 1");
}

TEST(MarkerSelection, KneeOfAnLShapedCurve)
{
  const std::vector<Eigen::Index> sizes = {1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> error = {10, 5, 1.2, 1.0, 0.8, 0.6, 0.3, 0.0};
  EXPECT_EQ(sizes[chooseKnee(sizes, error, error)], 3);
  expectInvalid([&] { (void)chooseKnee(sizes, error, {1.0}); }, "differ in length");
}

// The targets on real facial data (41 AnimFace markers), at the PFA sizes nearest 1/3,
// 1/2 and 2/3 of the markers, with 100 restarts instead of 1000 to keep the test short.
TEST(MarkerSelection, OnNoseMoCapGreedyBeatsPfaAndPfaBeatsRandom)
{
  const LayoutFrames frames = collectLayoutFrames({readTake(test::dataFile("trc/NoseMoCap.trc"))}, {});
  const Eigen::Index neutral = findNeutralFrame(frames.frames, frames.training);
  Eigen::MatrixX3d positions(frames.markerCount(), 3);
  for (Eigen::Index m = 0; m < frames.markerCount(); ++m)
    positions.row(m) = frames.frames.row(neutral).segment<3>(3 * m);
  const PairDetection pairs = detectMarkerPairs(positions, frames.labels);
  EXPECT_EQ(pairs.pairs.size(), 17u);
  LayoutPlanOptions options;
  options.pfa.restarts = 100;
  const LayoutPlan plan = planMarkerLayout(frames, pairs.symmetry, options);
  std::vector<Eigen::Index> pfaSizes;
  for (const LayoutSize& entry : plan.sizes)
    if (entry.pfa)
      pfaSizes.push_back(entry.markerCount);
  ASSERT_GE(pfaSizes.size(), 3u);
  for (const double fraction : {1.0 / 3.0, 0.5, 2.0 / 3.0}) {
    const double target = fraction * static_cast<double>(frames.markerCount());
    const Eigen::Index size =
        *std::min_element(pfaSizes.begin(), pfaSizes.end(), [&](Eigen::Index a, Eigen::Index b) {
          return std::abs(static_cast<double>(a) - target) < std::abs(static_cast<double>(b) - target);
        });
    const LayoutSize& entry = *plan.size(size);
    ASSERT_TRUE(entry.greedy);
    ASSERT_EQ(entry.randomCount, 20);
    EXPECT_LT(entry.pfa->blendshapeError, entry.randomBlendshapeError) << size << " markers";
    EXPECT_LT(entry.pfa->reconstructionRmse, entry.randomReconstructionRmse) << size << " markers";
    EXPECT_LT(entry.greedy->blendshapeError, entry.pfa->blendshapeError) << size << " markers";
    EXPECT_LT(entry.greedy->reconstructionRmse, entry.pfa->reconstructionRmse) << size << " markers";
  }
  EXPECT_GT(plan.recommendedSize, 0);
}

TEST(LayoutFrames, PlansEveryLabelledMarkerButTheExcludedOnesByDefault)
{
  const Take take = readTake(test::sampleTake());
  const std::vector<std::string> reference = {"root-1", "root-2", "root-3", "root-4", "root-5", "root-6"};
  const std::vector<std::string> planned = defaultPlannedLabels(take, reference);
  // 38 markers: 6 head references, the unlabelled point Unlabeled1 and 31 face markers.
  ASSERT_EQ(planned.size(), 31u);
  for (const std::string& label : planned)
    EXPECT_EQ(label.rfind("section", 0), 0u) << label;
  EXPECT_EQ(defaultPlannedLabels(take, {}).size(), 37u);
  // collectLayoutFrames plans the same markers when none are named.
  LayoutFramesOptions options;
  options.stabilizeLabels = reference;
  EXPECT_EQ(collectLayoutFrames({take}, options).labels, planned);
}

} // namespace
} // namespace mocap
