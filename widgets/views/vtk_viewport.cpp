#include "views/vtk_viewport.h"

#include "views/sample_colors.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QRubberBand>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {
constexpr int kClickSlop = 4;  // pixels a press may move and still count as a click
} // namespace

bool VtkViewport::isSoftwareRenderer(const QString& renderer)
{
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
    if (renderer.contains(QLatin1String(name), Qt::CaseInsensitive))
      return true;
  return false;
}

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

VtkViewport::VtkViewport(QWidget* parent) : QOpenGLWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover reports (labels under the cursor)
  m_window->AddRenderer(m_renderer);
  m_window->SetReadyForRendering(false);  // until initializeGL gives VTK a context
  for (unsigned long id : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                           vtkCommand::WindowFrameEvent})
    m_observers.push_back(m_window->AddObserver(id, this, &VtkViewport::onWindowEvent));
  setBackground(colorScheme().background);
  m_renderer->GradientBackgroundOn();
  m_settle.setSingleShot(true);
  m_settle.setInterval(kSettleMs);
  connect(&m_settle, &QTimer::timeout, this, [this] {
    m_settled = true;
    requestRender();
  });
}

void VtkViewport::setBackground(const QColor& color)
{
  const double r = static_cast<double>(color.redF()), g = static_cast<double>(color.greenF()),
               b = static_cast<double>(color.blueF());
  const auto lighter = [](double channel) { return std::min(1.0, channel + 0.14); };
  m_renderer->SetBackground(r, g, b);
  m_renderer->SetBackground2(lighter(r), lighter(g), lighter(b));
  requestRender();
}

VtkViewport::~VtkViewport()
{
  if (m_usable) {
    makeCurrent();  // VTK releases its GL resources in our context
    m_window->Finalize();
    doneCurrent();
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
  update();
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
  const QOpenGLContext* current = QOpenGLContext::currentContext();
  return current && current == context();
}

void VtkViewport::onWindowEvent(vtkObject*, unsigned long eventId, void* callData)
{
  switch (eventId) {
  case vtkCommand::WindowMakeCurrentEvent:
    // Only when not current already: makeCurrent() rebinds Qt's framebuffer, which breaks VTK
    // while it is creating its own framebuffers (a blank or garbage view).
    if (!contextIsCurrent())
      makeCurrent();
    break;
  case vtkCommand::WindowIsCurrentEvent:
    *static_cast<bool*>(callData) = contextIsCurrent();
    break;
  case vtkCommand::WindowFrameEvent:
    if (!m_inPaint)
      update();  // VTK rendered outside paintGL (e.g. a direct Render() call): show it
    break;
  default: break;
  }
}

void VtkViewport::initializeGL()
{
  QOpenGLContext* ctx = context();
  if (!ctx || !ctx->isValid()) {
    fail(tr("No OpenGL context is available, so the 3D view cannot be shown."));
    return;
  }
  const QSurfaceFormat format = ctx->format();
  if (format.majorVersion() * 10 + format.minorVersion() < 32) {
    fail(tr("The 3D view needs OpenGL 3.2; this display offers %1.%2.")
             .arg(format.majorVersion())
             .arg(format.minorVersion()));
    return;
  }
  m_window->SetForceMaximumHardwareLineWidth(1);
  // blitToWidget copies VTK's frame to the widget; VTK's own copy at the end of each render
  // (BlitToCurrent, into the widget's framebuffer too) was a second full-view blit.
  m_window->SetFrameBlitModeToNoBlit();
  const auto* renderer = reinterpret_cast<const char*>(ctx->functions()->glGetString(GL_RENDERER));
  m_softwareRendered = isSoftwareRenderer(QString::fromLatin1(renderer ? renderer : ""));
  if (m_softwareRendered) {
    // A CPU rasterizer (Xvfb, a VM, a remote desktop) shades every pixel once per sample: VTK's
    // default 8× multisampling made each frame 3–4× slower there. One FXAA pass instead.
    m_window->SetMultiSamples(0);
    m_renderer->UseFXAAOn();
  }
  m_window->SetReadyForRendering(true);
  m_window->SetOwnContext(0);
  m_window->OpenGLInitContext();
  m_usable = true;
  m_renderPending = true;
}

void VtkViewport::resizeGL(int width, int height)
{
  const double ratio = devicePixelRatioF();
  m_window->SetSize(static_cast<int>(std::lround(width * ratio)), static_cast<int>(std::lround(height * ratio)));
  m_renderPending = true;
}

void VtkViewport::paintGL()
{
  QOpenGLExtraFunctions* gl = context() ? context()->extraFunctions() : nullptr;
  if (!m_usable || !gl) {
    if (gl) {
      gl->glClearColor(0.12f, 0.13f, 0.15f, 1.0f);
      gl->glClear(GL_COLOR_BUFFER_BIT);
    }
    return;
  }
  if (m_renderPending) {
    m_inPaint = true;
    emit aboutToRender();
    renderScene();
    m_inPaint = false;
    m_renderPending = false;
  }
  makeCurrent();  // rendering may have switched contexts (e.g. progress updates elsewhere)
  blitToWidget();
}

QImage VtkViewport::grabFramebuffer()
{
  m_settled = true;  // antialiased
  if (m_lastRenderQuick)
    m_renderPending = true;
  return QOpenGLWidget::grabFramebuffer();
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

void VtkViewport::blitToWidget()
{
  QOpenGLExtraFunctions* gl = context()->extraFunctions();
  gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  gl->glDrawBuffers(1, &drawBuffer);
  const bool scissor = gl->glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
  if (scissor) {
    m_window->GetState()->vtkglDisable(GL_SCISSOR_TEST);
    gl->glDisable(GL_SCISSOR_TEST);  // scissoring would clip the blit
  }
  int* source = m_window->GetRenderFramebuffer()->GetLastSize();
  const double ratio = devicePixelRatioF();
  const int width = static_cast<int>(std::lround(this->width() * ratio));
  const int height = static_cast<int>(std::lround(this->height() * ratio));
  m_window->BlitDisplayFramebuffer(0, 0, 0, source[0], source[1], 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                                   GL_LINEAR);
  // Opaque alpha, or Mesa composes the view with whatever is behind the window.
  gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  gl->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  gl->glClear(GL_COLOR_BUFFER_BIT);
  gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (scissor) {
    m_window->GetState()->vtkglEnable(GL_SCISSOR_TEST);
    gl->glEnable(GL_SCISSOR_TEST);
  }
}

void VtkViewport::mousePressEvent(QMouseEvent* event)
{
  m_pressPosition = m_lastPosition = event->position().toPoint();
  m_dragged = false;
  if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier)) {
    if (!m_band)
      m_band = new QRubberBand(QRubberBand::Rectangle, this);
    m_band->setGeometry(QRect(m_pressPosition, QSize()));
    m_band->show();
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
  if (m_band && m_band->isVisible()) {  // rubber band: the camera stays
    m_band->setGeometry(QRect(m_pressPosition, position).normalized());
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
  const bool band = m_band && m_band->isVisible();
  if (band)
    m_band->hide();
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
  QOpenGLWidget::keyPressEvent(event);
}

} // namespace mocap::ui
