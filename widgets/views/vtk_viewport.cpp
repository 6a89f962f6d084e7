#include "views/vtk_viewport.h"

#include "views/render_look.h"
#include "views/sample_colors.h"

#include <QCoreApplication>
#include <QExposeEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QResizeEvent>
#include <QShowEvent>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <QWindow>

#include <vtkAutoInit.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

// VTK's object factories for the rendering classes every viewport creates: OpenGL render windows and
// mappers, FreeType text, the window interactor. Registered here, in the one file that every program
// with a 3D view links, instead of by vtk_module_autoinit, whose compile definition names a header in
// the build folder on every widgets compile line (a compiler cache could then not share them
// between two clones).
VTK_MODULE_INIT(vtkRenderingOpenGL2)
VTK_MODULE_INIT(vtkRenderingFreeType)
VTK_MODULE_INIT(vtkRenderingUI)

namespace mocap::ui {

namespace {
constexpr int kClickSlop = 4;  // pixels a press may move and still count as a click
constexpr int kBandWidth = 1;  // the rubber band's outline, in device pixels
} // namespace

/// The native window the viewport draws into. Its input goes to the viewport widget (its
/// handlers, and event filters installed on it, see it as their own), its exposure and update
/// requests to the viewport's present().
class VtkViewport::Surface final : public QWindow
{
public:
  explicit Surface(VtkViewport& owner) : m_owner(&owner)
  {
    setSurfaceType(QSurface::OpenGLSurface);
    setFormat(VtkViewport::defaultFormat());
  }
  void detach() { m_owner = nullptr; }

protected:
  void exposeEvent(QExposeEvent*) override
  {
    if (m_owner && isExposed())
      m_owner->present();
  }

  bool event(QEvent* event) override
  {
    if (!m_owner)
      return QWindow::event(event);
    switch (event->type()) {
    case QEvent::UpdateRequest: m_owner->present(); return true;
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
      QCoreApplication::sendEvent(m_owner, event);  // a key not taken goes on to the widget's parents
      return true;
    default: return QWindow::event(event);
    }
  }

private:
  VtkViewport* m_owner;
};

QSurfaceFormat VtkViewport::defaultFormat()
{
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(0);
  format.setSamples(0);
  return format;
}

VtkViewport::VtkViewport(QWidget* parent) : QWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover reports (labels under the cursor)
  m_surface = new Surface(*this);
  m_container = QWidget::createWindowContainer(m_surface, this);
  m_container->setFocusPolicy(Qt::NoFocus);  // the viewport widget takes the focus and the keys
  m_container->setGeometry(rect());
  m_window->AddRenderer(m_renderer);
  m_window->SetReadyForRendering(false);  // until initializeContext gives VTK a context
  for (unsigned long id : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                           vtkCommand::WindowFrameEvent})
    m_observers.push_back(m_window->AddObserver(id, this, &VtkViewport::onWindowEvent));
  setBackground(colorScheme().background);
  m_settle.setSingleShot(true);
  m_settle.setInterval(kSettleMs);
  connect(&m_settle, &QTimer::timeout, this, [this] {
    m_settled = true;
    requestRender();
  });
}

void VtkViewport::setBackground(const QColor& color)
{
  setGradientBackground(*m_renderer, color);
  requestRender();
}

VtkViewport::~VtkViewport()
{
  m_surface->detach();
  delete m_container;  // and the window: nothing presents while VTK lets go
  m_surface = nullptr;
  m_container = nullptr;
  if (m_usable && m_context->makeCurrent(m_offscreen.get())) {
    m_window->Finalize();  // VTK releases its GL resources in our context
    m_context->doneCurrent();
  }
  for (unsigned long id : m_observers)
    m_window->RemoveObserver(id);
  m_window->SetReadyForRendering(false);
}

vtkRenderer* VtkViewport::renderer() const
{
  return m_renderer.GetPointer();
}

vtkGenericOpenGLRenderWindow* VtkViewport::renderWindow() const
{
  return m_window.GetPointer();
}

void VtkViewport::requestRender()
{
  m_renderPending = true;
  schedulePresent();
}

