#include "mocap/cleaning/border_blend.h"

#include "mocap/base/error.h"
#include "mocap/math/smooth_step.h"

namespace mocap {

Eigen::Matrix<double, Eigen::Dynamic, 3> blendBorders(const GapQuery& gap, const BorderedTrack& track,
                                                      BorderRamp ramp)
{
  if (track.rows() != gap.length + 2)
    throw InvalidArgument("blendBorders: the track needs length + 2 rows");
  const bool hasBefore = gap.before() >= 0;
  const bool hasAfter = gap.after() >= 0;
  Eigen::RowVector3d before = Eigen::RowVector3d::Zero();
  Eigen::RowVector3d after = Eigen::RowVector3d::Zero();
  if (hasBefore)
    before = gap.at(gap.before()) - track.row(0);
  if (hasAfter)
    after = gap.at(gap.after()) - track.row(gap.length + 1);
  Eigen::Matrix<double, Eigen::Dynamic, 3> out = track.middleRows(1, gap.length);
  const double span = static_cast<double>(gap.length + 1);
  for (Eigen::Index i = 0; i < gap.length; ++i) {
    double s = hasBefore ? (hasAfter ? static_cast<double>(i + 1) / span : 0.0) : 1.0;
    if (ramp == BorderRamp::Smooth)
      s = smoothStep(s);
    out.row(i) += (1.0 - s) * before + s * after;
  }
  return out;
}

} // namespace mocap
