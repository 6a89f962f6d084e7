#include "views/review_scene.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <stdexcept>

namespace mocap::ui {

namespace {

/// The hidden markers of `document`, ascending. O(#markers).
std::vector<Eigen::Index> hiddenMarkers(const TakeDocument& document)
{
  std::vector<Eigen::Index> hidden;
  for (Eigen::Index m = 0; m < document.take().markerCount(); ++m)
    if (document.isHidden(m))
      hidden.push_back(m);
  return hidden;
}

void applyMeshLook(const SceneSettings& settings, MeshLayer& layer)
{
  layer.setOpacity(settings.meshOpacity);
  layer.setEdgesVisible(settings.meshEdges);
}

} // namespace

ReviewScene::ReviewScene(const ReviewSource& source, QSize size)
    : m_session(std::make_unique<StudioSession>()), m_window(std::make_unique<QWidget>()), m_size(size)
{
  if (!source.session)
    throw std::invalid_argument("ReviewScene: a session is needed");
  // Rendered into a window that is laid out and "shown" but never mapped on the screen.
  m_window->setAttribute(Qt::WA_DontShowOnScreen);
  auto* layout = new QVBoxLayout(m_window.get());
  layout->setContentsMargins(0, 0, 0, 0);
  m_view = new MarkerView3d(m_session->document(), m_window.get());
  layout->addWidget(m_view);
  const qreal ratio = m_window->devicePixelRatioF();
  m_window->setFixedSize(QSize(static_cast<int>(size.width() / ratio), static_cast<int>(size.height() / ratio)));
  m_window->show();
  // The layers first, so they draw what the copied models hold, as the studio's do.
  m_faceMesh = std::make_unique<FaceMeshScene>(m_session->faceMesh(), *m_view);
  m_blendshapes = std::make_unique<BlendshapeScene>(m_session->blendshapes(), m_session->faceMesh(), *m_view);
  copySession(*source.session);
  applyMeshLook(source.settings, m_faceMesh->layer());
  applyMeshLook(source.settings, m_faceMesh->compareLayer());
  m_blendshapes->setBeside(source.settings.rigBeside);
  m_blendshapes->setShown(source.settings.rigShown);
  applyViewSettings(source.settings, *m_view);
}

ReviewScene::~ReviewScene()
{
  // The scenes draw into the view's renderer: they go before the window that holds it.
  m_blendshapes.reset();
  m_faceMesh.reset();
  m_window.reset();
}

void ReviewScene::copySession(const StudioSession& source)
{
  const TakeDocument& from = source.document();
  TakeDocument& document = m_session->document();
  document.setTake(from.take(), from.filePath());
  (void)document.setReferenceMarkers(from.referenceMarkers());
  document.setSelection(from.selection());
  document.setHidden(hiddenMarkers(from), true);

  const FaceMeshModel& face = source.faceMesh();
  if (face.hasMesh()) {
    FaceMeshModel& to = m_session->faceMesh();
    to.setOptions(face.options());
    to.setMesh(face.mesh(), face.meshPath());
    to.setBinding(face.binding());
    to.setCompare(face.compare());
  }
  const BlendshapeSolveModel& rig = source.blendshapes();
  if (rig.hasRig()) {
    BlendshapeSolveModel& to = m_session->blendshapes();
    to.setRig(rig.rig(), rig.rigPath());
    if (rig.hasResult())
      (void)to.setResult(rig.result(), rig.solvedWith());
  }
}

const TakeDocument& ReviewScene::document() const
{
  return m_session->document();
}

void ReviewScene::frameCamera(Eigen::Index first, Eigen::Index last)
{
  TakeDocument& document = m_session->document();
  if (document.take().empty())
    return;
  // The mesh layers are framed where they are drawn: at the first frame reviewed.
  document.setCurrentFrame(std::clamp<Eigen::Index>(first, 0, document.take().frameCount() - 1));
  m_view->frameCamera(first, last);
}

bool ReviewScene::usable() const
{
  return m_view->viewport()->usable();
}

QString ReviewScene::failureReason() const
{
  return m_view->viewport()->failureReason();
}

QImage ReviewScene::render(Eigen::Index frame)
{
  VtkViewport* viewport = m_view->viewport();
  if (!viewport->usable())
    return {};
  m_session->document().setCurrentFrame(frame);
  viewport->requestRender();
  QImage image = viewport->grabFramebuffer();
  if (image.isNull())
    return {};
  if (image.size() != m_size)
    image = image.scaled(m_size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  return image.convertToFormat(QImage::Format_RGB888);
}

} // namespace mocap::ui
