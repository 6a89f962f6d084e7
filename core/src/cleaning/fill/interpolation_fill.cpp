#include "mocap/cleaning/fill/interpolation_fill.h"

#include <algorithm>
#include <vector>

namespace mocap {

namespace {

constexpr const char* kNeedsBothSides = "the gap touches the first or last frame and interpolation needs "
                                        "valid samples on both sides";

// First frame of the valid run ending at `frame` (walking back at most `limit` frames).
Eigen::Index runStart(const GapQuery& gap, Eigen::Index frame, Eigen::Index limit)
{
  Eigen::Index f = frame;
  while (f > 0 && frame - f < limit && gap.markerValid(f - 1))
    --f;
  return f;
}

// Last frame of the valid run starting at `frame` (walking on at most `limit` frames).
Eigen::Index runEnd(const GapQuery& gap, Eigen::Index frame, Eigen::Index limit)
{
  Eigen::Index f = frame;
  while (f + 1 < gap.take.frameCount() && f - frame < limit && gap.markerValid(f + 1))
    ++f;
  return f;
}

} // namespace

GapPrediction predictLinear(const GapQuery& gap)
{
  if (gap.atEdge())
    return GapPrediction::failure(kNeedsBothSides);
  const Eigen::RowVector3d start = gap.at(gap.before());
  const Eigen::RowVector3d end = gap.at(gap.after());
  GapPrediction prediction;
  prediction.method = "linear";
  prediction.positions.resize(gap.length, 3);
  const double span = static_cast<double>(gap.length + 1);
  for (Eigen::Index i = 0; i < gap.length; ++i) {
    const double s = static_cast<double>(i + 1) / span;
    prediction.positions.row(i) = (1.0 - s) * start + s * end;
  }
  return prediction;
}

GapPrediction predictSpline(const GapQuery& gap)
{
  if (gap.atEdge())
    return GapPrediction::failure(kNeedsBothSides);
  const Eigen::Index spacing = std::max<Eigen::Index>(1, (gap.length + 1) / 2);
  std::vector<Eigen::Index> knots;
  const Eigen::Index outerBefore = runStart(gap, gap.before(), spacing);
  if (outerBefore < gap.before())
    knots.push_back(outerBefore);
  knots.push_back(gap.before());
  knots.push_back(gap.after());
  const Eigen::Index outerAfter = runEnd(gap, gap.after(), spacing);
  if (outerAfter > gap.after())
    knots.push_back(outerAfter);

  // Lagrange form through the knots: only frame differences enter, so it stays well conditioned.
  GapPrediction prediction;
  prediction.method = "spline";
  prediction.positions.setZero(gap.length, 3);
  for (std::size_t k = 0; k < knots.size(); ++k) {
    const Eigen::RowVector3d value = gap.at(knots[k]);
    for (Eigen::Index i = 0; i < gap.length; ++i) {
      const auto t = static_cast<double>(gap.first + i);
      double basis = 1.0;
      for (std::size_t j = 0; j < knots.size(); ++j)
        if (j != k)
          basis *= (t - static_cast<double>(knots[j])) / static_cast<double>(knots[k] - knots[j]);
      prediction.positions.row(i) += basis * value;
    }
  }
  return prediction;
}

} // namespace mocap
