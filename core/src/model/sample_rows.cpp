#include "mocap/model/sample_rows.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"

#include <cstdint>
#include <limits>

namespace mocap {

void appendSampleRows(std::string& out, const Take& take, char separator)
{
  if (take.firstFrame() > std::numeric_limits<std::int64_t>::max() - take.frameCount())
    throw InvalidArgument("first frame " + std::to_string(take.firstFrame()) + " overflows the frame numbers");
  out.reserve(out.size() + static_cast<std::size_t>(take.frameCount() * (24 + 30 * take.markerCount())));
  const std::string emptySample(3, separator);
  for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
    out += std::to_string(take.firstFrame() + f);
    out += separator;
    appendNumber(out, take.timeOf(f));
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      const Eigen::Vector3d p = take.position(f, m);
      if (!take.isValid(f, m) || !p.allFinite()) {
        out += emptySample;
        continue;
      }
      for (Eigen::Index axis = 0; axis < 3; ++axis) {
        out += separator;
        appendNumber(out, p[axis]);
      }
    }
    out += '\n';
  }
}

} // namespace mocap
