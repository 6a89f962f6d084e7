#include "views/marker_view_3d.h"

#include "document/take_document.h"
#include "document/view_state.h"
#include "views/camera_framing.h"
#include "views/display_units.h"
#include "views/sample_colors.h"
#include "views/selection_palette.h"

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/model/marker_links.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/marker_set.h"
#include "views/vtk_viewport.h"

#include <QEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QStringList>
#include <QToolTip>
#include <QStackedLayout>

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCellArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGlyph3DMapper.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkUnsignedCharArray.h>


#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap::ui {

namespace {

bool isSelected(const std::vector<Eigen::Index>& selection, Eigen::Index marker)
{
  return std::binary_search(selection.begin(), selection.end(), marker);
}

// Kept, dropped and reference markers of a planned layout: far apart in brightness and hue,
// and none of them a sample-state colour (sample_colors.h) nor in the selection palette, so the
// layout reads at a glance and a kept marker is never mistaken for a smoothed one.
const QColor kLayoutKept(250, 250, 250);
const QColor kLayoutDropped(85, 85, 92);
const QColor kLayoutReference(40, 110, 255);

unsigned char channel(int value)
{
  return static_cast<unsigned char>(std::clamp(value, 0, 255));
}

/// The diagonal of the box holding every marker point's sample at `frame` (else its first valid
/// one; model outputs are no positions): the take's size, for the marker radius. O(#markers) and
/// O(#frames) per marker missing at `frame`.
double diagonalOf(const Take& take, Eigen::Index frame)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Index m : markerPoints(take)) {
    Eigen::Index f = frame;
    if (!take.isValid(f, m)) {
      const auto column = take.valid().col(m);
      f = -1;
      for (Eigen::Index i = 0; i < take.frameCount(); ++i)
        if (column(i)) {
          f = i;
          break;
        }
      if (f < 0)
        continue;
    }
    lo = lo.cwiseMin(take.position(f, m));
    hi = hi.cwiseMax(take.position(f, m));
  }
  return lo.x() <= hi.x() ? std::max((hi - lo).norm(), 1e-6) : 1.0;
}

} // namespace

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
  connect(m_viewport, &VtkViewport::hovered, this, [this](QPoint position) {
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
  });

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  sphere->SetRadius(1.0);
  m_colors->SetNumberOfComponents(3);
  m_colors->SetName("colors");
  m_markers->SetPoints(m_points);
  m_markers->GetPointData()->SetScalars(m_colors);
  m_mapper->SetInputData(m_markers);
  m_mapper->SetSourceConnection(sphere->GetOutputPort());
  m_mapper->SetScalarModeToUsePointData();
  m_mapper->ScalingOn();
  m_mapper->SetScaleModeToNoDataScaling();  // every sphere the same size: ScaleFactor
  m_actor->SetMapper(m_mapper);
  m_actor->GetProperty()->SetSpecular(0.3);
  m_viewport->renderer()->AddActor(m_actor);

  vtkNew<vtkPolyDataMapper> trailMapper;
  trailMapper->SetInputData(m_trails);
  trailMapper->SetScalarModeToUseCellData();  // each trail in its marker's colour
  m_trailActor->SetMapper(trailMapper);
  m_trailActor->GetProperty()->SetOpacity(0.7);
  m_trailActor->GetProperty()->SetLineWidth(2.0f);
  m_viewport->renderer()->AddActor(m_trailActor);

  vtkNew<vtkPolyDataMapper> linkMapper;
  linkMapper->SetInputData(m_linkLines);
  m_linkActor->SetMapper(linkMapper);
  m_linkActor->GetProperty()->SetColor(0.55, 0.6, 0.7);
  m_linkActor->GetProperty()->SetOpacity(0.6);
  m_linkActor->GetProperty()->SetLineWidth(1.0f);
  m_linkActor->SetVisibility(false);
  m_viewport->renderer()->AddActor(m_linkActor);

  // A small corner renderer shows the lab axes with the main camera's orientation.
  m_axesRenderer->SetViewport(0.0, 0.0, 0.16, 0.2);
  m_axesRenderer->InteractiveOff();
  m_axesRenderer->SetLayer(1);
  m_axesRenderer->AddActor(m_axes);
  m_viewport->renderWindow()->SetNumberOfLayers(2);
  m_viewport->renderWindow()->AddRenderer(m_axesRenderer);
  connect(m_viewport, &VtkViewport::aboutToRender, this, [this] {
    vtkCamera* main = m_viewport->renderer()->GetActiveCamera();
    vtkCamera* corner = m_axesRenderer->GetActiveCamera();
    double direction[3];
    main->GetDirectionOfProjection(direction);
    corner->SetFocalPoint(0, 0, 0);
    corner->SetPosition(-direction[0] * 5.0, -direction[1] * 5.0, -direction[2] * 5.0);
    corner->SetViewUp(main->GetViewUp());
    m_axesRenderer->ResetCameraClippingRange();
    keepLabelsInView();
  });

  connect(&document, &TakeDocument::takeReset, this, [this] {
    forgetMarkerIndices();  // a new take
    rebuildScene();
  });
  connect(&document, &TakeDocument::referenceMarkersChanged, this, [this] {
    m_followMarkers = markersToFollow();
    updateFollow();
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
    for (Eigen::Index m : markers)
      if (std::find(m_headReference.begin(), m_headReference.end(), m) != m_headReference.end()) {
        setHeadReference(m_headReference);
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
  m_layoutKept.clear();
  m_layoutReference.clear();
  m_headReference.clear();
  m_headMotion.reset();
  m_followMarkers = markersToFollow();
  updateStatus();
  m_links.clear();
  if (m_linksVisible)
    computeLinks();
}

double MarkerView3d::takeSize() const
{
  return diagonalOf(m_document.take(), m_document.currentFrame());
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

void MarkerView3d::setTrailFrames(int frames)
{
  m_trailFrames = std::max(frames, 0);
  updateFrame();
}

void MarkerView3d::setMarkerScale(double fraction)
{
  m_markerScale = std::clamp(fraction, 1e-4, 0.2);
  rebuildScene();
}

void MarkerView3d::refreshColors()
{
  m_viewport->setBackground(colorScheme().background);
  updateFrame();
  updateTrails();
}

void MarkerView3d::setUpAxis(int axis)
{
  m_upAxis = axis == 1 ? 1 : 2;
  resetCamera();
}

void MarkerView3d::resetCamera()
{
  frameCamera(m_document.currentFrame(), m_document.currentFrame());
}

std::vector<Eigen::Vector3d> MarkerView3d::drawnPositions(Eigen::Index first, Eigen::Index last) const
{
  const Take& take = m_document.take();
  std::vector<Eigen::Vector3d> points;
  const std::vector<Eigen::Index> markers = markerPoints(take);  // model outputs are no positions
  const Eigen::Index step = std::max<Eigen::Index>(1, (last - first + 1) / 500);
  for (Eigen::Index f = first; f <= last; f += step)
    for (const Eigen::Index m : markers)
      if (take.isValid(f, m) && !m_document.isHidden(m))
        points.push_back(displayPosition(f, m));
  if (!points.empty())
    return points;
  // Nothing valid in these frames: each marker where it first is.
  for (const Eigen::Index m : markers) {
    const auto column = take.valid().col(m);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (column(f)) {
        points.push_back(displayPosition(f, m));
        break;
      }
  }
  return points;
}

void MarkerView3d::frameCamera(Eigen::Index first, Eigen::Index last)
{
  const Take& take = m_document.take();
  if (take.empty())
    return;
  first = std::clamp<Eigen::Index>(first, 0, take.frameCount() - 1);
  last = std::clamp<Eigen::Index>(last, first, take.frameCount() - 1);
  std::vector<Eigen::Vector3d> points = drawnPositions(first, last);
  const ViewDirection direction = facingDirection(points, m_upAxis);  // the markers decide where the face looks
  // The other actors drawn (face mesh, posed rig beside it) by the corners of their boxes.
  vtkRenderer* renderer = m_viewport->renderer();
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp()) {
    if (prop == m_actor.Get() || prop == m_trailActor.Get() || prop == m_linkActor.Get() || !prop->GetVisibility() ||
        !vtkActor::SafeDownCast(prop))
      continue;
    const double* bounds = prop->GetBounds();
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
      continue;
    for (int corner = 0; corner < 8; ++corner)
      points.emplace_back(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)]);
  }
  const QSize size = m_viewport->size();
  const double aspect = size.isEmpty() ? 1.0 : static_cast<double>(size.width()) / size.height();
  vtkCamera* camera = renderer->GetActiveCamera();
  fitCamera(*camera, points, direction, aspect, m_markerScale * m_takeSize);
  renderer->ResetCameraClippingRange();
  m_framedCamera = cameraState(*camera, size);
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
  std::shared_ptr<const HeadMotion> motion;
  if (!referenceMarkers.empty()) {
    try {
      motion = m_document.headMotion(referenceMarkers);
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
  }
  m_headReference = std::move(referenceMarkers);
  m_headMotion = std::move(motion);
  updateStatus();
  updateFrame();
  return {};
}

QString MarkerView3d::statusText() const
{
  QStringList parts;
  if (m_headMotion)
    parts << tr("Head-stabilized on %n marker(s) — Ctrl+B for the lab frame", nullptr,
                static_cast<int>(m_headReference.size()));
  if (m_followHead)
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

std::vector<Eigen::Index> MarkerView3d::markersToFollow() const
{
  // The document's reference (head) markers, the one set every panel uses.
  const Take& take = m_document.take();
  std::vector<Eigen::Index> markers = m_document.referenceMarkers();
  if (markers.empty())  // no head markers: the whole face
    markers = markerPoints(take);
  return markers;
}

void MarkerView3d::setFollowHead(bool on)
{
  m_followHead = on;
  if (m_followMarkers.empty())
    m_followMarkers = markersToFollow();
  updateStatus();
  updateFollow();
  m_viewport->requestRender();
}

std::optional<Eigen::Vector3d> MarkerView3d::followTarget(Eigen::Index frame) const
{
  const Take& take = m_document.take();
  if (take.empty() || frame < 0 || frame >= take.frameCount())
    return std::nullopt;
  const auto halfWindow = static_cast<Eigen::Index>(std::lround(0.2 * take.frameRate()));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Index frames = 0;
  for (Eigen::Index f = std::max<Eigen::Index>(0, frame - halfWindow);
       f <= std::min<Eigen::Index>(take.frameCount() - 1, frame + halfWindow); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    Eigen::Index count = 0;
    for (Eigen::Index m : m_followMarkers)
      if (m < take.markerCount() && take.isValid(f, m)) {
        centroid += displayPosition(f, m);
        ++count;
      }
    // A frame counts only with every followed marker: a marker dropping out would jolt the centroid.
    if (count == static_cast<Eigen::Index>(m_followMarkers.size()) && count > 0) {
      sum += centroid / static_cast<double>(count);
      ++frames;
    }
  }
  if (frames == 0)
    return std::nullopt;
  return sum / static_cast<double>(frames);
}

// Moves the camera (position and focal point together) so it looks at the follow target.
void MarkerView3d::updateFollow()
{
  if (!m_followHead)
    return;
  const auto target = followTarget(m_document.currentFrame());
  if (!target)
    return;
  vtkCamera* camera = m_viewport->renderer()->GetActiveCamera();
  Eigen::Vector3d focal, position;
  camera->GetFocalPoint(focal.data());
  camera->GetPosition(position.data());
  const Eigen::Vector3d moved = position + (*target - focal);
  camera->SetFocalPoint(target->data());
  camera->SetPosition(moved.data());
  m_viewport->renderer()->ResetCameraClippingRange();
}

Eigen::Vector3d MarkerView3d::displayPosition(Eigen::Index frame, Eigen::Index marker) const
{
  const Eigen::Vector3d p = m_document.take().position(frame, marker);
  if (!m_headMotion)
    return p;
  // The pose maps the reference frame's head onto the captured one; its inverse takes the
  // captured sample back into the reference frame's head.
  return m_headMotion->poses[static_cast<std::size_t>(frame)].inverse() * p;
}

void MarkerView3d::rebuildScene()
{
  m_takeSize = takeSize();
  // The glyph is a unit sphere; the factor makes it the marker radius.
  m_mapper->SetScaleFactor(m_markerScale * m_takeSize);
  updateFrame();
  resetCamera();
}

void MarkerView3d::updateFrame()
{
  const Take& take = m_document.take();
  const Eigen::Index frame = m_document.currentFrame();
  const auto& selection = m_document.selection();
  m_points->Reset();
  m_colors->Reset();
  m_drawnMarkers.clear();
  if (frame < take.frameCount()) {
    std::vector<bool> flagged(static_cast<std::size_t>(take.markerCount()), false);
    for (const auto& [marker, flagFrame] : m_document.flags())
      if (flagFrame == frame && marker < take.markerCount())
        flagged[static_cast<std::size_t>(marker)] = true;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      if (!take.isValid(frame, m) || m_document.isHidden(m))
        continue;
      const Eigen::Vector3d p = displayPosition(frame, m);
      m_points->InsertNextPoint(p.data());
      // Unlabelled points (fragments waiting for a label) stand apart from every labelled state.
      const auto i = static_cast<std::size_t>(m);
      const QColor color = isSelected(selection, m) ? selectedMarkerColor(selection, m)
                           : !m_layoutKept.empty()
                               ? (m_layoutKept[i]                                     ? kLayoutKept
                                  : !m_layoutReference.empty() && m_layoutReference[i] ? kLayoutReference
                                                                                        : kLayoutDropped)
                           : flagged[i]                        ? colorScheme().flagged
                           : isUnlabelledLabel(take.label(m)) ? QColor(200, 130, 255)
                                                              : stateColor(take.state(frame, m));
      const unsigned char rgb[3] = {static_cast<unsigned char>(color.red()), static_cast<unsigned char>(color.green()),
                                    static_cast<unsigned char>(color.blue())};
      m_colors->InsertNextTypedTuple(rgb);
      m_drawnMarkers.push_back(m);
    }
  }
  m_points->Modified();
  m_colors->Modified();
  m_markers->Modified();
  updateLinks();
  updateTrails();
  updateLabels();
  updateFollow();
  m_viewport->requestRender();
}

void MarkerView3d::setLinksVisible(bool visible)
{
  m_linksVisible = visible;
  if (visible && m_links.empty())
    computeLinks();
  m_linkActor->SetVisibility(visible);
  updateFrame();
}

void MarkerView3d::computeLinks()
{
  const Take& take = m_document.take();
  m_links.clear();
  const Eigen::Index frame = take.empty() ? -1 : mostCompleteFrame(take);
  if (frame >= 0)  // none: no marker is ever valid, nothing to link
    m_links = nearestNeighbourLinks(take, frame);
}

void MarkerView3d::updateLinks()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const Take& take = m_document.take();
  const Eigen::Index frame = m_document.currentFrame();
  if (m_linksVisible && frame < take.frameCount()) {
    for (const auto& [a, b] : m_links) {
      if (a >= take.markerCount() || b >= take.markerCount() || !take.isValid(frame, a) || !take.isValid(frame, b) ||
          m_document.isHidden(a) || m_document.isHidden(b))
        continue;
      const vtkIdType ends[2] = {points->InsertNextPoint(displayPosition(frame, a).data()),
                                 points->InsertNextPoint(displayPosition(frame, b).data())};
      lines->InsertNextCell(2, ends);
    }
  }
  m_linkLines->SetPoints(points);
  m_linkLines->SetLines(lines);
  m_linkLines->Modified();
}

