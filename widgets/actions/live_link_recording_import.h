#pragma once

#include <QString>

#include <optional>
#include <string>

namespace mocap::ui {

class BlendshapeSolveModel;
class TakeDocument;

/// Opens a Live Link Face recording (the CSV Epic's app writes) as the weight curves of the loaded
/// rig, as `mocap convert REC.csv OUT --rig RIG [--map MAP]` reads it (liveLinkFaceWeightsOnRig):
/// its 52 curves through `map` (a shipped map's name or a map file) or, when none, the default
/// for the rig's names (rigMapFromLiveLinkFace); one row per recorded sample, shown at the take's
/// frames from the first, or, when the recording's rate is not the take's, resampled to the
/// take's rate by its timecodes (resampleLiveLinkFace); the rate, the first timecode and the head's
/// yaw, pitch and roll kept for exports (ReadWeightCurves). Undoable: pushed on the document's stack (ReplaceWeightCurvesCommand).
/// Returns "" or why nothing changed (no rig, an unreadable or malformed file, a map that does not
/// fit the rig, fewer than two samples). O(the file's size + #rows · #shapes).
QString openLiveLinkRecording(TakeDocument& document, BlendshapeSolveModel& model, const QString& path,
                              const std::optional<std::string>& map);

} // namespace mocap::ui
