// Actor profiles (issue 32): the profile's JSON, its bad input, and the evaluation on a synthetic
// different actor: the bundled ICT rig's face with another neutral shape (a smooth deformation)
// whose expressions reach their own extent per shape (jaw 0.7 of the rig's delta, smile 1.3, the
// others log-uniform in [0.6, 1.6]); a neutral take, a range-of-motion take reaching each shape's
// maximum once, and a performance driven by known weights in the actor's range (1 = the actor's
// maximum). Prints the figures the issue asks for and asserts its target.
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/random.h"
#include "mocap/deform/actor_calibration.h"
#include "mocap/deform/actor_profile_io.h"
#include "mocap/deform/blendshape_solver.h"
#include "mocap/io/rig_io.h"
#include "checkout_paths.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

namespace mocap {
namespace actor_profile_test {
namespace {

constexpr double kRate = 100.0;
constexpr double kNoiseMm = 0.2;

const BlendshapeRig& ictRig()
{
  static const BlendshapeRig rig = readRig(std::filesystem::path(checkout::sampleDir()) / "ict_face_rig.glb", {});
  return rig;
}

const MeshBinding& sampleBinding()
{
  static const MeshBinding binding = readBinding(
      std::filesystem::path(checkout::sampleDir()) / "Facial-Sing.ict_face_rig.binding.json", 9409);
  return binding;
}

/// The synthetic actor: its neutral bound points (mesh units) and each shape's range factor.
struct Actor
{
  PointSet neutral;            // #markers × 3, cm
  Eigen::MatrixXd shapes;      // 3·#markers × #shapes: the rig's deltas at the bound points, cm
  Eigen::VectorXd factor;      // the actor's full expression over the rig's, per shape
};

Actor differentActor()
{
  const BlendshapeRig& rig = ictRig();
  const MeshBinding& binding = sampleBinding();
  Actor actor;
  const auto markers = static_cast<Eigen::Index>(binding.markers.size());
  actor.neutral.resize(markers, 3);
  actor.shapes.resize(3 * markers, rig.shapeCount());
  for (Eigen::Index m = 0; m < markers; ++m) {
    const MeshPoint& point = binding.markers[static_cast<std::size_t>(m)].point;
    const Eigen::Vector3d p = point.on(rig.neutral.vertices);
    // Another face: 6 % wider, 4 % shorter, the lower face 3 mm further forward (smooth in y).
    actor.neutral.row(m) = Eigen::RowVector3d(1.06 * p.x(), 0.96 * p.y(), p.z() + 0.3 / (1.0 + std::exp(p.y())));
    for (Eigen::Index s = 0; s < rig.shapeCount(); ++s) {
      const SparseShape& shape = rig.shapes[static_cast<std::size_t>(s)];
      Eigen::Vector3d delta = Eigen::Vector3d::Zero();
      for (int c = 0; c < 3; ++c)
        delta += point.weights(c) * shape.deltaOf(point.vertices[static_cast<std::size_t>(c)]);
      actor.shapes.block<3, 1>(3 * m, s) = delta;
    }
  }
  Random random(32);
  actor.factor.resize(rig.shapeCount());
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s)
    actor.factor(s) = std::exp(std::log(0.6) + (std::log(1.6) - std::log(0.6)) * random.uniform());
  const std::vector<std::string> names = rig.shapeNames();
  for (std::size_t s = 0; s < names.size(); ++s) {
    if (names[s] == "jawOpen")
      actor.factor(static_cast<Eigen::Index>(s)) = 0.7;
    if (names[s] == "mouthSmile_L" || names[s] == "mouthSmile_R")
      actor.factor(static_cast<Eigen::Index>(s)) = 1.3;
  }
  return actor;
}

/// The actor's markers for weights `u` (#frames × #shapes, the actor's range) in the take's
/// frame (mm, through the binding's alignment), the head at `turn` degrees about the vertical and
/// moved by `shift` mm (takes recorded apart), with noise.
Take actorTake(const Actor& actor, const Eigen::MatrixXd& u, std::uint64_t seed, double turn = 0.0,
               const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  const Eigen::Matrix3d head = Eigen::AngleAxisd(turn * std::acos(-1.0) / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const MeshBinding& binding = sampleBinding();
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : binding.markers)
    labels.push_back(marker.label);
  Take take(labels, u.rows(), kRate);
  const Similarity& align = binding.alignment;  // take → mesh
  Random noise(seed);
  for (Eigen::Index f = 0; f < u.rows(); ++f) {
    const Eigen::VectorXd offsets = actor.shapes * actor.factor.cwiseProduct(u.row(f).transpose());
    for (Eigen::Index m = 0; m < actor.neutral.rows(); ++m) {
      const Eigen::Vector3d mesh = actor.neutral.row(m).transpose() + offsets.segment<3>(3 * m);
      const Eigen::Vector3d seen = align.rotation.transpose() * (mesh - align.translation) / align.scale;
      take.setPosition(f, m, head * seen + shift + kNoiseMm * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal()));
      take.valid()(f, m) = true;
    }
  }
  return take;
}

/// Each shape alone: up over 10 frames, held 5, down over 10, after 10 neutral frames.
Eigen::MatrixXd rangeOfMotion(Eigen::Index shapes)
{
  constexpr Eigen::Index kSpan = 35;
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(10 + kSpan * shapes, shapes);
  for (Eigen::Index s = 0; s < shapes; ++s)
    for (Eigen::Index i = 0; i < 25; ++i)
      u(10 + kSpan * s + i, s) = i < 10 ? static_cast<double>(i + 1) / 10.0 : i < 15 ? 1.0 : static_cast<double>(24 - i) / 10.0;
  return u;
}

/// A performance: every shape fires two raised-cosine pulses (0.3–1 high, 0.4–1 s long), so
/// several overlap at a time; frames 0–19 are the neutral.
Eigen::MatrixXd performance(Eigen::Index shapes, Eigen::Index frames)
{
  Random random(2032);
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(frames, shapes);
  for (Eigen::Index s = 0; s < shapes; ++s)
    for (int pulse = 0; pulse < 2; ++pulse) {
      const double length = 40.0 + 60.0 * random.uniform(), height = 0.3 + 0.7 * random.uniform();
      const double start = 20.0 + (static_cast<double>(frames) - 20.0 - length) * random.uniform();
      for (Eigen::Index f = 0; f < frames; ++f) {
        const double t = (static_cast<double>(f) - start) / length;
        if (t > 0.0 && t < 1.0)
          w(f, s) = std::min(1.0, w(f, s) + height * 0.5 * (1.0 - std::cos(2.0 * std::acos(-1.0) * t)));
      }
    }
  return w;
}

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  const Eigen::VectorXd x = a.array() - a.mean(), y = b.array() - b.mean();
  const double norm = x.norm() * y.norm();
  return norm > 0.0 ? x.dot(y) / norm : 0.0;
}