void MarkerView3d::updateTrails()
{
  const Take& take = m_document.take();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  const Eigen::Index frame = m_document.currentFrame();
  const auto& selection = m_document.selection();
  if (m_trailFrames > 0 && frame < take.frameCount()) {
    for (std::size_t i = 0; i < selection.size(); ++i) {
      const Eigen::Index m = selection[i];
      if (m_document.isHidden(m))
        continue;
      const QColor color = selectionPaletteColor(i);
      const unsigned char rgb[3] = {channel(color.red()), channel(color.green()), channel(color.blue())};
      const Eigen::Index first = std::max<Eigen::Index>(0, frame - m_trailFrames);
      const Eigen::Index last = std::min<Eigen::Index>(take.frameCount() - 1, frame + m_trailFrames);
      std::vector<vtkIdType> run;
      auto flush = [&] {
        if (run.size() > 1) {
          lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
          colors->InsertNextTypedTuple(rgb);
        }
        run.clear();
      };
      for (Eigen::Index f = first; f <= last; ++f) {
        if (!take.isValid(f, m)) {
          flush();  // a gap breaks the trail
          continue;
        }
        run.push_back(points->InsertNextPoint(displayPosition(f, m).data()));
      }
      flush();
    }
  }
  m_trails->SetPoints(points);
  m_trails->SetLines(lines);
  m_trails->GetCellData()->SetScalars(colors);
  m_trails->Modified();
}