void VtkViewport::schedulePresent()
{
  // Posted rather than QWindow::requestUpdate, which waits for a 60 Hz tick: the render then
  // follows the frame change in the same turn of the event loop as the other views' repaints.
  if (m_presentQueued || !m_surface || !m_surface->isExposed())
    return;
  m_presentQueued = true;
  QMetaObject::invokeMethod(this, &VtkViewport::present, Qt::QueuedConnection);
}

void VtkViewport::resetCamera()
{
  m_renderer->ResetCamera();
  requestRender();
}

QPointF VtkViewport::widgetPosition(const Eigen::Vector3d& world) const
{
  m_renderer->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  m_renderer->WorldToDisplay();
  double display[3];
  m_renderer->GetDisplayPoint(display);
  const double ratio = devicePixelRatioF();
  return {display[0] / ratio, height() - display[1] / ratio};  // VTK display y grows upwards
}

QPoint VtkViewport::displayPixel(QPoint position) const
{
  const double ratio = devicePixelRatioF();
  return {static_cast<int>(std::lround(position.x() * ratio)),
          static_cast<int>(std::lround((height() - position.y()) * ratio))};
}

void VtkViewport::fail(const QString& reason)
{
  m_usable = false;
  m_failure = reason;
  m_window->SetReadyForRendering(false);
  emit failed(reason);
}

bool VtkViewport::contextIsCurrent() const
{
  return m_context && QOpenGLContext::currentContext() == m_context.get();
}

bool VtkViewport::makeCurrent()
{
  if (!m_context)
    return false;
  if (m_surface && m_surface->isExposed())
    return m_context->makeCurrent(m_surface);
  return m_context->makeCurrent(m_offscreen.get());
}

QSize VtkViewport::deviceSize() const
{
  const double ratio = devicePixelRatioF();
  return {static_cast<int>(std::lround(width() * ratio)), static_cast<int>(std::lround(height() * ratio))};
}

void VtkViewport::onWindowEvent(vtkObject*, unsigned long eventId, void* callData)
{
  switch (eventId) {
  case vtkCommand::WindowMakeCurrentEvent:
    if (!contextIsCurrent())
      makeCurrent();
    break;
  case vtkCommand::WindowIsCurrentEvent:
    *static_cast<bool*>(callData) = contextIsCurrent();
    break;
  case vtkCommand::WindowFrameEvent:
    if (!m_inPaint)
      schedulePresent();  // VTK rendered outside present (e.g. a direct Render() call): show it
    break;
  default: break;
  }
}

bool VtkViewport::initializeContext()
{
  if (m_context)
    return m_usable;
  m_context = std::make_unique<QOpenGLContext>();
  m_context->setFormat(defaultFormat());
  m_offscreen = std::make_unique<QOffscreenSurface>();
  if (!m_context->create()) {
    fail(tr("No OpenGL context is available, so the 3D view cannot be shown."));
    return false;
  }
  const QSurfaceFormat format = m_context->format();
  if (format.majorVersion() * 10 + format.minorVersion() < 32) {
    fail(tr("The 3D view needs OpenGL 3.2; this display offers %1.%2.")
             .arg(format.majorVersion())
             .arg(format.minorVersion()));
    return false;
  }
  m_offscreen->setFormat(format);
  m_offscreen->create();
  if (!m_context->makeCurrent(m_offscreen.get())) {
    fail(tr("The OpenGL context cannot be used, so the 3D view cannot be shown."));
    return false;
  }
  m_window->SetForceMaximumHardwareLineWidth(1);
  // blitToWindow copies VTK's frame to the window; VTK's own copy at the end of each render
  // (BlitToCurrent) would be a second full-view blit.
  m_window->SetFrameBlitModeToNoBlit();
  const auto* renderer = reinterpret_cast<const char*>(m_context->functions()->glGetString(GL_RENDERER));
  m_softwareRendered = isSoftwareRenderer(QString::fromLatin1(renderer ? renderer : ""));
  setAntialiasing(*m_window, *m_renderer, m_softwareRendered);
  m_window->SetReadyForRendering(true);
  m_window->SetOwnContext(0);
  m_window->OpenGLInitContext();
  const QSize size = deviceSize();
  m_window->SetSize(std::max(size.width(), 1), std::max(size.height(), 1));
  m_usable = true;
  m_renderPending = true;
  return true;
}

void VtkViewport::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  initializeContext();
}

