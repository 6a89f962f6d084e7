#include "views/review_scene.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/take_document.h"
#include "views/blendshape_scene.h"
#include "views/face_mesh_scene.h"
#include "views/marker_view_3d.h"
#include "views/mesh_layer.h"
#include "views/vtk_viewport.h"

#include <QVBoxLayout>
#include <QWidget>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <stdexcept>
#include <utility>

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

void copyViewSettings(const MarkerView3d& from, MarkerView3d& to)
{
  to.setUpAxis(from.upAxis());
  to.setTrailFrames(from.trailFrames());
  to.setMarkerScale(from.markerScale());
  to.setLinksVisible(from.linksVisible());
  if (!from.headReference().empty())
    (void)to.setHeadReference(from.headReference());
  to.setFollowHead(from.followHead());
  if (!from.layoutHighlight().empty())
    to.setLayoutHighlight(from.layoutHighlight(), from.layoutReference());
  to.viewport()->renderer()->GetActiveCamera()->DeepCopy(from.viewport()->renderer()->GetActiveCamera());
}

} // namespace

ReviewScene::ReviewScene(const ReviewSource& source, QSize size)
    : m_window(std::make_unique<QWidget>()), m_document(std::make_unique<TakeDocument>()), m_size(size)
{
  if (!source.document || !source.view)
    throw std::invalid_argument("ReviewScene: a document and a 3D view are needed");
  m_document->setTake(source.document->take(), source.document->filePath());
  (void)m_document->setReferenceMarkers(source.document->referenceMarkers());
  m_document->setSelection(source.document->selection());
  m_document->setHidden(hiddenMarkers(*source.document), true);

  // Rendered into a window that is laid out and "shown" but never mapped on the screen.
  m_window->setAttribute(Qt::WA_DontShowOnScreen);
  auto* layout = new QVBoxLayout(m_window.get());
  layout->setContentsMargins(0, 0, 0, 0);
  m_view = new MarkerView3d(*m_document, m_window.get());
  layout->addWidget(m_view);
  const qreal ratio = m_window->devicePixelRatioF();
  m_window->setFixedSize(QSize(static_cast<int>(size.width() / ratio), static_cast<int>(size.height() / ratio)));
  m_window->show();
  copyViewSettings(*source.view, *m_view);
  if (source.faceMesh)
    copyFaceMesh(*source.faceMesh);
  if (source.blendshapes && m_faceMesh)
    copyBlendshapes(*source.blendshapes);
  m_resetCamera = source.resetCamera;
}

ReviewScene::~ReviewScene()
{
  // The scenes draw into the view's renderer: they go before the window that holds it.
  m_blendshapes.reset();
  m_faceMesh.reset();
  m_window.reset();
}

void ReviewScene::copyFaceMesh(const FaceMeshScene& source)
{
  const FaceMeshModel& from = source.model();
  if (!from.hasMesh())
    return;
  m_faceMeshModel = std::make_unique<FaceMeshModel>(*m_document);
  m_faceMeshModel->setOptions(from.options());
  m_faceMeshModel->setStabilization(from.stabilization());
  m_faceMeshModel->setMesh(from.mesh());
  m_faceMeshModel->setBinding(from.binding());
  m_faceMeshModel->setCompare(from.compare());
  m_faceMesh = std::make_unique<FaceMeshScene>(*m_faceMeshModel, *m_view);
  m_faceMesh->layer().copyAppearance(source.layer());
  m_faceMesh->compareLayer().copyAppearance(source.compareLayer());
}

void ReviewScene::copyBlendshapes(const BlendshapeScene& source)
{
  const BlendshapeSolveModel& from = source.model();
  if (!from.hasRig())
    return;
  m_blendshapeModel = std::make_unique<BlendshapeSolveModel>();
  m_blendshapeModel->setRig(from.rig(), from.rigPath());
  if (from.hasResult())
    (void)m_blendshapeModel->setResult(from.result(), from.solvedWith());
  m_blendshapes = std::make_unique<BlendshapeScene>(*m_blendshapeModel, *m_faceMesh, *m_view);
  m_blendshapes->setBeside(source.beside());
  m_blendshapes->setShown(source.shown());
  m_blendshapes->layer().copyAppearance(source.layer());
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
  m_document->setCurrentFrame(frame);
  if (std::exchange(m_resetCamera, false))
    m_view->resetCamera();  // around the markers where the review starts (the head moves in the lab)
  viewport->requestRender();
  QImage image = viewport->grabFramebuffer();
  if (image.isNull())
    return {};
  if (image.size() != m_size)
    image = image.scaled(m_size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  return image.convertToFormat(QImage::Format_RGB888);
}

} // namespace mocap::ui
