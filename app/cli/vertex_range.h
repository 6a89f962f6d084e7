#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>

namespace mocap::cli {

/// The vertices FIRST…LAST of `--vertices FIRST:LAST` (both included; parseIndexRange's form) on
/// a mesh of `vertexCount` vertices. Throws UsageError naming the text and what is wrong for
/// another form or a range that is reversed or leaves the mesh. O(|text|).
[[nodiscard]] std::pair<Eigen::Index, Eigen::Index> parseVertexRange(const std::string& text, Eigen::Index vertexCount);

} // namespace mocap::cli