void VtkViewport::resizeEvent(QResizeEvent* event)
{
  QWidget::resizeEvent(event);
  m_container->setGeometry(rect());
  const QSize size = deviceSize();
  m_window->SetSize(std::max(size.width(), 1), std::max(size.height(), 1));
  m_renderPending = true;
  schedulePresent();
}

void VtkViewport::renderIfPending()
{
  if (!m_renderPending)
    return;
  m_inPaint = true;
  emit aboutToRender();
  renderScene();
  m_inPaint = false;
  m_renderPending = false;
}

void VtkViewport::present()
{
  m_presentQueued = false;
  if (!m_usable || !m_surface || !m_surface->isExposed() || !m_context->makeCurrent(m_surface))
    return;
  renderIfPending();
  if (!m_context->makeCurrent(m_surface))  // rendering may have switched surfaces or contexts
    return;
  const QSize size = m_surface->size() * m_surface->devicePixelRatio();
  blitToWindow(size);
drawRubberBand(size);
  m_context->swapBuffers(m_surface);
}

QImage VtkViewport::grabFramebuffer()
{
  if (!m_usable && (m_context || !initializeContext()))
    return {};
  m_settled = true;  // antialiased
  if (m_lastRenderQuick)
    m_renderPending = true;
  if (!makeCurrent())
    return {};
  renderIfPending();
  const int* size = m_window->GetRenderFramebuffer()->GetLastSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  if (size[0] <= 0 || size[1] <= 0 || m_window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 1, pixels, 0) == 0)
    return {};
  // VTK's rows run bottom-up, three bytes a pixel.
  const QImage bottomUp(pixels->GetPointer(0), size[0], size[1], 3 * size[0], QImage::Format_RGB888);
  QImage image = bottomUp.mirrored(false, true).convertToFormat(QImage::Format_RGB32);
  image.setDevicePixelRatio(devicePixelRatioF());
  return image;
}

void VtkViewport::renderScene()
{
  // A CPU rasterizer spends about a third of a frame on the FXAA pass (playback of the sample
  // take under Xvfb: 34 → 22 ms a frame without it), so renders in quick succession skip it
  // and the last of them is redone antialiased once they pause. Direct Render() calls elsewhere
  // keep FXAA on: it is switched off only around this render.
  const bool quick = m_softwareRendered && !m_settled && m_sinceRender.isValid() &&
                     m_sinceRender.elapsed() < kSettleMs;
  m_settled = false;
  m_sinceRender.start();
  if (quick)
    m_renderer->UseFXAAOff();
  m_window->Render();
  if (quick) {
    m_renderer->UseFXAAOn();
    m_settle.start();
  } else {
    m_settle.stop();  // this one is antialiased already
  }
  m_lastRenderQuick = quick;
}

void VtkViewport::blitToWindow(QSize size)
{
  vtkOpenGLState* state = m_window->GetState();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_context->defaultFramebufferObject());
  state->vtkglDrawBuffer(GL_BACK);
  state->vtkglDisable(GL_SCISSOR_TEST);  // scissoring would clip the blit
  const int* source = m_window->GetRenderFramebuffer()->GetLastSize();
  m_window->BlitDisplayFramebuffer(0, 0, 0, source[0], source[1], 0, 0, size.width(), size.height(),
                                   GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void VtkViewport::drawRubberBand(QSize size)
{
  if (m_band.isNull())
    return;
  const double ratio = devicePixelRatioF();
  const int left = static_cast<int>(std::lround(m_band.left() * ratio));
  const int right = static_cast<int>(std::lround((m_band.right() + 1) * ratio));
  const int top = size.height() - static_cast<int>(std::lround(m_band.top() * ratio));  // GL's y grows upwards
  const int bottom = size.height() - static_cast<int>(std::lround((m_band.bottom() + 1) * ratio));
  const int w = std::max(right - left, kBandWidth), h = std::max(top - bottom, kBandWidth);
  vtkOpenGLState* state = m_window->GetState();
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglClearColor(0.95f, 0.95f, 0.95f, 1.0f);
  for (const QRect& edge : {QRect(left, bottom, w, kBandWidth), QRect(left, top - kBandWidth, w, kBandWidth),
                            QRect(left, bottom, kBandWidth, h), QRect(right - kBandWidth, bottom, kBandWidth, h)}) {
    state->vtkglScissor(edge.x(), edge.y(), edge.width(), edge.height());
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  state->vtkglDisable(GL_SCISSOR_TEST);
}

void VtkViewport::mousePressEvent(QMouseEvent* event)
{
  m_pressPosition = m_lastPosition = event->position().toPoint();
  m_dragged = false;
  if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier)) {
    m_band = QRect(m_pressPosition, QSize(1, 1));
    schedulePresent();
  }
  event->accept();
}

