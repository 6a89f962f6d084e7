#include "views/render_look.h"

#include <QColor>
#include <QLatin1String>
#include <QString>

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace mocap::ui {

bool isSoftwareRenderer(const QString& renderer)
{
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
    if (renderer.contains(QLatin1String(name), Qt::CaseInsensitive))
      return true;
  return false;
}

void setAntialiasing(vtkRenderWindow& window, vtkRenderer& scene, bool softwareRendered)
{
  if (!softwareRendered)
    return;
  window.SetMultiSamples(0);
  scene.UseFXAAOn();
}

void setGradientBackground(vtkRenderer& renderer, const QColor& color)
{
  const double r = static_cast<double>(color.redF()), g = static_cast<double>(color.greenF()),
               b = static_cast<double>(color.blueF());
  const auto lighter = [](double channel) { return std::min(1.0, channel + 0.14); };
  renderer.SetBackground(r, g, b);
  renderer.SetBackground2(lighter(r), lighter(g), lighter(b));
  renderer.GradientBackgroundOn();
}

} // namespace mocap::ui