/// The least-squares slope of `solved` on `truth` (with an intercept).
double slope(const Eigen::VectorXd& solved, const Eigen::VectorXd& truth)
{
  const Eigen::VectorXd x = truth.array() - truth.mean(), y = solved.array() - solved.mean();
  return x.dot(y) / x.squaredNorm();
}

double rms(const std::vector<double>& values)
{
  double sum = 0.0;
  for (const double v : values)
    sum += v * v;
  return values.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(values.size()));
}

/// The calibration the issue warns about: each extent the shape's maximum in the usual (temporal,
/// GCV) solve of the range-of-motion take, i.e. a gain of 1 / that maximum and nothing else (no
/// range-of-motion source, so the solve does not also undo its shrinkage).
ActorProfile naiveProfile(const Actor& actor, ActorProfile profile)
{
  const BlendshapeRig& rig = ictRig();
  const Take rom = actorTake(actor, rangeOfMotion(rig.shapeCount()), 8, -3.0, Eigen::Vector3d(-4.0, 6.0, 2.0));
  profile.extent.setOnes();
  profile.romSource.clear();
  BlendshapeSolveOptions options;
  options.actor = std::make_shared<const ActorProfile>(profile);
  const Eigen::MatrixXd w = BlendshapeSolver(rig, sampleBinding(), rom, options).solve(rom).weights;
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s)
    profile.extent(s) = std::max(w.col(s).maxCoeff(), 0.05);
  return profile;
}

ActorProfile calibratedProfile(const Actor& actor, ActorRange* range = nullptr)
{
  const BlendshapeRig& rig = ictRig();
  const Take neutral = actorTake(actor, Eigen::MatrixXd::Zero(200, rig.shapeCount()), 7);
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : sampleBinding().markers)
    labels.push_back(marker.label);
  ActorProfile profile = makeActorProfile("synthetic", sampleBinding(), rig, neutralFromTake(neutral, labels),
                                          neutral.units(), "neutral take (median)");
  const Take rom = actorTake(actor, rangeOfMotion(rig.shapeCount()), 8, -3.0, Eigen::Vector3d(-4.0, 6.0, 2.0));
  const ActorRange found = calibrateActorRange(profile, rig, rom, "rom");
  if (range)
    *range = found;
  return profile;
}

