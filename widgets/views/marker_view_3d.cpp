#include "views/marker_view_3d.h"

#include "document/take_document.h"
#include "document/view_state.h"
#include "views/axes_corner.h"
#include "views/display_units.h"
#include "views/marker_layer.h"
#include "views/sample_colors.h"
#include "views/session_scene.h"
#include "views/vtk_viewport.h"

#include <QEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QStackedLayout>
#include <QStringList>
#include <QToolTip>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

MarkerView3d::MarkerView3d(TakeDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document)
{
  m_stack = new QStackedLayout(this);
  m_viewport = new VtkViewport(this);
  m_failure = new QLabel(this);
  m_failure->setAlignment(Qt::AlignCenter);
  m_failure->setWordWrap(true);
  m_stack->addWidget(m_viewport);
  m_viewport->installEventFilter(this);
  m_stack->addWidget(m_failure);
  // Says what the view shows when it is not the plain lab frame; a child of the viewport, so
  // it stays in its corner and out of the rendered image the baseline test compares. The
  // viewport draws in a native window, which covers plain child widgets: the label is a native
  // window too, stacked above it, and opaque (native windows do not blend).
  m_status = new QLabel(m_viewport);
  m_status->setObjectName(QStringLiteral("viewStatus"));
  m_status->setAttribute(Qt::WA_TransparentForMouseEvents);
  m_status->setAttribute(Qt::WA_NativeWindow);
  m_status->setStyleSheet(QStringLiteral("QLabel { color: #ffd27a; background: #141519; "
                                         "padding: 3px 6px; font-weight: bold; }"));
  m_status->move(8, 8);
  m_status->hide();
  connect(m_viewport, &VtkViewport::failed, this, [this](const QString& reason) {
    m_failure->setText(reason);
    m_stack->setCurrentWidget(m_failure);
  });
  connect(m_viewport, &VtkViewport::clicked, this, &MarkerView3d::onClicked);
  connect(m_viewport, &VtkViewport::rectangleSelected, this, &MarkerView3d::onRectangle);
  connect(m_viewport, &VtkViewport::hovered, this, &MarkerView3d::showTooltip);

  m_scene = std::make_unique<MarkerScene>(m_viewport->renderer(), document);
  m_axes = std::make_unique<AxesCorner>(*m_viewport->renderWindow());
  connect(m_viewport, &VtkViewport::aboutToRender, this, [this] {
    m_axes->follow(*m_viewport->renderer()->GetActiveCamera());
    m_scene->beforeRender();
  });

  connect(&document, &TakeDocument::takeReset, this, [this] {
    forgetMarkerIndices();  // a new take
    rebuildScene();
  });
  connect(&document, &TakeDocument::referenceMarkersChanged, this, [this] {
    m_scene->follow().chooseMarkers();
    m_scene->follow().aim(*m_viewport->renderer(), m_document.currentFrame());
  });
  connect(&document, &TakeDocument::currentFrameChanged, this, &MarkerView3d::updateFrame);
  connect(&document, &TakeDocument::samplesChanged, this, &MarkerView3d::updateFrame);
  connect(&document, &TakeDocument::selectionChanged, this, &MarkerView3d::updateFrame);
  connect(&document, &TakeDocument::markerRenamed, this, &MarkerView3d::updateFrame);
  connect(&document, &TakeDocument::markersChanged, this, [this] {
    forgetMarkerIndices();  // indices shifted
    updateFrame();
  });
  connect(&document, &TakeDocument::samplesChanged, this, [this](const std::vector<Eigen::Index>& markers) {
    // An edit of a reference marker moves the head pose: estimate it again.
    const std::vector<Eigen::Index>& reference = m_scene->positions().headReference();
    for (Eigen::Index m : markers)
      if (std::find(reference.begin(), reference.end(), m) != reference.end()) {
        setHeadReference(reference);
        return;
      }
  });
  connect(&document, &TakeDocument::visibilityChanged, this, &MarkerView3d::updateFrame);
  connect(&document, &TakeDocument::flagsChanged, this, &MarkerView3d::updateFrame);
  rebuildScene();
}

MarkerView3d::~MarkerView3d() = default;

void MarkerView3d::forgetMarkerIndices()
{
  m_scene->forgetMarkerIndices();
  updateStatus();
}

