#include "image_difference.h"

#include <cstdlib>

namespace mocap::test {

double meanDifference(const QImage& a, const QImage& b)
{
  const QImage x = a.convertToFormat(QImage::Format_RGB888), y = b.convertToFormat(QImage::Format_RGB888);
  if (x.size() != y.size())
    return 255.0;
  double sum = 0.0;
  for (int row = 0; row < x.height(); ++row) {
    const uchar* p = x.constScanLine(row);
    const uchar* q = y.constScanLine(row);
    for (int i = 0; i < x.width() * 3; ++i)
      sum += std::abs(int(p[i]) - int(q[i]));
  }
  return sum / (x.width() * x.height() * 3.0);
}

} // namespace mocap::test
