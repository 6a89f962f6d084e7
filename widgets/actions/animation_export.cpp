#include "actions/animation_export.h"

#include "dialogs/export_dialog.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"

#include <QMessageBox>

namespace mocap::ui {

void exportAnimation(const StudioSession& session, QWidget& dialogParent)
{
  ExportDialog dialog(session.document(), &dialogParent);
  const FaceMeshModel& mesh = session.faceMesh();
  if (mesh.rig()) {
    try {  // the export runs on a worker thread: with a rig of its own
      dialog.setMeshSource(mesh.mesh(), mesh.detachedDeformer(), QStringLiteral("face"));
    } catch (const std::exception& e) {
      QMessageBox::warning(&dialogParent, ExportDialog::tr("Export Animation"),
                           ExportDialog::tr("The face mesh cannot be exported: %1").arg(QString::fromStdString(e.what())));
    }
  }
  dialog.exec();
}

} // namespace mocap::ui
