#pragma once

#include "mocap/model/take.h"

#include <string>
#include <vector>

namespace mocap {

/// Vicon Plug-in Gait's virtual points in a file that does not list them (issue 30). Nexus and
/// Workstation write each body segment's axes as four points, origin O, anterior A, lateral L and
/// proximal P ("PELO", "LFEA", "Anna:RTIL"…), and the body's CentreOfMass and CentreOfMassFloor,
/// among the markers and in none of POINT:ANGLES, FORCES, MOMENTS or POWERS. They are a model's
/// output, not positions a camera saw.

/// Types as PointType::Virtual, among the points of `take` still typed Marker:
/// - the four points of a Plug-in Gait segment (PEL, LFE, RTI, HED, TRX, LHU… followed by O, A, L,
///   P, behind one subject prefix) when all four are in the take and are axes: in every frame where
///   the four are valid (at least one), A−O, L−O and P−O are at right angles (|cos| ≤ 0.02), which
///   markers on a body or a face never keep;
/// - CentreOfMass and CentreOfMassFloor (behind a subject prefix too) when the take holds other
///   model outputs (listed in the file, or the segments above).
/// So a take's own labels are never typed by their names alone. Returns the labels typed, in take
/// order. O(#points + #frames · #segments).
std::vector<std::string> typeViconVirtualPoints(Take& take);

} // namespace mocap
