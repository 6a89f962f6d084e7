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
#include <vtkMath.h>
#include <vtkRenderer.h>

#include <cmath>
#include <stdexcept>
#include <algorithm>

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

/// The source view's camera for a view of `size`: the same view, widened when the review is
/// narrower than the source (VTK keeps the vertical angle, so a narrower view would crop the sides).
void copyCamera(const MarkerView3d& from, vtkCamera* camera, QSize size)
{
  vtkCamera* source = from.viewport()->renderer()->GetActiveCamera();
  camera->DeepCopy(source);
  const QWidget* view = from.viewport();
  if (view->width() <= 0 || view->height() <= 0 || size.isEmpty() || camera->GetParallelProjection())
    return;
  const double sourceAspect = static_cast<double>(view->width()) / view->height();
  const double aspect = static_cast<double>(size.width()) / size.height();
  if (aspect >= sourceAspect)
    return;
  const double halfAngle = vtkMath::RadiansFromDegrees(source->GetViewAngle() / 2.0);
  camera->SetViewAngle(2.0 * vtkMath::DegreesFromRadians(std::atan(std::tan(halfAngle) * sourceAspect / aspect)));
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
  copyCamera(*source.view, m_view->viewport()->renderer()->GetActiveCamera(), size);
  if (source.faceMesh)
    copyFaceMesh(*source.faceMesh);
  if (source.blendshapes && m_faceMesh)
    copyBlendshapes(*source.blendshapes);
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
  m_blendshapes = std::make_unique<BlendshapeScene>(*m_blendshapeModel, *m_faceMeshModel, *m_view);
  m_blendshapes->setBeside(source.beside());
  m_blendshapes->setShown(source.shown());
  m_blendshapes->layer().copyAppearance(source.layer());
}

void ReviewScene::frameCamera(Eigen::Index first, Eigen::Index last)
{
  const Take& take = m_document->take();
  first = std::clamp<Eigen::Index>(first, 0, take.frameCount() - 1);
  last = std::clamp<Eigen::Index>(last, first, take.frameCount() - 1);
  m_document->setCurrentFrame(first);
  m_view->resetCamera();  // the direction the studio faces the take from
  double bounds[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  const Eigen::Index step = std::max<Eigen::Index>(1, (last - first + 1) / 500);
  for (Eigen::Index f = first; f <= last; f += step)
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      if (!take.isValid(f, m) || m_document->isHidden(m))
        continue;
      const Eigen::Vector3d p = m_view->displayPosition(f, m);
      for (int axis = 0; axis < 3; ++axis) {
        bounds[2 * axis] = std::min(bounds[2 * axis], p[axis]);
        bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], p[axis]);
      }
    }
  if (bounds[0] > bounds[1])
    return;  // nothing valid: the current frame's framing stays
  vtkRenderer* renderer = m_view->viewport()->renderer();
  renderer->ResetCamera(bounds);
  renderer->GetActiveCamera()->Zoom(1.25);  // ResetCamera fits a bounding sphere; a face is flatter
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
  viewport->requestRender();
  QImage image = viewport->grabFramebuffer();
  if (image.isNull())
    return {};
  if (image.size() != m_size)
    image = image.scaled(m_size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  return image.convertToFormat(QImage::Format_RGB888);
}

} // namespace mocap::ui
