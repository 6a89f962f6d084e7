#pragma once

class QColor;
class QString;
class vtkRenderWindow;
class vtkRenderer;

namespace mocap::ui {

/// How the studio's 3D pictures are rendered, whichever window they are drawn in (the 3D view's,
/// a review's off-screen one), so the two are the same picture.

/// Whether a GL_RENDERER string names a CPU rasterizer (Mesa's llvmpipe under Xvfb or in a VM).
[[nodiscard]] bool isSoftwareRenderer(const QString& renderer);

/// Antialiasing: on a CPU rasterizer, which shades every pixel once per sample (VTK's default 8×
/// multisampling made each frame 3–4× slower there), one FXAA pass on `scene` instead; elsewhere
/// VTK's multisampling. Before the window's first render.
void setAntialiasing(vtkRenderWindow& window, vtkRenderer& scene, bool softwareRendered);

/// The background: `color` at the bottom in a gradient to a lighter shade at the top.
void setGradientBackground(vtkRenderer& renderer, const QColor& color);

} // namespace mocap::ui