void MarkerView3d::updateLabels()
{
  vtkRenderer* renderer = m_viewport->renderer();
  const Take& take = m_document.take();
  const auto& selection = m_document.selection();
  // Selected markers in their palette colours, then the kept markers of a layout highlight.
  std::vector<Eigen::Index> markers = selection;
  std::vector<QColor> colors;
  for (std::size_t i = 0; i < selection.size(); ++i)
    colors.push_back(selectionPaletteColor(i));
  for (std::size_t m = 0; m < m_layoutKept.size(); ++m)
    if (m_layoutKept[m] && !isSelected(selection, static_cast<Eigen::Index>(m))) {
      markers.push_back(static_cast<Eigen::Index>(m));
      colors.push_back(kLayoutKept);
    }
  // Text actors are rebuilt only when the labelled markers (or a label) change: rasterising
  // text every frame would dominate playback.
  bool rebuild = markers != m_labelMarkers || colors != m_labelColors;
  for (std::size_t i = 0; !rebuild && i < markers.size(); ++i)
    rebuild = m_labelTexts[i] != take.label(markers[i]);
  if (rebuild) {
    for (auto& label : m_labels)
      renderer->RemoveActor(label);
    m_labels.clear();
    m_labelMarkers = markers;
    m_labelColors = colors;
    m_labelTexts.clear();
    for (std::size_t i = 0; i < markers.size(); ++i) {
      auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
      label->SetInput(take.label(markers[i]).c_str());
      label->GetTextProperty()->SetFontSize(14);
      label->GetTextProperty()->SetColor(static_cast<double>(colors[i].redF()), static_cast<double>(colors[i].greenF()),
                                         static_cast<double>(colors[i].blueF()));
      label->GetTextProperty()->SetBold(true);
      label->GetTextProperty()->SetShadow(true);
      renderer->AddActor(label);
      m_labels.push_back(label);
      m_labelTexts.push_back(take.label(markers[i]));
    }
  }
  const Eigen::Index frame = m_document.currentFrame();
  const double offset = 2.5 * m_markerScale * m_takeSize;
  for (std::size_t i = 0; i < m_labels.size(); ++i) {
    const Eigen::Index m = m_labelMarkers[i];
    const bool visible = frame < take.frameCount() && m < take.markerCount() && take.isValid(frame, m) &&
                         !m_document.isHidden(m);
    m_labels[i]->SetVisibility(visible);
    if (!visible)
      continue;
    const Eigen::Vector3d p = displayPosition(frame, m);
    const Eigen::Vector3d lifted = p + offset * Eigen::Vector3d::Unit(m_upAxis);
    m_labels[i]->SetPosition(lifted.x(), lifted.y(), lifted.z());
  }
}

