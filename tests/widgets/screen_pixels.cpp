#include "screen_pixels.h"

#include <QGuiApplication>
#include <QPixmap>
#include <QScreen>
#include <QWidget>

#include <cstdlib>

namespace mocap::test {

QImage shownOnScreen(const QWidget& widget, QRect area)
{
  if (area.isNull())
    area = widget.rect();
  const QPoint topLeft = widget.mapToGlobal(area.topLeft());
  QScreen* screen = widget.screen() ? widget.screen() : QGuiApplication::primaryScreen();
  return screen->grabWindow(0, topLeft.x(), topLeft.y(), area.width(), area.height())
      .toImage()
      .convertToFormat(QImage::Format_RGB32);
}

qsizetype pixelsNear(const QImage& image, QColor color, int tolerance)
{
  qsizetype count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QRgb pixel = image.pixel(x, y);
      if (std::abs(qRed(pixel) - color.red()) <= tolerance && std::abs(qGreen(pixel) - color.green()) <= tolerance &&
          std::abs(qBlue(pixel) - color.blue()) <= tolerance)
        ++count;
    }
  return count;
}

} // namespace mocap::test