void MarkerView3d::observe(const ViewState& state)
{
  setMarkerScale(state.markerScale());
  setTrailFrames(state.trailFrames());
  setUpAxis(state.upAxis());
  setDisplayUnit(state.displayUnit());
  refreshColors();
  setLinksVisible(state.linksVisible());
  setFollowHead(state.followHead());
  if (!state.headReference().empty())
    (void)setHeadReference(state.headReference());
  setLayoutHighlight(state.layoutKept(), state.layoutReference());
  connect(&state, &ViewState::markerScaleChanged, this, &MarkerView3d::setMarkerScale);
  connect(&state, &ViewState::trailFramesChanged, this, &MarkerView3d::setTrailFrames);
  connect(&state, &ViewState::upAxisChanged, this, &MarkerView3d::setUpAxis);
  connect(&state, &ViewState::displayUnitChanged, this, &MarkerView3d::setDisplayUnit);
  connect(&state, &ViewState::colorsChanged, this, &MarkerView3d::refreshColors);
  connect(&state, &ViewState::linksVisibleChanged, this, &MarkerView3d::setLinksVisible);
  connect(&state, &ViewState::followHeadChanged, this, &MarkerView3d::setFollowHead);
  // The head-stabilized view's set is checked by whoever sets it (HeadStabilizedViewAction).
  connect(&state, &ViewState::headReferenceChanged, this,
          [this, &state] { (void)setHeadReference(state.headReference()); });
  connect(&state, &ViewState::layoutHighlightChanged, this,
          [this, &state] { setLayoutHighlight(state.layoutKept(), state.layoutReference()); });
  connect(&state, &ViewState::cameraResetRequested, this, &MarkerView3d::resetCamera);
}

void MarkerView3d::addLayers(SessionScene& layers)
{
  connect(&layers, &SessionScene::changed, m_viewport, &VtkViewport::requestRender);
  connect(m_viewport, &VtkViewport::aboutToRender, &layers, &SessionScene::beforeRender);
}

void MarkerView3d::setMarkerScale(double fraction)
{
  m_scene->setMarkerScale(fraction);
  rebuildScene();
}

void MarkerView3d::refreshColors()
{
  m_viewport->setBackground(colorScheme().background);
  updateFrame();
}

void MarkerView3d::setUpAxis(int axis)
{
  m_scene->setUpAxis(axis);
  resetCamera();
}

void MarkerView3d::resetCamera()
{
  frameCamera(m_document.currentFrame(), m_document.currentFrame());
}

void MarkerView3d::frameCamera(Eigen::Index first, Eigen::Index last)
{
  if (!m_scene->frameCamera(first, last, m_viewport->size()))
    return;
  m_framedCamera = cameraState(*m_viewport->renderer()->GetActiveCamera(), m_viewport->size());
  m_viewport->requestRender();
}

bool MarkerView3d::eventFilter(QObject* watched, QEvent* event)
{
  // R in the view is Reset Camera: this framing, not VTK's own.
  if (watched == m_viewport && event->type() == QEvent::KeyPress) {
    const auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_R && key->modifiers() == Qt::NoModifier) {
      resetCamera();
      return true;
    }
  }
  // A view resized before anyone moved the camera is framed again for its new shape: the window
  // comes up at its own size after the take was opened and framed.
  if (watched == m_viewport && event->type() == QEvent::Resize && m_framedCamera) {
    vtkCamera* camera = m_viewport->renderer()->GetActiveCamera();
    const CameraState now = cameraState(*camera, m_framedCamera->viewSize);
    if (now.position == m_framedCamera->position && now.focalPoint == m_framedCamera->focalPoint &&
        now.viewUp == m_framedCamera->viewUp && now.viewSize != m_viewport->size())
      resetCamera();
  }
  return QWidget::eventFilter(watched, event);
}

QString MarkerView3d::setHeadReference(std::vector<Eigen::Index> referenceMarkers)
{
  QString error = m_scene->positions().setHeadReference(std::move(referenceMarkers));
  if (!error.isEmpty())
    return error;
  updateStatus();
  updateFrame();
  return {};
}

QString MarkerView3d::statusText() const
{
  QStringList parts;
  if (m_scene->positions().stabilized())
    parts << tr("Head-stabilized on %n marker(s) — Ctrl+B for the lab frame", nullptr,
                static_cast<int>(m_scene->positions().headReference().size()));
  if (m_scene->follow().on())
    parts << tr("Camera follows the head");
  return parts.join(QStringLiteral("\n"));
}

void MarkerView3d::updateStatus()
{
  const QString text = statusText();
  m_status->setText(text);
  m_status->adjustSize();
  m_status->setVisible(!text.isEmpty());
  m_status->raise();
}

void MarkerView3d::setFollowHead(bool on)
{
  m_scene->follow().setOn(on);
  updateStatus();
  m_scene->follow().aim(*m_viewport->renderer(), m_document.currentFrame());
  m_viewport->requestRender();
}

