#pragma once

#include <QImage>
#include <QSize>
#include <QString>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkOpenGLRenderWindow;
class vtkRenderWindow;
class vtkRenderer;

namespace mocap::ui {

/// A VTK render window that renders off screen (VTK's own X11 window with SetOffScreenRendering: no
/// widget, no window shown, no Qt OpenGL context), with one scene renderer antialiased as the
/// studio's 3D view is (render_look.h) and wide lines drawn as the view's window draws them, so
/// what it renders is the view's picture. It needs an X display (xvfb-run where there is none);
/// without one, or without OpenGL 3.2, usable() is false and failureReason() says why, and nothing
/// is rendered.
class OffscreenRenderWindow
{
public:
  /// A window of `size` device pixels.
  explicit OffscreenRenderWindow(QSize size);
  ~OffscreenRenderWindow();
  OffscreenRenderWindow(const OffscreenRenderWindow&) = delete;
  OffscreenRenderWindow& operator=(const OffscreenRenderWindow&) = delete;

  [[nodiscard]] vtkRenderWindow& window() const;
  /// The scene's renderer (layer 0, the whole window).
  [[nodiscard]] vtkRenderer* renderer() const;
  [[nodiscard]] QSize size() const { return m_size; }
  [[nodiscard]] bool usable() const { return m_usable; }
  [[nodiscard]] const QString& failureReason() const { return m_failure; }

  /// Renders the window and reads the picture back: `size()` pixels, RGB888, top row first.
  /// Null when not usable. O(one render + #pixels).
  [[nodiscard]] QImage render();

private:
  /// Opens the window's OpenGL context; false (and the reason) when it cannot be had.
  bool open();

  vtkSmartPointer<vtkOpenGLRenderWindow> m_window;
  void* m_display = nullptr;  ///< the X connection the window uses, ours to close (an Xlib Display*)
  vtkNew<vtkRenderer> m_renderer;
  QSize m_size;
  bool m_usable = false;
  QString m_failure;
};

} // namespace mocap::ui
