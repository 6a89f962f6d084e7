#include "document/session_files.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"

#include "mocap/deform/blendshape_solver.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/mesh_io.h"
#include "mocap/io/rig_io.h"

#include <QFileInfo>

#include <exception>
#include <memory>

namespace mocap::ui {

namespace {

QString failed(const QString& path, const std::exception& e)
{
  return QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(e.what()));
}

void loadRig(StudioSession& session, const SessionFiles& files)
{
  session.setBlendshapeRig(
      std::make_shared<const BlendshapeRig>(readRig(files.rig.toStdString(), files.rigShapes.toStdString())), files.rig,
      files.rigShapes);
}

QString solve(StudioSession& session)
{
  const FaceMeshModel& face = session.faceMesh();
  BlendshapeSolveModel& model = session.blendshapes();
  if (!model.hasRig())
    return QStringLiteral("--solve needs a rig");
  if (face.binding().markers.empty())
    return QStringLiteral("the rig's neutral has no marker binding; give one with --binding");
  BlendshapeSolveOptions options;
  options.neutralFrame = face.options().neutralFrame;
  options.scale = face.options().scale;
  const BlendshapeSolver solver(*model.rig(), face.binding(), face.rigTake(), options);
  (void)model.setResult(solver.solve(face.rigTake()), options);
  return {};
}

} // namespace

QString loadSessionFiles(StudioSession& session, const SessionFiles& files)
{
  try {
    session.document().open(TakeDocument::read(files.take), files.take);
  } catch (const std::exception& e) {
    return failed(files.take, e);
  }
  FaceMeshModel& face = session.faceMesh();
  if (!files.mesh.isEmpty()) {
    try {
      face.setMesh(readMesh(files.mesh.toStdString()), files.mesh);
    } catch (const std::exception& e) {
      return failed(files.mesh, e);
    }
  }
  if (!files.rig.isEmpty()) {
    try {
      loadRig(session, files);
    } catch (const std::exception& e) {
      return failed(files.rig, e);
    }
  }
  if (!files.binding.isEmpty()) {
    if (!face.hasMesh())
      return QStringLiteral("a binding needs the mesh it was made on (--mesh or --solve)");
    try {
      face.setBinding(readBinding(files.binding.toStdString(), face.mesh().vertexCount()));
    } catch (const std::exception& e) {
      return failed(files.binding, e);
    }
    if (!face.error().isEmpty())
      return QStringLiteral("%1: %2").arg(QFileInfo(files.binding).fileName(), face.error());
  }
  if (files.solve) {
    try {
      return solve(session);
    } catch (const std::exception& e) {
      return failed(files.rig, e);
    }
  }
  return {};
}

} // namespace mocap::ui
