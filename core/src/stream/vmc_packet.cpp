#include "mocap/stream/vmc_packet.h"

#include "mocap/base/error.h"
#include "mocap/stream/osc_packet.h"

#include <cmath>

namespace mocap {

void encodeVmcFrame(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::RowVectorXf>& values,
                    const std::vector<std::string>& markerNames,
                    const Eigen::Ref<const Eigen::RowVectorXf>& positions, std::vector<std::uint8_t>& out)
{
  if (static_cast<Eigen::Index>(names.size()) != values.size())
    throw InvalidArgument("VMC: " + std::to_string(names.size()) + " names for " + std::to_string(values.size()) +
                          " values");
  if (positions.size() != 0 && 3 * static_cast<Eigen::Index>(markerNames.size()) != positions.size())
    throw InvalidArgument("VMC: " + std::to_string(markerNames.size()) + " marker names for " +
                          std::to_string(positions.size()) + " coordinates");
  OscBundleWriter bundle(out);
  for (std::size_t i = 0; i < names.size(); ++i) {
    bundle.beginMessage("/VMC/Ext/Blend/Val", "sf");
    bundle.addString(names[i]);
    bundle.addFloat(values(static_cast<Eigen::Index>(i)));
    bundle.endMessage();
  }
  if (!names.empty()) {
    bundle.beginMessage("/VMC/Ext/Blend/Apply", "");
    bundle.endMessage();
  }
  for (Eigen::Index m = 0; m < positions.size() / 3; ++m) {
    const auto xyz = positions.segment<3>(3 * m);
    if (!xyz.allFinite())
      continue;
    bundle.beginMessage("/VMC/Ext/Tra/Pos", "sfffffff");
    bundle.addString(markerNames[static_cast<std::size_t>(m)]);
    for (Eigen::Index axis = 0; axis < 3; ++axis)
      bundle.addFloat(xyz(axis));
    for (const float q : {0.0F, 0.0F, 0.0F, 1.0F})
      bundle.addFloat(q);
    bundle.endMessage();
  }
}

} // namespace mocap
