#include "vertex_range.h"

#include "cli_error.h"

#include "mocap/base/error.h"
#include "mocap/base/index_range.h"

namespace mocap::cli {

std::pair<Eigen::Index, Eigen::Index> parseVertexRange(const std::string& text, Eigen::Index vertexCount)
{
  try {
    const IndexRange range = parseIndexRange(text, 0, vertexCount - 1);
    return {static_cast<Eigen::Index>(range.first), static_cast<Eigen::Index>(range.last)};
  } catch (const InvalidArgument& e) {
    throw UsageError("--vertices needs FIRST:LAST vertex indices of the mesh (0…" + std::to_string(vertexCount - 1) +
                     "), not '" + text + "': " + e.what());
  }
}

} // namespace mocap::cli
