#include "vertex_range.h"

#include "cli_error.h"

#include <cstdio>

namespace mocap::cli {

std::pair<Eigen::Index, Eigen::Index> parseVertexRange(const std::string& text, Eigen::Index vertexCount)
{
  long long first = 0, last = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lld:%lld%c", &first, &last, &tail) != 2 || first < 0 || last < first ||
      last >= vertexCount)
    throw UsageError("--vertices needs FIRST:LAST vertex indices of the mesh (0…" + std::to_string(vertexCount - 1) +
                     "), not '" + text + "'");
  return {static_cast<Eigen::Index>(first), static_cast<Eigen::Index>(last)};
}

} // namespace mocap::cli
