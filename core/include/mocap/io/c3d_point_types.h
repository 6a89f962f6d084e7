#pragma once

#include "mocap/model/c3d_parameters.h"
#include "mocap/model/take.h"

#include <string>
#include <utility>
#include <vector>

namespace mocap {

/// How a C3D file says which points are model outputs (Vicon Nexus): label lists in the POINT
/// group, named by POINT:TYPE_GROUPS (pairs of list parameter and type: ANGLES, ANGLE...) or,
/// without it, POINT:ANGLES, FORCES, MOMENTS and POWERS. The reader and the writer share them.

/// The lists `tree` names, with the type of the points each holds (a type name we do not know is
/// Other), in TYPE_GROUPS order. O(#lists).
[[nodiscard]] std::vector<std::pair<std::string, PointType>> c3dPointTypeLists(const C3dParameterTree& tree);

/// Sets each listed point of `take` to its list's type; a listed label the take does not have is
/// ignored. O(#points + #listed labels) expected.
void readC3dPointTypes(const C3dParameterTree& tree, Take& take);

/// Rewrites the lists in `tree` from the take's point types, so a re-read gives the same types:
/// each holds exactly the take's points of its type, in take order (a point keeps the list it was
/// in when several lists have its type). A type without a list gets one (ANGLES, FORCES, MOMENTS,
/// POWERS, OTHERS, VIRTUALS), named in TYPE_GROUPS when the file has one or the type is Other or
/// Virtual (a reader finds only the first four without it); a list of the
/// file whose points are gone is kept, empty; a take of markers only adds nothing.
/// O(#points + #listed labels) expected.
void writeC3dPointTypes(const Take& take, C3dParameterTree& tree);

} // namespace mocap