void MarkerView3d::keepLabelsInView()
{
  // A label sits above and right of its marker, so the one of a marker at the view's top or right
  // edge (where Reset Camera puts the outermost markers) was cut: it is shifted back inside as far
  // as needed, as long as its marker is in view. O(#labels) per render.
  vtkRenderer* renderer = m_viewport->renderer();
  const int* size = renderer->GetSize();
  const int dpi = m_viewport->renderWindow()->GetDPI();
  for (const auto& label : m_labels) {
    label->SetDisplayOffset(0, 0);
    if (!label->GetVisibility())
      continue;
    const double* position = label->GetPosition();
    renderer->SetWorldPoint(position[0], position[1], position[2], 1.0);
    renderer->WorldToDisplay();
    const double* anchor = renderer->GetDisplayPoint();
    if (anchor[0] < 0.0 || anchor[1] < 0.0 || anchor[0] > size[0] || anchor[1] > size[1])
      continue;  // its marker is out of view: no label dragged in
    int box[4] = {0, 0, 0, 0};  // xmin, xmax, ymin, ymax around the anchor, in pixels
    if (!vtkTextRenderer::GetInstance()->GetBoundingBox(label->GetTextProperty(), vtkStdString(label->GetInput()), box,
                                                        dpi))
      continue;
    const auto shift = [](double at, int low, int high, int room) {
      const int over = static_cast<int>(std::ceil(at)) + high - room;
      if (over > 0)
        return -over;
      const int under = -static_cast<int>(std::floor(at)) - low;
      return under > 0 ? under : 0;
    };
    label->SetDisplayOffset(shift(anchor[0], box[0], box[1], size[0]), shift(anchor[1], box[2], box[3], size[1]));
  }
}