TEST(ActorProfile, OnADifferentActorTheCalibrationCutsTheRangeError)
{
  const BlendshapeRig& rig = ictRig();
  const Actor actor = differentActor();
  ActorRange range;
  const auto profile = std::make_shared<const ActorProfile>(calibratedProfile(actor, &range));
  const Eigen::MatrixXd truth = performance(rig.shapeCount(), 1500);
  const Take take = actorTake(actor, truth, 9, 5.0, Eigen::Vector3d(12.0, -5.0, 3.0));

  BlendshapeSolveOptions plain;
  const BlendshapeSolveResult without = BlendshapeSolver(rig, sampleBinding(), take, plain).solve(take);
  BlendshapeSolveOptions calibrated;
  calibrated.actor = profile;
  const BlendshapeSolveResult with = BlendshapeSolver(rig, sampleBinding(), take, calibrated).solve(take);
  BlendshapeSolveOptions naive;
  naive.actor = std::make_shared<const ActorProfile>(naiveProfile(actor, *profile));
  const BlendshapeSolveResult withNaive = BlendshapeSolver(rig, sampleBinding(), take, naive).solve(take);

  std::vector<double> logGainFactor, logFactor, logSlopeWith, logSlopeWithout, logNaiveGainFactor, logNaiveSlope,
      logExtentFactor;
  int unreached = 0;
  std::cout << "shape              factor  extent   slope without  slope with\n";
  for (Eigen::Index s = 0; s < rig.shapeCount(); ++s) {
    unreached += range.reached[static_cast<std::size_t>(s)] ? 0 : 1;
    if (correlation(without.weights.col(s), truth.col(s)) <= 0.9)
      continue;
    const double slopeWithout = slope(without.weights.col(s), truth.col(s));
    const double slopeWith = slope(with.weights.col(s), truth.col(s));
    const double gain = slopeWith / slopeWithout;
    logGainFactor.push_back(std::log(gain * actor.factor(s)));
    logNaiveGainFactor.push_back(std::log(slope(withNaive.weights.col(s), truth.col(s)) / slopeWithout * actor.factor(s)));
    logNaiveSlope.push_back(std::log(slope(withNaive.weights.col(s), truth.col(s))));
    logExtentFactor.push_back(std::log(profile->extent(s) / actor.factor(s)));
    logFactor.push_back(std::log(actor.factor(s)));
    logSlopeWith.push_back(std::log(slopeWith));
    logSlopeWithout.push_back(std::log(slopeWithout));
    std::cout << rig.shapes[static_cast<std::size_t>(s)].name << "  " << actor.factor(s) << "  "
              << profile->extent(s) << "  " << slopeWithout << "  " << slopeWith << "\n";
  }
  const auto weightRms = [&](const Eigen::MatrixXd& w) {
    return std::sqrt((w - truth).squaredNorm() / static_cast<double>(truth.size()));
  };
  std::cout << logFactor.size() << " of " << rig.shapeCount() << " shapes seen (correlation > 0.9); " << unreached
            << " not reached in the range-of-motion take\n"
            << "RMS log(extent / factor) " << rms(logExtentFactor) << "\nRMS log(gain × factor) " << rms(logGainFactor)
            << " (no profile: RMS log(factor) " << rms(logFactor)
            << "; gain 1 / the ROM maximum of the usual solve: " << rms(logNaiveGainFactor)
            << ")\nRMS log(slope) with the profile " << rms(logSlopeWith) << ", without " << rms(logSlopeWithout)
            << " (ratio " << rms(logSlopeWith) / rms(logSlopeWithout) << "; 1 / the ROM maximum of the usual solve: "
            << rms(logNaiveSlope) << ")"
            << "\nweight RMS error with the profile " << weightRms(with.weights) << ", without "
            << weightRms(without.weights) << "\n";
  // Measured with g++ (46 shapes seen): RMS log(slope) 0.075 against 0.370 (0.20×), the extents
  // within RMS log 0.042 of the true factors (0.16× RMS log(factor) 0.260), weight RMS error 0.035
  // against 0.052; clang (45 shapes seen): 0.070 against 0.361 (0.19×), extents within RMS log
  // 0.048, weight RMS error 0.034 against 0.050. The gain × factor measure is
  // no longer the one to meet: undoing the solver's shrinkage makes the gain 1 / the slope without
  // the profile, so gain × factor is 1 / that solve's own shrinkage (0.258, about RMS log(factor));
  // the calibration is checked directly by its extents instead. Before the solve undid its
  // shrinkage (extents alone, the rig's λ kept), RMS log(slope) was 0.175 against 0.370 (0.47×;
  // clang's sanitizer build 0.51×): the true factors as extents gave 0.171, as the ridge's
  // shrinkage (GCV's λ) stays; and gain × factor 0.125 (0.48×, clang 0.52×) could not go below
  // 0.117 with the true factors either, since the solve without a profile measures from one noisy
  // frame, which moves GCV's λ (0.0063 against 0.0040) and each shape's shrinkage with it.
  // 1 / the usual solve's ROM maximum, the calibration the issue warns about: RMS log(slope) 0.132,
  // gain × factor 0.356 (worse than none).
  ASSERT_GE(logFactor.size(), 10u);
  EXPECT_LE(rms(logSlopeWith), 0.5 * rms(logSlopeWithout));
  EXPECT_LE(rms(logExtentFactor), 0.25 * rms(logFactor));
  EXPECT_LT(rms(logSlopeWith), rms(logNaiveSlope));
  EXPECT_LT(rms(logGainFactor), rms(logNaiveGainFactor));
  EXPECT_LT(weightRms(with.weights), weightRms(without.weights));
}

