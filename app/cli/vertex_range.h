#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>

namespace mocap::cli {

/// The vertices FIRST…LAST of `--vertices FIRST:LAST` (both included) on a mesh of `vertexCount`
/// vertices. Throws UsageError for another form or a range that is empty or leaves the mesh. O(1).
[[nodiscard]] std::pair<Eigen::Index, Eigen::Index> parseVertexRange(const std::string& text, Eigen::Index vertexCount);

} // namespace mocap::cli