QPointF MarkerView3d::projected(vtkIdType id) const
{
  vtkRenderer* renderer = m_viewport->renderer();
  double world[4] = {0, 0, 0, 1};
  m_points->GetPoint(id, world);
  renderer->SetWorldPoint(world);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  const double ratio = m_viewport->devicePixelRatioF();
  return {display[0] / ratio, m_viewport->height() - display[1] / ratio};  // VTK display y grows upwards
}

Eigen::Index MarkerView3d::markerAt(QPoint position, int radius) const
{
  Eigen::Index best = -1;
  double bestDistance = radius;
  for (vtkIdType id = 0; id < m_points->GetNumberOfPoints(); ++id) {
    const QPointF p = projected(id);
    const double distance = std::hypot(p.x() - position.x(), p.y() - position.y());
    if (distance <= bestDistance) {
      bestDistance = distance;
      best = m_drawnMarkers[static_cast<std::size_t>(id)];
    }
  }
  return best;
}

std::vector<Eigen::Index> MarkerView3d::markersIn(const QRect& rectangle) const
{
  std::vector<Eigen::Index> markers;
  const QRectF area(rectangle);
  for (vtkIdType id = 0; id < m_points->GetNumberOfPoints(); ++id)
    if (area.contains(projected(id)))
      markers.push_back(m_drawnMarkers[static_cast<std::size_t>(id)]);
  std::sort(markers.begin(), markers.end());
  return markers;
}