TEST(ActorProfile, ACalibratedProfileReportsTheActorsFullExpressionAsOne)
{
  // The actor holds one shape the ridge shrinks (mouthPress_L: the solve reports about 0.8 of it
  // alone) at its full extent: with the range-of-motion calibration the weight is 1, the solve's
  // own shrinkage undone; the same extents without a range-of-motion source keep it.
  const BlendshapeRig& rig = ictRig();
  const Actor actor = differentActor();
  const std::vector<std::string> names = rig.shapeNames();
  const auto press = static_cast<Eigen::Index>(std::find(names.begin(), names.end(), "mouthPress_L") - names.begin());
  ASSERT_LT(press, rig.shapeCount());
  Eigen::MatrixXd held = Eigen::MatrixXd::Zero(300, rig.shapeCount());
  held.block(50, press, 250, 1).setOnes();
  const Take take = actorTake(actor, held, 11, 2.0);
  BlendshapeSolveOptions calibrated;
  calibrated.actor = std::make_shared<const ActorProfile>(calibratedProfile(actor));
  ActorProfile extentsOnly = *calibrated.actor;
  extentsOnly.romSource.clear();
  BlendshapeSolveOptions plain;
  plain.actor = std::make_shared<const ActorProfile>(extentsOnly);
  const auto meanHeld = [&](const BlendshapeSolveOptions& options) {
    const Eigen::MatrixXd w = BlendshapeSolver(rig, sampleBinding(), take, options).solve(take).weights;
    return w.block(100, press, 200, 1).mean();
  };
  EXPECT_NEAR(meanHeld(calibrated), 1.0, 0.06);
  EXPECT_LT(meanHeld(plain), 0.9);
}

TEST(ActorProfile, TheProfileChangesTheWeightsUnitNotTheirShrinkage)
{
  // The actor's neutral is the take's first frame, as the solve without a profile takes it, the
  // profile has no range-of-motion take (so the solve keeps its shrinkage) and no weight comes
  // near either bound: the weights with the profile times the extents are then the
  // weights without it (λ by GCV, the ridge solve being exact). Scaling the shape matrix by the
  // extents instead weighs each shape's ridge by 1 / extent² and moves GCV's λ.
  const BlendshapeRig& rig = ictRig();
  const Actor actor = differentActor();
  const Take take = actorTake(actor, 0.5 * performance(rig.shapeCount(), 200), 5);
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : sampleBinding().markers)
    labels.push_back(marker.label);
  ActorProfile profile = makeActorProfile("frame", sampleBinding(), rig, neutralFromFrame(take, labels, take.firstFrame()),
                                          take.units(), "first frame");
  profile.extent = actor.factor;
  BlendshapeSolveOptions plain;
  plain.method = BlendshapeSolveMethod::Ridge;
  BlendshapeSolveOptions calibrated = plain;
  calibrated.actor = std::make_shared<const ActorProfile>(profile);
  const BlendshapeSolveResult without = BlendshapeSolver(rig, sampleBinding(), take, plain).solve(take);
  const BlendshapeSolveResult with = BlendshapeSolver(rig, sampleBinding(), take, calibrated).solve(take);
  EXPECT_EQ(with.lambda, without.lambda);
  EXPECT_LT((with.weights * actor.factor.asDiagonal() - without.weights).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ActorProfile, WithoutAProfileTheSolveIsUnchanged)
{
  const BlendshapeRig& rig = ictRig();
  const Actor actor = differentActor();
  const Take take = actorTake(actor, performance(rig.shapeCount(), 200), 3);
  BlendshapeSolveOptions options;
  options.method = BlendshapeSolveMethod::Bvls;
  const BlendshapeSolver solver(rig, sampleBinding(), take, options);
  EXPECT_EQ(solver.neutralFrame(), 0);
  EXPECT_LE(solver.solve(take).weights.maxCoeff(), 1.0);
}

