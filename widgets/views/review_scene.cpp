#include "views/review_scene.h"

#include "document/blendshape_solve_model.h"
#include "document/face_mesh_model.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "document/view_state.h"
#include "views/axes_corner.h"
#include "views/marker_scene.h"
#include "views/offscreen_render_window.h"
#include "views/render_look.h"
#include "views/sample_colors.h"
#include "views/session_scene.h"

#include <vtkRenderer.h>

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

} // namespace

ReviewScene::ReviewScene(const ReviewSource& source, QSize size)
    : m_session(std::make_unique<StudioSession>()), m_window(std::make_unique<OffscreenRenderWindow>(size))
{
  if (!source.session)
    throw std::invalid_argument("ReviewScene: a session is needed");
  vtkRenderer* renderer = m_window->renderer();
  setGradientBackground(*renderer, colorScheme().background);
  // In the 3D view's order: the marker layers, the session's layers over them, the axes corner.
  m_markers = std::make_unique<MarkerScene>(renderer, m_session->document());
  m_layers = std::make_unique<SessionScene>(*m_session, *m_markers);
  m_axes = std::make_unique<AxesCorner>(m_window->window());
  copySession(*source.session);
  applySettings(source.settings);
}

ReviewScene::~ReviewScene() = default;

void ReviewScene::copySession(const StudioSession& source)
{
  const TakeDocument& from = source.document();
  TakeDocument& document = m_session->document();
  document.setTake(from.take(), from.filePath());
  (void)document.setReferenceMarkers(from.referenceMarkers());
  document.setSelection(from.selection());
  document.setHidden(hiddenMarkers(from), true);
  m_markers->forgetMarkerIndices();  // the markers (and reference markers) of the copied take

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

void ReviewScene::applySettings(const SceneSettings& settings)
{
  ViewState& look = m_session->view();
  look.setMeshOpacity(settings.meshOpacity);
  look.setMeshEdges(settings.meshEdges);
  look.setRigShown(settings.rigShown);
  look.setRigBeside(settings.rigBeside);
  m_layers->observe(look);
  applyViewSettings(settings, *m_markers, m_window->size());
  if (!settings.camera) {
    const Eigen::Index frame = m_session->document().currentFrame();
    frameCamera(frame, frame);
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
  m_markers->update();
  m_layers->beforeRender();
  (void)m_markers->frameCamera(first, last, m_window->size());
}

bool ReviewScene::usable() const
{
  return m_window->usable();
}

QString ReviewScene::failureReason() const
{
  return m_window->failureReason();
}

void ReviewScene::prepareRender()
{
  vtkRenderer* renderer = m_window->renderer();
  m_axes->follow(*renderer->GetActiveCamera());
  m_markers->beforeRender();
  m_layers->beforeRender();
}

QImage ReviewScene::render(Eigen::Index frame)
{
  if (!m_window->usable())
    return {};
  m_session->document().setCurrentFrame(frame);
  m_markers->update();
  prepareRender();
  return m_window->render();
}

} // namespace mocap::ui
