#include "mocap/deform/retarget.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/cleaning/head_stabilization.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mocap {

namespace {

constexpr EnumTable<RetargetScale, 2> kScales{{{
    {RetargetScale::Uniform, "uniform"},
    {RetargetScale::PerAxis, "per-axis"},
}}};

} // namespace

std::string_view retargetScaleName(RetargetScale scale)
{
  return kScales.name(scale, "per-axis");
}

std::string retargetScaleNames()
{
  return kScales.names();
}

std::optional<RetargetScale> parseRetargetScale(std::string_view name)
{
  return kScales.parse(name);
}

Retarget fitRetarget(const Eigen::Ref<const PointSet>& neutral, const Eigen::Ref<const PointSet>& bound,
                     RetargetScale scale)
{
  const Similarity similarity = fitSimilarity(neutral, bound);
  Retarget retarget;
  retarget.rotation = similarity.rotation;
  retarget.uniformScale = similarity.scale;
  retarget.axisScale.setConstant(similarity.scale);
  if (scale == RetargetScale::PerAxis) {
    const PointSet rotated = neutral * similarity.rotation.transpose();
    const Eigen::RowVector3d rotatedSpread = (rotated.rowwise() - rotated.colwise().mean()).colwise().norm();
    const Eigen::RowVector3d boundSpread = (bound.rowwise() - bound.colwise().mean()).colwise().norm();
    for (int a = 0; a < 3; ++a)
      if (rotatedSpread(a) > 1e-3 * rotatedSpread.maxCoeff() && boundSpread(a) > 0.0)
        retarget.axisScale(a) = boundSpread(a) / rotatedSpread(a);
  }
  return retarget;
}

PointSet markerPositions(const Take& take, Eigen::Index frame, const std::vector<Eigen::Index>& markers)
{
  PointSet positions(static_cast<Eigen::Index>(markers.size()), 3);
  for (std::size_t i = 0; i < markers.size(); ++i)
    positions.row(static_cast<Eigen::Index>(i)) = take.position(frame, markers[i]).transpose();
  return positions;
}

Eigen::Index chooseNeutralFrame(const Take& take, const std::vector<Eigen::Index>& markers,
                                std::optional<long long> frameNumber)
{
  const auto complete = [&](Eigen::Index f) {
    for (const Eigen::Index m : markers)
      if (!take.isValid(f, m) || !take.position(f, m).allFinite())
        return false;
    return true;
  };
  if (frameNumber) {
    const long long index = *frameNumber - take.firstFrame();
    if (index < 0 || index >= take.frameCount())
      throw InvalidArgument("neutral frame " + std::to_string(*frameNumber) + " is outside the take (frames " +
                            std::to_string(take.firstFrame()) + "…" +
                            std::to_string(take.firstFrame() + take.frameCount() - 1) + ")");
    const auto frame = static_cast<Eigen::Index>(index);
    for (const Eigen::Index m : markers)
      if (!take.isValid(frame, m))
        throw InvalidArgument("neutral frame " + std::to_string(*frameNumber) + ": marker " + take.label(m) +
                              " is missing there");
    return frame;
  }
  for (Eigen::Index f = 0; f < take.frameCount(); ++f)
    if (complete(f))
      return f;
  throw InvalidArgument("no frame has every bound marker; give --neutral FRAME");
}

std::vector<Eigen::Index> stabilizeTake(Take& take, const std::vector<std::string>& labels)
{
  if (labels.empty())
    return {};
  std::vector<Eigen::Index> reference = markerIndices(take, labels);
  removeHeadMotion(take, estimateHeadMotion(take, reference));
  return reference;
}

void controlDisplacements(const Take& take, const std::vector<Eigen::Index>& markers, Eigen::Index neutralFrame,
                          const Retarget& retarget, Eigen::Index frame, PointSet& displacements,
                          std::vector<bool>& present)
{
  controlDisplacements(take, markers, markerPositions(take, neutralFrame, markers), retarget, frame, displacements,
                       present);
}

void controlDisplacements(const Take& take, const std::vector<Eigen::Index>& markers,
                          const Eigen::Ref<const PointSet>& neutral, const Retarget& retarget, Eigen::Index frame,
                          PointSet& displacements, std::vector<bool>& present)
{
  displacements.setZero(static_cast<Eigen::Index>(markers.size()), 3);
  present.assign(markers.size(), false);
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const Eigen::Index m = markers[i];
    const Eigen::Vector3d delta = take.position(frame, m) - neutral.row(static_cast<Eigen::Index>(i)).transpose();
    if (!take.isValid(frame, m) || !delta.allFinite())
      continue;
    present[i] = true;
    displacements.row(static_cast<Eigen::Index>(i)) = retarget.map(delta).transpose();
  }
}

PointSet boundPositions(const Eigen::Ref<const MeshVertices>& vertices, const std::vector<MeshPoint>& points)
{
  PointSet positions(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    positions.row(static_cast<Eigen::Index>(i)) = points[i].on(vertices).transpose();
  return positions;
}

bool BoundTake::fits(const Take& take) const
{
  return neutral < take.frameCount() &&
         std::all_of(markers.begin(), markers.end(), [&](Eigen::Index m) { return m < take.markerCount(); });
}

namespace {

/// The binding's markers found in `take` and their points on `rest`; no neutral yet.
BoundTake bindLabels(const MeshBinding& binding, const Take& take, const Eigen::Ref<const MeshVertices>& rest)
{
  if (binding.meshVertices != 0 && binding.meshVertices != rest.rows())
    throw InvalidArgument("the binding was made for a mesh of " + std::to_string(binding.meshVertices) +
                          " vertices, not " + std::to_string(rest.rows()));
  BoundTake bound;
  for (const MarkerBinding& marker : binding.markers) {
    bound.labels.push_back(marker.label);
    bound.points.push_back(marker.point);
  }
  bound.markers = markerIndices(take, bound.labels);
  bound.boundPoints = boundPositions(rest, bound.points);
  return bound;
}

} // namespace

BoundTake bindTake(const MeshBinding& binding, const Take& take, const Eigen::Ref<const MeshVertices>& rest,
                   std::optional<long long> neutralFrame, RetargetScale scale)
{
  BoundTake bound = bindLabels(binding, take, rest);
  bound.neutral = chooseNeutralFrame(take, bound.markers, neutralFrame);
  bound.neutralMarkers = markerPositions(take, bound.neutral, bound.markers);
  bound.retarget = fitRetarget(bound.neutralMarkers, bound.boundPoints, scale);
  return bound;
}

BoundTake bindTakeToNeutral(const MeshBinding& binding, const Take& take, const Eigen::Ref<const MeshVertices>& rest,
                            const Eigen::Ref<const PointSet>& neutral, RetargetScale scale)
{
  BoundTake bound = bindLabels(binding, take, rest);
  if (neutral.rows() != static_cast<Eigen::Index>(bound.markers.size()) || neutral.cols() != 3)
    throw InvalidArgument("the neutral has " + std::to_string(neutral.rows()) + " positions for " +
                          std::to_string(bound.markers.size()) + " bound markers");
  bound.neutral = -1;
  bound.neutralMarkers = neutral;
  bound.retarget = fitRetarget(bound.neutralMarkers, bound.boundPoints, scale);
  return bound;
}

} // namespace mocap