TEST(ActorProfile, RoundTripsThroughJsonAndRefusesBadFiles)
{
  const Actor actor = differentActor();
  ActorProfile profile = calibratedProfile(actor);
  test::TempDir dir;
  const std::filesystem::path path = dir.file("actor.json");
  writeActorProfile(path, profile);
  const ActorProfile read = readActorProfile(path);
  EXPECT_EQ(read.labels, profile.labels);
  EXPECT_EQ(read.shapes, profile.shapes);
  EXPECT_TRUE(read.neutral.isApprox(profile.neutral, 1e-12));
  EXPECT_TRUE(read.extent.isApprox(profile.extent, 1e-12));
  EXPECT_EQ(read.binding.markers.size(), profile.binding.markers.size());
  EXPECT_EQ(read.romSource, "rom");

  const std::string text = readFileBytes(path);
  const auto refuses = [&](std::string broken, const std::string& message) {
    try {
      (void)parseActorProfile(broken, "actor.json");
      ADD_FAILURE() << "accepted a profile that should say: " << message;
    } catch (const FormatError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
  };
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string copy = text;
    copy.replace(copy.find(from), from.size(), to);
    return copy;
  };
  refuses(replaced("\"mocap actor profile\"", "\"mocap retarget map\""), "\"format\"");
  refuses(replaced("\"version\": 1", "\"version\": 2"), "\"version\"");
  refuses(replaced("\"units\": \"mm\"", "\"unit\": \"mm\""), "\"unit\"");
  refuses(replaced("\"extent\": ", "\"extent\": -"), "extent");
  refuses(replaced("\"shapes\"", "\"shapez\""), "\"shapez\"");
}

TEST(ActorProfile, BadInputGivesClearErrors)
{
  const BlendshapeRig& rig = ictRig();
  const Actor actor = differentActor();
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : sampleBinding().markers)
    labels.push_back(marker.label);
  Take neutral = actorTake(actor, Eigen::MatrixXd::Zero(20, rig.shapeCount()), 1);
  neutral.valid()(4, 2) = false;  // frame 5 (a take numbers frames from 1)
  try {
    (void)neutralFromFrame(neutral, labels, 5);
    ADD_FAILURE() << "a neutral frame with a missing marker was accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find(labels[2]), std::string::npos) << error.what();
  }
  ActorProfile profile = makeActorProfile("a", sampleBinding(), rig, neutralFromFrame(neutral, labels, 1),
                                          neutral.units(), "n:1");
  // A range-of-motion take with another marker set.
  Take other = actorTake(actor, Eigen::MatrixXd::Zero(20, rig.shapeCount()), 2);
  other.setLabel(0, "Elsewhere");
  const Eigen::VectorXd before = profile.extent;
  EXPECT_THROW((void)calibrateActorRange(profile, rig, other, "other"), InvalidArgument);
  EXPECT_EQ(profile.extent, before);
  // A profile made for another rig.
  ActorProfile renamed = profile;
  renamed.shapes[0] = "browDownLeft";
  BlendshapeSolveOptions options;
  options.actor = std::make_shared<const ActorProfile>(renamed);
  try {
    (void)BlendshapeSolver(rig, sampleBinding(), neutral, options);
    ADD_FAILURE() << "a profile for another rig was accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("another rig"), std::string::npos) << error.what();
  }
  // A bound marker the profile lacks.
  ActorProfile fewer = profile;
  fewer.labels[1] = "Nobody";
  options.actor = std::make_shared<const ActorProfile>(fewer);
  EXPECT_THROW((void)BlendshapeSolver(rig, sampleBinding(), neutral, options), InvalidArgument);
  // An unwritable output keeps nothing partial.
  test::TempDir dir;
  EXPECT_THROW(writeActorProfile(dir.file("missing") / "actor.json", profile), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing")));
}

} // namespace
} // namespace actor_profile_test
} // namespace mocap
