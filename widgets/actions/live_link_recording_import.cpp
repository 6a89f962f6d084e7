#include "actions/live_link_recording_import.h"

#include "commands/replace_weight_curves_command.h"
#include "document/blendshape_solve_model.h"
#include "document/take_document.h"

#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/live_link_face_resample.h"
#include "mocap/io/shipped_retarget_maps.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <cmath>
#include <limits>

namespace mocap::ui {

namespace {
/// Rates closer than this share are the same (liveLinkFaceRate rounds a drifting one within it).
constexpr double kSameRate = 0.005;
} // namespace

QString openLiveLinkRecording(TakeDocument& document, BlendshapeSolveModel& model, const QString& path,
                              const std::optional<std::string>& map)
{
  if (!model.hasRig())
    return QCoreApplication::translate("LiveLinkRecordingImport", "Load a rig first: the recording's curves animate its shapes.");
  BlendshapeSolveResult curves;
  ReadWeightCurves read;
  read.path = path;
  try {
    const std::optional<RetargetMap> chosen =
        map ? std::optional<RetargetMap>(readRetargetMapByNameOrPath(*map)) : std::nullopt;
    LiveLinkFaceRecording recording = readLiveLinkFaceCsv(path.toStdString());
    read.recordedRate = liveLinkFaceRate(recording);
    if (!(read.recordedRate > 0.0))
      return QCoreApplication::translate("LiveLinkRecordingImport", "%1: a recording needs two rows or more with increasing timecodes.").arg(QFileInfo(path).fileName());
    // At another rate than the take's, its rows would not meet the take's frames: resampled in time.
    const double takeRate = document.take().frameRate();
    if (std::isfinite(takeRate) && takeRate > 0.0 && std::abs(read.recordedRate - takeRate) > kSameRate * takeRate)
      recording = resampleLiveLinkFace(recording, takeRate);
    read.frameRate = liveLinkFaceRate(recording);
    read.startSeconds = liveLinkFaceSeconds(recording.timecodes.front());
    read.firstTimecode = QString::fromStdString(recording.timecodes.front());
    read.headRotation = recording.rotations;  // the head's and the eyes', written back on export
    curves.weights = liveLinkFaceWeightsOnRig(recording.weights, model.rig()->shapeNames(), chosen);
  } catch (const std::exception& e) {  // a malformed file or a map that does not fit: nothing changes
    return QString::fromStdString(e.what());
  }
  const Eigen::Index rows = curves.weights.rows();
  curves.residual = Eigen::VectorXd::Constant(rows, std::numeric_limits<double>::quiet_NaN());  // no markers
  curves.held.assign(static_cast<std::size_t>(rows), false);
  document.undoStack()->push(new ReplaceWeightCurvesCommand(
      model, QCoreApplication::translate("LiveLinkRecordingImport", "Open Live Link Recording %1").arg(QFileInfo(path).fileName()), std::move(curves), std::move(read)));
  return {};
}

} // namespace mocap::ui
