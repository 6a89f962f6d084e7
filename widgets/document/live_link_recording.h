#pragma once

#include "mocap/io/live_link_face_csv.h"
#include "mocap/model/retarget_map.h"

#include <Eigen/Core>

#include <optional>

namespace mocap::ui {

class StudioSession;

/// The head's yaw, pitch and roll per frame (#frames × 3, radians) in the face mesh's axes, from
/// the head motion the face mesh's stabilization removes: Live Link Face's HeadYaw, HeadPitch and
/// HeadRoll. Empty (zeros for a writer) when the face mesh is not stabilized or not placed.
/// O(#frames).
[[nodiscard]] Eigen::MatrixXd solvedHeadRotation(const StudioSession& session);

/// The session's solved weights as a Live Link Face recording at the take's rate (through `map`,
/// else the default map for the rig's names) with solvedHeadRotation, or the head turn of the
/// recording the curves were read from: what the live stream sends. Throws InvalidArgument without a solve, or as
/// liveLinkFaceRecordingOfRig. O(#frames · 61).
[[nodiscard]] LiveLinkFaceRecording sessionLiveLinkRecording(const StudioSession& session,
                                                             const std::optional<RetargetMap>& map = std::nullopt);

} // namespace mocap::ui