void VtkViewport::mouseMoveEvent(QMouseEvent* event)
{
  const QPoint position = event->position().toPoint();
  if ((position - m_pressPosition).manhattanLength() > kClickSlop)
    m_dragged = true;
  const QPoint delta = position - m_lastPosition;
  m_lastPosition = position;
  if (event->buttons() == Qt::NoButton) {
    emit hovered(position);
    return;
  }
  if (!m_band.isNull()) {  // rubber band: the camera stays
    m_band = QRect(m_pressPosition, position).normalized();
    schedulePresent();
    return;
  }
  if (!m_dragged || event->buttons() == Qt::NoButton)
    return;
  vtkCamera* camera = m_renderer->GetActiveCamera();
  const bool pan = (event->buttons() & Qt::MiddleButton) ||
                   ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) {
    // Move focal point and position together by the drag, scaled to the view's height.
    double focal[3], eye[3], up[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(eye);
    camera->GetViewUp(up);
    const double distance = camera->GetDistance();
    const double scale = 2.0 * distance * std::tan(camera->GetViewAngle() * M_PI / 360.0) / std::max(height(), 1);
    double forward[3] = {focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2]};
    double right[3] = {forward[1] * up[2] - forward[2] * up[1], forward[2] * up[0] - forward[0] * up[2],
                       forward[0] * up[1] - forward[1] * up[0]};
    const double rightLength = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
    for (double& r : right)
      r /= rightLength > 0.0 ? rightLength : 1.0;
    for (int i = 0; i < 3; ++i) {
      const double shift = (-delta.x() * right[i] + delta.y() * up[i]) * scale;
      focal[i] += shift;
      eye[i] += shift;
    }
    camera->SetFocalPoint(focal);
    camera->SetPosition(eye);
  } else if (event->buttons() & Qt::LeftButton) {
    camera->Azimuth(-0.4 * delta.x());
    camera->Elevation(0.4 * delta.y());
    camera->OrthogonalizeViewUp();
  } else if (event->buttons() & Qt::RightButton) {
    camera->Dolly(std::pow(1.01, -delta.y()));
  }
  m_renderer->ResetCameraClippingRange();
  requestRender();
}

void VtkViewport::mouseReleaseEvent(QMouseEvent* event)
{
  const bool band = !m_band.isNull();
  if (band) {
    m_band = QRect();
    schedulePresent();
  }
  if (band && m_dragged)
    emit rectangleSelected(QRect(m_pressPosition, event->position().toPoint()).normalized(), event->modifiers());
  else if (!m_dragged && event->button() == Qt::LeftButton)
    emit clicked(event->position().toPoint(), event->modifiers());
  m_dragged = false;
}

void VtkViewport::wheelEvent(QWheelEvent* event)
{
  const double steps = event->angleDelta().y() / 120.0;
  m_renderer->GetActiveCamera()->Dolly(std::pow(1.1, steps));
  m_renderer->ResetCameraClippingRange();
  requestRender();
  event->accept();
}

void VtkViewport::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_R && event->modifiers() == Qt::NoModifier) {
    resetCamera();
    return;
  }
  QWidget::keyPressEvent(event);
}

QImage grabWithViewports(QWidget& widget)
{
  QImage image = widget.grab().toImage();
  QPainter painter(&image);
  for (VtkViewport* view : widget.findChildren<VtkViewport*>()) {
    if (!view->isVisibleTo(&widget) || !view->usable())
      continue;
    const QPoint at = view->mapTo(&widget, QPoint(0, 0));
    painter.drawImage(QRect(at, view->size()), view->grabFramebuffer());
    for (QWidget* child : view->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
      if (child != view->m_container && child->isVisibleTo(view))
        painter.drawPixmap(at + child->pos(), child->grab());
  }
  return image;
}

} // namespace mocap::ui
