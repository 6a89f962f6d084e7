#pragma once

#include "../core/coded_video.h"

#include <QImage>

namespace mocap::test {

/// The number a coded test video's frame spells (coded_video.h), read from the image Qt shows:
/// its bars across the middle row, on the green channel.
inline Eigen::Index codedFrameNumber(const QImage& image)
{
  return codedFrameNumber(image.width(), image.height(), [&](int x, int y) { return qGreen(image.pixel(x, y)) > 128; });
}

} // namespace mocap::test
