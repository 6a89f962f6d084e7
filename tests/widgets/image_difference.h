#pragma once

#include <QImage>

namespace mocap::test {

/// Mean absolute difference per channel (0–255) of two renders; 255 when the sizes differ.
[[nodiscard]] double meanDifference(const QImage& a, const QImage& b);

} // namespace mocap::test
