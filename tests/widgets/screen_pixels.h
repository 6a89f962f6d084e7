#pragma once

#include <QColor>
#include <QImage>
#include <QRect>

class QWidget;

namespace mocap::test {

/// What the display shows over `area` of `widget` (widget coordinates; the whole widget when
/// null), read back from the screen: native child windows included, as a user sees it (Xvfb has
/// no compositor). Unlike QWidget::grab, which paints the widget tree into an image and misses
/// what a native window covers or draws.
[[nodiscard]] QImage shownOnScreen(const QWidget& widget, QRect area = {});

/// How many pixels of `image` are within `tolerance` of `color` in every channel.
[[nodiscard]] qsizetype pixelsNear(const QImage& image, QColor color, int tolerance);

} // namespace mocap::test
