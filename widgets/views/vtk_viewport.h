#pragma once

#include <QColor>
#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPointF>
#include <QPoint>
#include <QRect>
#include <QString>
#include <QTimer>

#include <vtkNew.h>

#include <Eigen/Core>

class QRubberBand;

#include <vector>

class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;

namespace mocap::ui {

/// A Qt 6 QOpenGLWidget hosting a VTK render window, in the way VTK's own (Qt 5-only)
/// QVTKOpenGLNativeWidget works: VTK renders into its own framebuffers inside the widget's
/// context, and paintGL() blits the result into the widget's framebuffer.
///
/// The camera is driven directly: left-drag orbits, middle- or shift-drag pans, the wheel
/// zooms, R resets. A click that does not drag emits clicked() for picking.
/// When no usable OpenGL context can be had, usable() is false and failed() says why; the
/// widget then paints nothing and never calls into VTK rendering.
class VtkViewport : public QOpenGLWidget
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
  /// Whether a GL_RENDERER string names a CPU rasterizer.
  [[nodiscard]] static bool isSoftwareRenderer(const QString& renderer);
  [[nodiscard]] const QString& failureReason() const { return m_failure; }

  /// Asks for a VTK render at the next paint.
  void requestRender();
  /// On a CPU rasterizer, renders that follow each other within kSettleMs (playback, scrubbing,
  /// orbiting) skip the antialiasing pass, and the last of them is redone antialiased once they
  /// pause; a grab always is (hides QOpenGLWidget's, which is not virtual: a grabbed image is kept).
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
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

private:
  void onWindowEvent(vtkObject* caller, unsigned long eventId, void* callData);
  [[nodiscard]] bool contextIsCurrent() const;
  void fail(const QString& reason);
  void blitToWidget();
  /// Renders the scene, antialiased unless another render came less than kSettleMs before.
  void renderScene();

  vtkNew<vtkGenericOpenGLRenderWindow> m_window;
  vtkNew<vtkRenderer> m_renderer;
  std::vector<unsigned long> m_observers;
  bool m_usable = false;
  bool m_softwareRendered = false;
  bool m_renderPending = true;
  bool m_inPaint = false;
  bool m_lastRenderQuick = false;
  bool m_settled = false;       // the settle timer fired: the next render is antialiased
  QElapsedTimer m_sinceRender;  // started at the first render
  QTimer m_settle;              // fires kSettleMs after a render without antialiasing
  QString m_failure;
  QPoint m_pressPosition;
  QPoint m_lastPosition;
  bool m_dragged = false;
  QRubberBand* m_band = nullptr;  // shown during a Ctrl+left drag
};

} // namespace mocap::ui
