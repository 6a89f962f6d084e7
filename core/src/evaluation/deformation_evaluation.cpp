#include "mocap/evaluation/deformation_evaluation.h"

#include "mocap/base/error.h"
#include "mocap/base/random.h"
#include "mocap/deform/laplacian_deformer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mocap {

void LeaveOutResult::add(double error, double restDistance)
{
  m_sum += error;
  m_squares += error * error;
  m_restSum += restDistance;
  maxError = std::max(maxError, error);
  ++samples;
}

void LeaveOutResult::finish()
{
  if (samples == 0)
    return;
  const auto n = static_cast<double>(samples);
  meanError = m_sum / n;
  rmsError = std::sqrt(m_squares / n);
  restError = m_restSum / n;
}

std::vector<Eigen::Index> chooseHiddenMarkers(std::size_t count, const LeaveOutOptions& options)
{
  if (count < 2)
    throw InvalidArgument("leave-out: needs at least 2 bound markers");
  if (!(options.fraction > 0.0 && options.fraction < 1.0))
    throw InvalidArgument("leave-out: the hidden fraction must be in (0, 1)");
  const auto hiddenCount = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(options.fraction * static_cast<double>(count))), 1, count - 1);
  std::vector<Eigen::Index> order(count);
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  Random(options.seed).shuffle(order.begin(), order.end());
  std::vector<Eigen::Index> hidden(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(hiddenCount));
  std::sort(hidden.begin(), hidden.end());
  return hidden;
}

LeaveOutResult evaluateLeaveOut(const Take& take, const std::vector<Eigen::Index>& markers,
                                const std::vector<MeshPoint>& points, Eigen::Index neutralFrame,
                                const Retarget& retarget, const MeshVertices& rest, const DeformerFactory& factory,
                                const LeaveOutOptions& options)
{
  if (markers.size() != points.size())
    throw InvalidArgument("leave-out: needs one bound point per marker");
  LeaveOutResult result;
  result.hidden = chooseHiddenMarkers(markers.size(), options);
  const std::size_t count = markers.size();

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
      result.add((hiddenPoints[h].on(deformed) - actual).norm() / retarget.uniformScale,
                 truth.row(row).norm() / retarget.uniformScale);
    }
  }
  result.finish();
  return result;
}

LeaveOutResult evaluateBlendshapeLeaveOut(const BlendshapeSolver& solver, const Take& take,
                                          const LeaveOutOptions& options)
{
  const std::vector<Eigen::Index>& markers = solver.markers();
  LeaveOutResult result;
  result.hidden = chooseHiddenMarkers(markers.size(), options);
  std::vector<bool> use(markers.size(), true);
  for (const Eigen::Index h : result.hidden)
    use[static_cast<std::size_t>(h)] = false;
  const BlendshapeSolveResult solved = solver.solve(take, use);
  std::vector<Eigen::Index> hiddenMarkers;
  PointSet hiddenNeutral(static_cast<Eigen::Index>(result.hidden.size()), 3);  // the frame's, or an actor's
  for (std::size_t i = 0; i < result.hidden.size(); ++i) {
    hiddenMarkers.push_back(markers[static_cast<std::size_t>(result.hidden[i])]);
    hiddenNeutral.row(static_cast<Eigen::Index>(i)) = solver.neutralMarkers().row(result.hidden[i]);
  }
  const Retarget& retarget = solver.retarget();
  PointSet truth;
  std::vector<bool> present;
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    if (solved.held[static_cast<std::size_t>(f)])
      continue;
    controlDisplacements(take, hiddenMarkers, hiddenNeutral, retarget, f, truth, present);
    const Eigen::VectorXd w = solved.weights.row(f).transpose();
    for (std::size_t i = 0; i < result.hidden.size(); ++i) {
      if (!present[i])
        continue;
      const Eigen::Vector3d predicted = solver.shapeMatrix().middleRows<3>(3 * result.hidden[i]) * w;
      const auto row = static_cast<Eigen::Index>(i);
      result.add((predicted - truth.row(row).transpose()).norm() / retarget.uniformScale,
                 truth.row(row).norm() / retarget.uniformScale);
    }
  }
  result.finish();
  return result;
}

} // namespace mocap
