#include "mocap/deform/actor_profile.h"

#include "mocap/base/error.h"
#include "mocap/math/kabsch.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace mocap {

namespace {

void checkUnique(const std::vector<std::string>& names, const char* what)
{
  std::set<std::string> seen;
  for (const std::string& name : names)
    if (!seen.insert(name).second)
      throw InvalidArgument(std::string("actor profile: the ") + what + " '" + name + "' is listed twice");
}

std::size_t indexOf(const std::vector<std::string>& names, const std::string& name)
{
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

} // namespace

void checkActorProfile(const ActorProfile& profile)
{
  const auto labels = static_cast<Eigen::Index>(profile.labels.size());
  const auto shapes = static_cast<Eigen::Index>(profile.shapes.size());
  if (profile.neutral.rows() != labels || profile.neutral.cols() != 3)
    throw InvalidArgument("actor profile: " + std::to_string(profile.neutral.rows()) + " neutral positions for " +
                          std::to_string(labels) + " markers");
  if (profile.extent.size() != shapes || profile.romMaximum.size() != shapes)
    throw InvalidArgument("actor profile: the extents and maxima must have one value per shape (" +
                          std::to_string(shapes) + ")");
  checkUnique(profile.labels, "marker");
  checkUnique(profile.shapes, "shape");
  for (Eigen::Index m = 0; m < labels; ++m)
    if (!profile.neutral.row(m).allFinite())
      throw InvalidArgument("actor profile: the neutral position of " + profile.labels[static_cast<std::size_t>(m)] +
                            " is not finite");
  for (Eigen::Index s = 0; s < shapes; ++s)
    if (!(std::isfinite(profile.extent(s)) && profile.extent(s) > 0.0))
      throw InvalidArgument("actor profile: the extent of " + profile.shapes[static_cast<std::size_t>(s)] +
                            " must be finite and > 0");
}

PointSet actorNeutral(const ActorProfile& profile, const std::vector<std::string>& labels)
{
  PointSet neutral(static_cast<Eigen::Index>(labels.size()), 3);
  for (std::size_t m = 0; m < labels.size(); ++m) {
    const std::size_t i = indexOf(profile.labels, labels[m]);
    if (i == profile.labels.size())
      throw InvalidArgument("the actor profile has no neutral position for the bound marker " + labels[m]);
    neutral.row(static_cast<Eigen::Index>(m)) = profile.neutral.row(static_cast<Eigen::Index>(i));
  }
  return neutral;
}

PointSet placeActorNeutral(const Eigen::Ref<const PointSet>& neutral, const Take& take,
                           const std::vector<Eigen::Index>& markers, Eigen::Index frame)
{
  const auto presentIn = [&](Eigen::Index f) {
    std::vector<Eigen::Index> rows;
    for (std::size_t i = 0; i < markers.size(); ++i)
      if (take.isValid(f, markers[i]) && take.position(f, markers[i]).allFinite())
        rows.push_back(static_cast<Eigen::Index>(i));
    return rows;
  };
  std::vector<Eigen::Index> rows;
  if (frame >= 0 && frame < take.frameCount()) {
    rows = presentIn(frame);
  } else {
    for (Eigen::Index f = 0; f < take.frameCount() && rows.size() < markers.size(); ++f)
      if (std::vector<Eigen::Index> present = presentIn(f); present.size() > rows.size()) {
        rows = std::move(present);
        frame = f;
      }
  }
  if (rows.size() < 3)
    throw InvalidArgument("no frame of the take has 3 of the bound markers to place the actor's neutral");
  const auto count = static_cast<Eigen::Index>(rows.size());
  PointSet from(count, 3), to(count, 3);
  for (Eigen::Index i = 0; i < count; ++i) {
    from.row(i) = neutral.row(rows[static_cast<std::size_t>(i)]);
    to.row(i) = take.position(frame, markers[static_cast<std::size_t>(rows[static_cast<std::size_t>(i)])]).transpose();
  }
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(count);
  Eigen::Isometry3d transform = kabsch(from, to, weights);
  const Eigen::Index kept = std::max<Eigen::Index>(3, (6 * count + 9) / 10);
  for (int round = 0; round < 5; ++round) {
    Eigen::VectorXd residual(count);
    for (Eigen::Index i = 0; i < count; ++i)
      residual(i) = (transform * Eigen::Vector3d(from.row(i).transpose()) - to.row(i).transpose()).norm();
    std::vector<double> sorted(residual.data(), residual.data() + count);
    std::nth_element(sorted.begin(), sorted.begin() + (kept - 1), sorted.end());
    const double limit = sorted[static_cast<std::size_t>(kept - 1)];
    for (Eigen::Index i = 0; i < count; ++i)
      weights(i) = residual(i) <= limit ? 1.0 : 0.0;
    transform = kabsch(from, to, weights);
  }
  PointSet placed(neutral.rows(), 3);
  for (Eigen::Index m = 0; m < neutral.rows(); ++m)
    placed.row(m) = (transform * Eigen::Vector3d(neutral.row(m).transpose())).transpose();
  return placed;
}

Eigen::VectorXd actorExtents(const ActorProfile& profile, const std::vector<std::string>& shapes)
{
  Eigen::VectorXd extent(static_cast<Eigen::Index>(shapes.size()));
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const std::size_t i = indexOf(profile.shapes, shapes[s]);
    if (i == profile.shapes.size())
      throw InvalidArgument("the actor profile was made for another rig: it has no shape " + shapes[s]);
    extent(static_cast<Eigen::Index>(s)) = profile.extent(static_cast<Eigen::Index>(i));
  }
  return extent;
}

} // namespace mocap
