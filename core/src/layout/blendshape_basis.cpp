#include "mocap/layout/blendshape_basis.h"

#include "mocap/math/bounded_least_squares.h"
#include "mocap/base/error.h"

#include <algorithm>
#include <set>
#include <string>

namespace mocap {

namespace {

std::vector<Eigen::Index> allRows(Eigen::Index count)
{
  std::vector<Eigen::Index> rows(static_cast<std::size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i)
    rows[static_cast<std::size_t>(i)] = i;
  return rows;
}

void checkRow(Eigen::Index row, Eigen::Index count, const char* what)
{
  if (row < 0 || row >= count)
    throw InvalidArgument(std::string(what) + " " + std::to_string(row) + " is outside the " +
                          std::to_string(count) + " frames");
}

} // namespace

Eigen::Index findNeutralFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                              const std::vector<Eigen::Index>& candidates)
{
  const std::vector<Eigen::Index> rows = candidates.empty() ? allRows(frames.rows()) : candidates;
  if (rows.empty())
    throw InvalidArgument("neutral frame: there are no frames");
  for (const Eigen::Index r : rows)
    checkRow(r, frames.rows(), "neutral frame: candidate");
  Eigen::RowVectorXd median(frames.cols());
  std::vector<double> column(rows.size());
  for (Eigen::Index c = 0; c < frames.cols(); ++c) {
    for (std::size_t i = 0; i < rows.size(); ++i)
      column[i] = frames(rows[i], c);
    const auto middle = column.begin() + static_cast<std::ptrdiff_t>(column.size() / 2);
    std::nth_element(column.begin(), middle, column.end());
    median(c) = *middle;
  }
  Eigen::Index best = rows.front();
  double bestDistance = (frames.row(best) - median).squaredNorm();
  for (const Eigen::Index r : rows) {
    const double d = (frames.row(r) - median).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = r;
    }
  }
  return best;
}

std::vector<Eigen::Index> chooseKeyPoses(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                         Eigen::Index neutralFrame, Eigen::Index count,
                                         const std::vector<Eigen::Index>& candidates)
{
  if (count < 1)
    throw InvalidArgument("key poses: the count must be at least 1, not " + std::to_string(count));
  checkRow(neutralFrame, frames.rows(), "key poses: neutral frame");
  const std::vector<Eigen::Index> rows = candidates.empty() ? allRows(frames.rows()) : candidates;
  for (const Eigen::Index r : rows)
    checkRow(r, frames.rows(), "key poses: candidate");
  // nearest[i]: squared distance of candidate i to the neutral and every pose chosen so far.
  Eigen::VectorXd nearest(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    nearest(static_cast<Eigen::Index>(i)) = (frames.row(rows[i]) - frames.row(neutralFrame)).squaredNorm();
  std::vector<Eigen::Index> chosen;
  while (static_cast<Eigen::Index>(chosen.size()) < count && nearest.size() > 0) {
    Eigen::Index farthest = 0;
    if (!(nearest.maxCoeff(&farthest) > 0.0))
      break;
    const Eigen::Index row = rows[static_cast<std::size_t>(farthest)];
    chosen.push_back(row);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto ii = static_cast<Eigen::Index>(i);
      nearest(ii) = std::min(nearest(ii), (frames.row(rows[i]) - frames.row(row)).squaredNorm());
    }
  }
  return chosen;
}

BlendshapeBasis buildBlendshapeBasis(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                     Eigen::Index neutralFrame, const std::vector<Eigen::Index>& keyFrames)
{
  if (keyFrames.empty())
    throw InvalidArgument("blendshape basis: there are no key poses");
  checkRow(neutralFrame, frames.rows(), "blendshape basis: neutral frame");
  std::set<Eigen::Index> seen;
  for (const Eigen::Index r : keyFrames) {
    checkRow(r, frames.rows(), "blendshape basis: key pose frame");
    if (r == neutralFrame)
      throw InvalidArgument("blendshape basis: the neutral frame " + std::to_string(r) +
                            " is also a key pose");
    if (!seen.insert(r).second)
      throw InvalidArgument("blendshape basis: key pose frame " + std::to_string(r) + " is given twice");
  }
  BlendshapeBasis basis;
  basis.neutralFrame = neutralFrame;
  basis.keyFrames = keyFrames;
  basis.neutral = frames.row(neutralFrame);
  if (!basis.neutral.allFinite())
    throw InvalidArgument("blendshape basis: the neutral frame is not finite");
  basis.deltas.resize(frames.cols(), static_cast<Eigen::Index>(keyFrames.size()));
  for (std::size_t j = 0; j < keyFrames.size(); ++j)
    basis.deltas.col(static_cast<Eigen::Index>(j)) = (frames.row(keyFrames[j]) - basis.neutral).transpose();
  if (!basis.deltas.allFinite())
    throw InvalidArgument("blendshape basis: a key pose is not finite");
  return basis;
}

Eigen::MatrixXd solveBlendshapeWeights(const BlendshapeBasis& basis,
                                       const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                       const std::vector<Eigen::Index>& markers,
                                       const std::vector<Eigen::Index>& rows)
{
  if (frames.cols() != basis.deltas.rows() || frames.cols() % 3 != 0)
    throw InvalidArgument("blendshape weights: frames of " + std::to_string(frames.cols()) +
                          " values for a basis of " + std::to_string(basis.deltas.rows()));
  const Eigen::Index markerCount = frames.cols() / 3;
  std::vector<Eigen::Index> coordinates;
  for (const Eigen::Index m : markers.empty() ? allRows(markerCount) : markers) {
    if (m < 0 || m >= markerCount)
      throw InvalidArgument("blendshape weights: marker " + std::to_string(m) + " out of range");
    for (Eigen::Index axis = 0; axis < 3; ++axis)
      coordinates.push_back(3 * m + axis);
  }
  const std::vector<Eigen::Index> used = rows.empty() ? allRows(frames.rows()) : rows;
  for (const Eigen::Index r : used)
    checkRow(r, frames.rows(), "blendshape weights: row");
  const Eigen::Index k = basis.keyPoseCount();
  const Eigen::MatrixXd a = basis.deltas(coordinates, Eigen::all);
  const BoundedLeastSquares solver(a, Eigen::VectorXd::Zero(k), Eigen::VectorXd::Ones(k));
  const Eigen::MatrixXd at = a.transpose();
  const Eigen::RowVectorXd neutral = basis.neutral(coordinates);
  Eigen::MatrixXd weights(static_cast<Eigen::Index>(used.size()), k);
  Eigen::VectorXd previous, b, atb;
  BoundedLeastSquares::Workspace workspace;
  for (std::size_t i = 0; i < used.size(); ++i) {
    b = (frames(used[i], coordinates) - neutral).transpose();
    if (!b.allFinite())
      throw InvalidArgument("blendshape weights: frame " + std::to_string(used[i]) + " is not finite");
    atb.noalias() = at * b;
    solver.solveNormal(atb, previous, i > 0, workspace);
    weights.row(static_cast<Eigen::Index>(i)) = previous.transpose();
  }
  return weights;
}

} // namespace mocap
