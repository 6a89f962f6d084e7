#include "views/offscreen_render_window.h"

#include "views/render_look.h"

#include <QCoreApplication>

#include <vtkObjectFactory.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>

#include <vtkXOpenGLRenderWindow.h>  // last: Xlib's macros (None, Status, Bool…) follow it

namespace mocap::ui {

namespace {

/// VTK's X11 window, drawing lines wider than a pixel (the trails) with VTK's own shader as the 3D
/// view's window does (it is told the driver has no wide lines), not with the driver's
/// glLineWidth, which draws them otherwise.
class ShaderLinesXWindow final : public vtkXOpenGLRenderWindow
{
public:
  static ShaderLinesXWindow* New();
  vtkTypeMacro(ShaderLinesXWindow, vtkXOpenGLRenderWindow)
  float GetMaximumHardwareLineWidth() override { return 1.0f; }
};

vtkStandardNewMacro(ShaderLinesXWindow);

} // namespace

OffscreenRenderWindow::OffscreenRenderWindow(QSize size)
    : m_window(vtkSmartPointer<ShaderLinesXWindow>::New()), m_size(size)
{
  m_window->SetOffScreenRendering(1);
  m_window->SetSize(std::max(size.width(), 1), std::max(size.height(), 1));
  m_window->AddRenderer(m_renderer);
  m_usable = open();
}

OffscreenRenderWindow::~OffscreenRenderWindow()
{
  if (m_usable)
    m_window->Finalize();
  if (m_display)
    XCloseDisplay(static_cast<Display*>(m_display));
}

vtkRenderWindow& OffscreenRenderWindow::window() const
{
  return *m_window;
}

vtkRenderer* OffscreenRenderWindow::renderer() const
{
  return m_renderer.Get();
}

bool OffscreenRenderWindow::open()
{
  // VTK's X11 window aborts the program when it cannot reach a display: say so instead.
  if (qEnvironmentVariableIsEmpty("DISPLAY")) {
    m_failure = QCoreApplication::translate("OffscreenRenderWindow",
                                            "there is no X display (DISPLAY is not set); run under xvfb-run");
    return false;
  }
  // One connection for the OpenGL probe and the window: VTK's probe would otherwise open and close
  // its own, and an X server left without clients resets (Xvfb and xvfb-run do, unless -noreset),
  // refusing the window's connection made meanwhile, and VTK aborts the program on that.
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    m_failure = QCoreApplication::translate("OffscreenRenderWindow", "cannot connect to the X display %1")
                    .arg(qEnvironmentVariable("DISPLAY"));
    return false;
  }
  m_display = display;
  static_cast<vtkXOpenGLRenderWindow&>(*m_window).SetDisplayId(display);
  if (m_window->SupportsOpenGL() == 0) {
    m_failure = QCoreApplication::translate("OffscreenRenderWindow", "OpenGL 3.2 is not available on this display");
    return false;
  }
  m_window->Initialize();  // the context, current from here on
  const QString capabilities = QString::fromLatin1(m_window->ReportCapabilities());
  setAntialiasing(*m_window, *m_renderer, isSoftwareRenderer(capabilities));
  return true;
}

QImage OffscreenRenderWindow::render()
{
  if (!m_usable)
    return {};
  m_window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  const int width = m_size.width(), height = m_size.height();
  if (m_window->GetPixelData(0, 0, width - 1, height - 1, 0, pixels, 0) == 0)
    return {};
  // VTK's rows run bottom-up, three bytes a pixel.
  QImage image(width, height, QImage::Format_RGB888);
  const auto row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.scanLine(y), pixels->GetPointer(static_cast<vtkIdType>(row) * (height - 1 - y)), row);
  return image;
}

} // namespace mocap::ui
