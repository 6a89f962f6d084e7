#include "document/live_link_recording.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"

#include "mocap/base/error.h"
#include "mocap/cleaning/head_angles.h"
#include "mocap/io/live_link_face_map.h"

namespace mocap::ui {

Eigen::MatrixXd solvedHeadRotation(const StudioSession& session)
{
  const FaceMeshModel& faceMesh = session.faceMesh();
  const TakeDocument& document = session.document();
  const std::vector<std::string>& labels = faceMesh.stabilization();
  if (labels.empty())
    return {};
  const std::shared_ptr<const HeadMotion> motion = document.headMotion(markerIndices(document.take(), labels));
  const std::optional<Eigen::Affine3d> meshToLab = motion ? faceMesh.meshToLab(motion->referenceFrame) : std::nullopt;
  if (!meshToLab)
    return {};
  // The mesh's axes in the lab at the reference frame, where the head has not turned yet.
  return headYawPitchRoll(*motion, meshToLab->rotation().transpose());
}

LiveLinkFaceRecording sessionLiveLinkRecording(const StudioSession& session, const std::optional<RetargetMap>& map)
{
  const BlendshapeSolveModel& solve = session.blendshapes();
  if (!solve.hasResult() || !solve.rig())
    throw InvalidArgument("solve the take to a rig first (Blendshape Solve dock)");
  // Curves read from a recording keep its head turn; a solve's comes from the stabilization.
  const std::optional<ReadWeightCurves>& read = solve.readCurves();
  return liveLinkFaceRecordingOfRig(solve.rig()->shapeNames(), solve.weights(), map,
                                    session.document().take().frameRate(),
                                    read ? read->headRotation : solvedHeadRotation(session));
}

} // namespace mocap::ui
