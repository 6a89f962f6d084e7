#pragma once

#include "mocap/model/take.h"

#include <string>
#include <vector>

namespace mocap::test {

/// Takes shaped like files from other vendors' systems, built in code for the C3D tests (issue 30):
/// write one with encodeC3d, break or check it, read it back.

/// `markers` points "P1".. over `frames` frames at 100 Hz, every sample valid with residual 2, and
/// `channels` analog channels sampled `samples` times per frame; every value differs (position of
/// marker m in frame f: m·1000 + f), so bytes read from the wrong place show.
[[nodiscard]] Take distinctValuesTake(int markers, int frames, int channels = 0, int samples = 1);

/// A Vicon Nexus export in miniature: the marker LASI and the model outputs LHipAngles,
/// LHipForce, LHipMoment, LHipPower, LHipScalar and RHipAngles over 4 frames, named in
/// POINT:ANGLES (with "NotInTheTake"), FORCES, MOMENTS and POWERS; with `typeGroups`, also
/// POINT:SCALARS and POINT:TYPE_GROUPS naming all five lists. The take's point types are set
/// from those lists, as a reader would (the writer writes the lists from the types).
[[nodiscard]] Take nexusStyleTake(bool typeGroups);

/// A longer Nexus-style take for cleaning and statistics: the markers LASI, RASI, LPSI, RPSI (a
/// rigid body turning and moving smoothly, with a little noise) and the model outputs LHipAngles,
/// RHipAngles, LHipForce, LHipMoment, LHipPower (curves of tens of units) over `frames` frames at
/// 100 Hz, named in POINT:ANGLES, FORCES, MOMENTS and POWERS. Point m misses the 5 frames from
/// 40 + 5m and jumps by 40 units in frame 120, so a step that touched an output would change it.
/// `frames` ≥ 150.
[[nodiscard]] Take nexusCleaningTake(Eigen::Index frames = 200);

/// A Vicon Plug-in Gait export in miniature, every label behind `prefix` ("" or "Anna:"), over 30
/// frames at 100 Hz, no model-output list in the parameters: the markers LASI, RASI, SACR; the
/// pelvis's virtual points PELO, PELA, PELL, PELP (an origin and the ends of three right-angled
/// 100 mm axes, turning and moving; PELA misses frames 10–12); CentreOfMass and CentreOfMassFloor;
/// an incomplete femur LFEO, LFEA, LFEL (right-angled, no LFEP); and a tibia LTIO, LTIA, LTIL, LTIP
/// whose lateral axis is 45° off the anterior one (four markers that happen to have those names).
[[nodiscard]] Take plugInGaitTake(const std::string& prefix);

/// The point type of each point of `take`, in order.
[[nodiscard]] std::vector<PointType> pointTypes(const Take& take);

} // namespace mocap::test
