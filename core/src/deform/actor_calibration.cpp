#include "mocap/deform/actor_calibration.h"

#include "mocap/base/error.h"
#include "mocap/deform/blendshape_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace mocap {

namespace {

double median(std::vector<double>& values)
{
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1)
    return *middle;
  return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

/// The largest running median of `window` consecutive values (the whole column when shorter).
double largestRunningMedian(const Eigen::Ref<const Eigen::VectorXd>& values, int window)
{
  const Eigen::Index n = values.size(), w = std::min<Eigen::Index>(std::max(window, 1), n);
  double best = n > 0 ? -std::numeric_limits<double>::infinity() : 0.0;
  std::vector<double> span(static_cast<std::size_t>(w));
  for (Eigen::Index start = 0; start + w <= n; ++start) {
    for (Eigen::Index i = 0; i < w; ++i)
      span[static_cast<std::size_t>(i)] = values(start + i);
    best = std::max(best, median(span));
  }
  return best;
}

} // namespace

PointSet neutralFromFrame(const Take& take, const std::vector<std::string>& labels, long long frameNumber)
{
  const std::vector<Eigen::Index> markers = markerIndices(take, labels);
  const long long index = frameNumber - take.firstFrame();
  if (index < 0 || index >= take.frameCount())
    throw InvalidArgument("neutral frame " + std::to_string(frameNumber) + " is outside the take (frames " +
                          std::to_string(take.firstFrame()) + "…" +
                          std::to_string(take.firstFrame() + take.frameCount() - 1) + ")");
  const auto frame = static_cast<Eigen::Index>(index);
  std::string missing;
  for (std::size_t i = 0; i < markers.size(); ++i)
    if (!take.isValid(frame, markers[i]) || !take.position(frame, markers[i]).allFinite())
      missing += (missing.empty() ? "" : ", ") + labels[i];
  if (!missing.empty())
    throw InvalidArgument("neutral frame " + std::to_string(frameNumber) + ": the bound markers " + missing +
                          " are missing there; choose a frame with every bound marker");
  PointSet neutral(static_cast<Eigen::Index>(markers.size()), 3);
  for (std::size_t i = 0; i < markers.size(); ++i)
    neutral.row(static_cast<Eigen::Index>(i)) = take.position(frame, markers[i]).transpose();
  return neutral;
}

PointSet neutralFromTake(const Take& take, const std::vector<std::string>& labels)
{
  const std::vector<Eigen::Index> markers = markerIndices(take, labels);
  PointSet neutral(static_cast<Eigen::Index>(markers.size()), 3);
  std::vector<double> values;
  for (std::size_t i = 0; i < markers.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      values.clear();
      for (Eigen::Index f = 0; f < take.frameCount(); ++f)
        if (take.isValid(f, markers[i]) && take.position(f, markers[i]).allFinite())
          values.push_back(take.position(f, markers[i])(c));
      if (values.empty())
        throw InvalidArgument("the neutral take has no sample of the bound marker " + labels[i]);
      neutral(static_cast<Eigen::Index>(i), c) = median(values);
    }
  return neutral;
}

ActorProfile makeActorProfile(std::string name, const MeshBinding& binding, const BlendshapeRig& rig,
                              const PointSet& neutral, LengthUnit units, std::string neutralSource)
{
  ActorProfile profile;
  profile.name = std::move(name);
  profile.units = units;
  for (const MarkerBinding& marker : binding.markers)
    profile.labels.push_back(marker.label);
  profile.neutral = neutral;
  profile.neutralSource = std::move(neutralSource);
  profile.shapes = rig.shapeNames();
  const auto shapes = static_cast<Eigen::Index>(profile.shapes.size());
  profile.extent = Eigen::VectorXd::Ones(shapes);
  profile.romMaximum = Eigen::VectorXd::Constant(shapes, std::numeric_limits<double>::quiet_NaN());
  profile.binding = binding;
  checkActorProfile(profile);
  return profile;
}

ActorRange calibrateActorRange(ActorProfile& profile, const BlendshapeRig& rig, const Take& rom,
                               const std::string& romSource, const ActorRangeOptions& options,
                               const JobControl& control)
{
  if (rig.shapeNames() != profile.shapes)
    throw InvalidArgument("the actor profile was made for another rig (its shapes differ from this rig's)");
  if (rom.units() != profile.units)
    throw InvalidArgument("the range-of-motion take is in " + std::string(unitName(rom.units())) +
                          ", the actor's neutral in " + std::string(unitName(profile.units)));
  auto unscaled = std::make_shared<ActorProfile>(profile);
  unscaled->extent.setOnes();
  BlendshapeSolveOptions settings;
  settings.method = BlendshapeSolveMethod::Bvls;
  settings.maximumWeight = options.maximumWeight;
  settings.actor = unscaled;
  Eigen::MatrixXd weights;
  try {
    const BlendshapeSolver solver(rig, profile.binding, rom, settings);
    weights = solver.solve(rom, {}, control).weights;
  } catch (const InvalidArgument& error) {
    throw InvalidArgument(std::string("the range-of-motion take: ") + error.what());
  }
  ActorRange range;
  const auto shapes = static_cast<Eigen::Index>(profile.shapes.size());
  range.maximum.resize(shapes);
  for (Eigen::Index s = 0; s < shapes; ++s) {
    const double maximum = largestRunningMedian(weights.col(s), options.window);
    range.maximum(s) = maximum;
    range.reached.push_back(maximum >= options.reachedWeight);
    range.clipped.push_back(maximum >= options.maximumWeight * (1.0 - 1e-6));
    // A shape at the bound is more likely one the markers cannot see than a fourfold exaggeration.
    profile.extent(s) = range.reached.back() && !range.clipped.back() ? maximum : 1.0;
  }
  profile.romMaximum = range.maximum;
  profile.romSource = romSource;
  return range;
}

} // namespace mocap
