#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace mocap {

/// The VMC protocol's default port (the receiver's, as VSeeFace and the Blender add-ons listen).
inline constexpr int kVmcPort = 39539;

/// One frame as the VMC protocol (OSC over UDP) carries it, in one bundle: a
/// `/VMC/Ext/Blend/Val` (name, value) per weight, then `/VMC/Ext/Blend/Apply` so the receiver
/// shows them together, then a `/VMC/Ext/Tra/Pos` (name, x, y, z, qx, qy, qz, qw) per marker with
/// a finite position (a missing sample is left out, never sent as a made-up place), rotation the
/// identity. Names are as given: ARKit's for "PerfectSync" avatars. `positions` holds x, y, z per
/// marker in metres (VMC's unit), or is empty. The buffer is cleared first and reused. Throws
/// InvalidArgument when the sizes disagree. O(#weights + #markers).
void encodeVmcFrame(const std::vector<std::string>& names, const Eigen::Ref<const Eigen::RowVectorXf>& values,
                    const std::vector<std::string>& markerNames,
                    const Eigen::Ref<const Eigen::RowVectorXf>& positions, std::vector<std::uint8_t>& out);

} // namespace mocap