std::optional<QPointF> MarkerView3d::screenPosition(Eigen::Index marker) const
{
  const auto it = std::find(m_drawnMarkers.begin(), m_drawnMarkers.end(), marker);
  if (it == m_drawnMarkers.end())
    return std::nullopt;
  return projected(static_cast<vtkIdType>(it - m_drawnMarkers.begin()));
}

Eigen::Vector3d MarkerView3d::cameraFocalPoint() const
{
  Eigen::Vector3d focal;
  m_viewport->renderer()->GetActiveCamera()->GetFocalPoint(focal.data());
  return focal;
}

std::optional<QColor> MarkerView3d::markerColor(Eigen::Index marker) const
{
  const auto it = std::find(m_drawnMarkers.begin(), m_drawnMarkers.end(), marker);
  if (it == m_drawnMarkers.end())
    return std::nullopt;
  unsigned char rgb[3];
  m_colors->GetTypedTuple(static_cast<vtkIdType>(it - m_drawnMarkers.begin()), rgb);
  return QColor(rgb[0], rgb[1], rgb[2]);
}

void MarkerView3d::setLayoutHighlight(std::vector<bool> kept, std::vector<bool> reference)
{
  if (static_cast<Eigen::Index>(kept.size()) != m_document.take().markerCount())
    kept.clear();  // a flag per marker or none: anything else belongs to another take
  if (kept.empty() || reference.size() != kept.size())
    reference.clear();
  m_layoutKept = std::move(kept);
  m_layoutReference = std::move(reference);
  updateFrame();
}

void MarkerView3d::clearLayoutHighlight()
{
  setLayoutHighlight({});
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
