#pragma once

#include <QColor>
#include <QElapsedTimer>
#include <QWidget>
#include <QPointF>
#include <QPoint>
#include <QRect>
#include <QSize>
#include <QString>
#include <QSurfaceFormat>
#include <QTimer>

#include <vtkNew.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

class QOffscreenSurface;
class QOpenGLContext;

class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;

namespace mocap::ui {

[[nodiscard]] QImage grabWithViewports(QWidget& widget);

/// A widget hosting a VTK render window in a native OpenGL child window (as VTK's own, Qt
/// 5-only QVTKOpenGLStereoWidget does): VTK renders into its own framebuffers in the viewport's
/// context, and each repaint blits the result into that window and swaps only it.
///
/// Not a QOpenGLWidget on purpose: one of those makes Qt compose the whole top-level window
/// through OpenGL on every repaint of any widget, which on a CPU rasterizer (Xvfb, a VM, a
/// remote desktop) cost the studio more than the 3D render itself while scrubbing. The context
/// is current on an offscreen surface when the window is not exposed, so a never-shown view
/// (a review video's) renders and grabs all the same.
///
/// The camera is driven directly: left-drag orbits, middle- or shift-drag pans, the wheel
/// zooms, R resets. A click that does not drag emits clicked() for picking.
/// When no usable OpenGL context can be had, usable() is false and failed() says why; the
/// widget then paints nothing and never calls into VTK rendering.
class VtkViewport : public QWidget
{
  Q_OBJECT

public:
  explicit VtkViewport(QWidget* parent = nullptr);
  ~VtkViewport() override;

  /// The surface format VTK needs (OpenGL 3.2 core, RGBA8, 24-bit depth); set it as the
  /// application default before the QApplication is created.
  [[nodiscard]] static QSurfaceFormat defaultFormat();

  [[nodiscard]] vtkRenderer* renderer() const;
  [[nodiscard]] vtkGenericOpenGLRenderWindow* renderWindow() const;
  [[nodiscard]] bool usable() const { return m_usable; }
  /// Whether OpenGL runs on the CPU (Mesa's llvmpipe under Xvfb or in a VM): then the view
  /// antialiases by FXAA instead of multisampling. Known once the context is up.
  [[nodiscard]] bool softwareRendered() const { return m_softwareRendered; }
  [[nodiscard]] const QString& failureReason() const { return m_failure; }

  /// Asks for a VTK render at the next paint.
  void requestRender();
  /// On a CPU rasterizer, renders that follow each other within kSettleMs (playback, scrubbing,
  /// orbiting) skip the antialiasing pass, and the last of them is redone antialiased once they
  /// pause; a grab always is. Null when the view is not usable.
  [[nodiscard]] QImage grabFramebuffer();
  /// Whether the last render skipped antialiasing for speed (its antialiased redo is due).
  [[nodiscard]] bool lastRenderQuick() const { return m_lastRenderQuick; }
  /// How long renders must pause before the antialiased one.
  static constexpr int kSettleMs = 150;
  /// Background: `color` at the bottom in a gradient to a lighter shade at the top.
  void setBackground(const QColor& color);
  /// Fits the camera to the visible props.
  void resetCamera();
  /// Where the scene point `world` appears, in widget (logical) coordinates.
  [[nodiscard]] QPointF widgetPosition(const Eigen::Vector3d& world) const;
  /// A widget position as VTK display coordinates (device pixels, y up), e.g. for pickers.
  [[nodiscard]] QPoint displayPixel(QPoint position) const;

signals:
  /// A press-release without dragging, in widget (logical) coordinates.
  void clicked(QPoint position, Qt::KeyboardModifiers modifiers);
  /// The cursor moved over the view with no button held, in widget coordinates.
  void hovered(QPoint position);
  /// A Ctrl+left drag drew this rectangle (rubber-band selection), in widget coordinates;
  /// `modifiers` as held at release.
  void rectangleSelected(QRect rectangle, Qt::KeyboardModifiers modifiers);
  /// No usable OpenGL context: the reason, for a message in place of the view.
  void failed(const QString& reason);
  /// Emitted just before VTK renders, so owners can update props lazily.
  void aboutToRender();

protected:
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

private:
  class Surface;
  friend QImage grabWithViewports(QWidget& widget);  // skips the window's container

  void onWindowEvent(vtkObject* caller, unsigned long eventId, void* callData);
  /// Creates the context and readies VTK in it, once; false (and failed()) when that cannot be.
  bool initializeContext();
  [[nodiscard]] bool contextIsCurrent() const;
  /// Makes the context current on the window when it is exposed, else on the offscreen surface.
  bool makeCurrent();
  [[nodiscard]] QSize deviceSize() const;
  void fail(const QString& reason);
  /// Renders when a render is pending, blits it into the window with the rubber band, swaps.
  void present();
  void schedulePresent();
  void renderIfPending();
  void blitToWindow(QSize size);
  void drawRubberBand(QSize size);
  /// Renders the scene, antialiased unless another render came less than kSettleMs before.
  void renderScene();

  std::unique_ptr<QOpenGLContext> m_context;
  std::unique_ptr<QOffscreenSurface> m_offscreen;
  Surface* m_surface = nullptr;   // owned by m_container
  QWidget* m_container = nullptr;  // the window's widget, filling the viewport
  vtkNew<vtkGenericOpenGLRenderWindow> m_window;
  vtkNew<vtkRenderer> m_renderer;
  std::vector<unsigned long> m_observers;
  bool m_usable = false;
  bool m_softwareRendered = false;
  bool m_renderPending = true;
  bool m_inPaint = false;
  bool m_presentQueued = false;
  bool m_lastRenderQuick = false;
  bool m_settled = false;       // the settle timer fired: the next render is antialiased
  QElapsedTimer m_sinceRender;  // started at the first render
  QTimer m_settle;              // fires kSettleMs after a render without antialiasing
  QString m_failure;
  QPoint m_pressPosition;
  QPoint m_lastPosition;
  bool m_dragged = false;
  QRect m_band;  // during a Ctrl+left drag: drawn over the scene (no widget shows over a native window)
};

/// `widget` as QWidget::grab paints it, with each shown VtkViewport's scene (and the widgets over
/// it) drawn in: QWidget::grab cannot read a native OpenGL window, so a plain grab leaves the 3D
/// views blank. For whole-window screenshots.
[[nodiscard]] QImage grabWithViewports(QWidget& widget);

} // namespace mocap::ui