std::optional<Eigen::Vector3d> MarkerView3d::followTarget(Eigen::Index frame) const
{
  return m_scene->follow().target(frame);
}

Eigen::Vector3d MarkerView3d::displayPosition(Eigen::Index frame, Eigen::Index marker) const
{
  return m_scene->positions().at(frame, marker);
}

void MarkerView3d::rebuildScene()
{
  m_scene->sizeToTake();
  updateFrame();
  resetCamera();
}

void MarkerView3d::updateFrame()
{
  m_scene->update();
  m_viewport->requestRender();
}

void MarkerView3d::setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference)
{
  m_scene->setLayoutHighlight(std::move(kept), std::move(reference));
  updateFrame();
}

void MarkerView3d::clearLayoutHighlight()
{
  setLayoutHighlight({});
}

void MarkerView3d::showTooltip(QPoint position)
{
  // The label of the marker under the cursor, as a tooltip that follows it.
  const Eigen::Index marker = markerAt(position, 8);
  if (marker < 0) {
    QToolTip::hideText();
    return;
  }
  const Take& take = m_document.take();
  const Eigen::Vector3d p = take.position(m_document.currentFrame(), marker);
  QToolTip::showText(m_viewport->mapToGlobal(position),
                     tr("%1\n%2, %3, %4 %5")
                         .arg(QString::fromStdString(take.label(marker)),
                              formatLength(p.x(), take.units(), m_displayUnit),
                              formatLength(p.y(), take.units(), m_displayUnit),
                              formatLength(p.z(), take.units(), m_displayUnit), unitLabel(m_displayUnit)),
                     m_viewport);
}

QPointF MarkerView3d::projected(std::size_t index) const
{
  return m_viewport->widgetPosition(m_scene->markerLayer().point(index));
}

Eigen::Index MarkerView3d::markerAt(QPoint position, int radius) const
{
  Eigen::Index best = -1;
  double bestDistance = radius;
  const std::vector<Eigen::Index>& drawn = m_scene->markerLayer().drawnMarkers();
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const QPointF p = projected(i);
    const double distance = std::hypot(p.x() - position.x(), p.y() - position.y());
    if (distance <= bestDistance) {
      bestDistance = distance;
      best = drawn[i];
    }
  }
  return best;
}

std::vector<Eigen::Index> MarkerView3d::markersIn(const QRect& rectangle) const
{
  std::vector<Eigen::Index> markers;
  const QRectF area(rectangle);
  const std::vector<Eigen::Index>& drawn = m_scene->markerLayer().drawnMarkers();
  for (std::size_t i = 0; i < drawn.size(); ++i)
    if (area.contains(projected(i)))
      markers.push_back(drawn[i]);
  std::sort(markers.begin(), markers.end());
  return markers;
}

std::optional<QPointF> MarkerView3d::screenPosition(Eigen::Index marker) const
{
  const std::optional<std::size_t> index = m_scene->markerLayer().indexOf(marker);
  if (!index)
    return std::nullopt;
  return projected(*index);
}

Eigen::Vector3d MarkerView3d::cameraFocalPoint() const
{
  Eigen::Vector3d focal;
  m_viewport->renderer()->GetActiveCamera()->GetFocalPoint(focal.data());
  return focal;
}

std::optional<QColor> MarkerView3d::markerColor(Eigen::Index marker) const
{
  return m_scene->markerLayer().colorOf(marker);
}

void MarkerView3d::onRectangle(const QRect& rectangle, Qt::KeyboardModifiers modifiers)
{
  std::vector<Eigen::Index> selection = markersIn(rectangle);
  if (modifiers & Qt::ShiftModifier)  // Ctrl draws the band; Shift as well adds to the selection
    selection.insert(selection.end(), m_document.selection().begin(), m_document.selection().end());
  m_document.setSelection(std::move(selection));
}

void MarkerView3d::onClicked(QPoint position, Qt::KeyboardModifiers modifiers)
{
  const Eigen::Index marker = markerAt(position);
  if (m_labellingMode) {
    if (marker >= 0)
      emit labelPointClicked(marker);
    return;
  }
  const bool extend = modifiers & (Qt::ControlModifier | Qt::ShiftModifier);
  std::vector<Eigen::Index> selection = extend ? m_document.selection() : std::vector<Eigen::Index>{};
  if (marker >= 0) {
    const auto it = std::find(selection.begin(), selection.end(), marker);
    if (extend && it != selection.end())
      selection.erase(it);
    else
      selection.push_back(marker);
  }
  m_document.setSelection(std::move(selection));
}

} // namespace mocap::ui
