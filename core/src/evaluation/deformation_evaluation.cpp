#include "mocap/evaluation/deformation_evaluation.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/deform/laplacian_deformer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mocap {

LeaveOutResult evaluateLeaveOut(const Take& take, const std::vector<Eigen::Index>& markers,
                                const std::vector<MeshPoint>& points, Eigen::Index neutralFrame,
                                const Retarget& retarget, const MeshVertices& rest, const DeformerFactory& factory,
                                const LeaveOutOptions& options)
{
  if (markers.size() < 2 || markers.size() != points.size())
    throw InvalidArgument("leave-out: needs at least 2 bound markers, one point each");
  if (!(options.fraction > 0.0 && options.fraction < 1.0))
    throw InvalidArgument("leave-out: the hidden fraction must be in (0, 1)");
  const std::size_t count = markers.size();
  const auto hiddenCount = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(options.fraction * static_cast<double>(count))), 1, count - 1);
  std::vector<Eigen::Index> order(count);
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  Random(options.seed).shuffle(order.begin(), order.end());
  LeaveOutResult result;
  result.hidden.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(hiddenCount));
  std::sort(result.hidden.begin(), result.hidden.end());

  std::vector<Eigen::Index> keptMarkers, hiddenMarkers;
  std::vector<MeshPoint> keptPoints, hiddenPoints;
  for (std::size_t i = 0; i < count; ++i) {
    const bool hidden = std::binary_search(result.hidden.begin(), result.hidden.end(), static_cast<Eigen::Index>(i));
    (hidden ? hiddenMarkers : keptMarkers).push_back(markers[i]);
    (hidden ? hiddenPoints : keptPoints).push_back(points[i]);
  }
  std::unique_ptr<MeshDeformer> deformer = factory(keptPoints);
  const PointSet hiddenRest = boundPositions(rest, hiddenPoints);
  PointSet kept, truth;
  std::vector<bool> keptPresent, truthPresent;
  MeshVertices deformed;
  double sum = 0.0, squares = 0.0, restSum = 0.0;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    controlDisplacements(take, hiddenMarkers, neutralFrame, retarget, f, truth, truthPresent);
    if (std::none_of(truthPresent.begin(), truthPresent.end(), [](bool p) { return p; }))
      continue;
    controlDisplacements(take, keptMarkers, neutralFrame, retarget, f, kept, keptPresent);
    deformFrame(*deformer, kept, keptPresent, options.rotations, deformed);
    for (std::size_t h = 0; h < hiddenPoints.size(); ++h) {
      if (!truthPresent[h])
        continue;
      const auto row = static_cast<Eigen::Index>(h);
      const Eigen::Vector3d actual = hiddenRest.row(row).transpose() + truth.row(row).transpose();
      const double error = (hiddenPoints[h].on(deformed) - actual).norm() / retarget.uniformScale;
      sum += error;
      squares += error * error;
      result.maxError = std::max(result.maxError, error);
      restSum += truth.row(row).norm() / retarget.uniformScale;
      ++result.samples;
    }
  }
  if (result.samples > 0) {
    const auto n = static_cast<double>(result.samples);
    result.meanError = sum / n;
    result.rmsError = std::sqrt(squares / n);
    result.restError = restSum / n;
  }
  return result;
}

} // namespace mocap
