#pragma once

#include "mocap/io/live_link_face_csv.h"

namespace mocap {

/// A Live Link Face recording at `rate` samples per second, so its rows meet a take's frames one to
/// one: row k at the first timecode + k / rate, for every such time up to the last timecode, each
/// weight and rotation linearly interpolated in time between the recorded rows around it (by their
/// timecodes, so a row the app dropped leaves no shift behind it); the timecodes are written anew.
/// Throws InvalidArgument for a rate that is not finite and > 0, fewer than two rows, or timecodes
/// that do not increase (naming the row). O(#rows + #rows at `rate`) · 61.
[[nodiscard]] LiveLinkFaceRecording resampleLiveLinkFace(const LiveLinkFaceRecording& recording, double rate);

} // namespace mocap
