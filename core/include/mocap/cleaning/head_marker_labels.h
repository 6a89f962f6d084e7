#pragma once

#include "mocap/model/take.h"

#include <vector>

namespace mocap {

/// The markers whose labels start with "root" or "head" (any case; after a subject prefix
/// "Subject:" when there is one), the usual names of head-mounted markers, when there are at least three; else empty. Named by the take, not
/// guessed: the studio uses them without asking, while a rigid cluster (mostRigidCluster in
/// head_stabilization.h) is only proposed. O(#markers).
[[nodiscard]] std::vector<Eigen::Index> labelledHeadMarkers(const Take& take);

} // namespace mocap
