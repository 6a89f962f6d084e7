#include "image_difference.h"
#include "checkout_paths.h"

#include <QDir>
#include <QFile>

#include <cstdlib>

namespace mocap::test {
namespace {

[[nodiscard]] QImage opaque(const QImage& image)
{
  return image.convertToFormat(QImage::Format_RGB32);
}

[[nodiscard]] bool pixelsDiffer(QRgb a, QRgb b)
{
  return std::abs(qRed(a) - qRed(b)) > kChannelTolerance || std::abs(qGreen(a) - qGreen(b)) > kChannelTolerance ||
         std::abs(qBlue(a) - qBlue(b)) > kChannelTolerance;
}

[[nodiscard]] QString describe(const ImageDifference& difference)
{
  if (difference.sizesDiffer)
    return QStringLiteral("the sizes differ");
  QString text = QStringLiteral("%1 of %2 pixels (%3 %) differ by more than %4/255 in a channel (at most %5 % may)")
                     .arg(difference.differing)
                     .arg(difference.total)
                     .arg(100.0 * difference.fraction(), 0, 'f', 3)
                     .arg(kChannelTolerance)
                     .arg(100.0 * kMaxDifferingFraction);
  if (difference.differing > 0) {
    const QRect& b = difference.bounds;
    text += QStringLiteral(", within x %1–%2, y %3–%4").arg(b.left()).arg(b.right()).arg(b.top()).arg(b.bottom());
  }
  return text;
}

} // namespace

ImageDifference compareImages(const QImage& actual, const QImage& expected)
{
  const QImage a = opaque(actual), b = opaque(expected);
  ImageDifference difference;
  if (a.size() != b.size()) {
    difference.sizesDiffer = true;
    return difference;
  }
  difference.total = qsizetype(a.width()) * a.height();
  for (int y = 0; y < a.height(); ++y) {
    const auto* p = reinterpret_cast<const QRgb*>(a.constScanLine(y));
    const auto* q = reinterpret_cast<const QRgb*>(b.constScanLine(y));
    for (int x = 0; x < a.width(); ++x)
      if (pixelsDiffer(p[x], q[x])) {
        ++difference.differing;
        difference.bounds |= QRect(x, y, 1, 1);
      }
  }
  return difference;
}

QImage highlightDifferences(const QImage& actual, const QImage& expected)
{
  QImage image = opaque(actual);
  const QImage b = opaque(expected);
  const bool comparable = image.size() == b.size();
  for (int y = 0; y < image.height(); ++y) {
    auto* p = reinterpret_cast<QRgb*>(image.scanLine(y));
    const auto* q = comparable ? reinterpret_cast<const QRgb*>(b.constScanLine(y)) : nullptr;
    for (int x = 0; x < image.width(); ++x) {
      const int grey = qGray(p[x]) / 3;  // dim, so the highlight stands out from the scene
      p[x] = q && pixelsDiffer(p[x], q[x]) ? qRgb(255, 0, 255) : qRgb(grey, grey, grey);
    }
  }
  return image;
}

QString actualImagePath(const QString& name)
{
  return QDir(QString::fromUtf8(checkout::testBuildDir())).filePath(name + QStringLiteral(".actual.png"));
}

QString differenceImagePath(const QString& name)
{
  return QDir(QString::fromUtf8(checkout::testBuildDir())).filePath(name + QStringLiteral(".diff.png"));
}

::testing::AssertionResult matchesImage(const QImage& actual, const QImage& expected, const QString& name)
{
  const QString actualPath = actualImagePath(name), diffPath = differenceImagePath(name);
  QFile::remove(diffPath);  // a diff left from an earlier failure would mislead
  if (!actual.save(actualPath))
    return ::testing::AssertionFailure() << "cannot write " << actualPath.toStdString();
  const ImageDifference difference = compareImages(actual, expected);
  if (difference.matches())
    return ::testing::AssertionSuccess() << describe(difference).toStdString();
  highlightDifferences(actual, expected).save(diffPath);
  return ::testing::AssertionFailure() << "the render of " << name.toStdString() << " does not match: "
                                       << describe(difference).toStdString() << "\n  actual: " << actualPath.toStdString()
                                       << "\n  differences (magenta): " << diffPath.toStdString();
}

::testing::AssertionResult matchesBaseline(const QImage& actual, const QString& name)
{
  const QString baselinePath = QDir(QString::fromUtf8(checkout::baselineDir())).filePath(name + QStringLiteral(".png"));
  const QImage expected(baselinePath);
  if (expected.isNull()) {
    (void)actual.save(actualImagePath(name));
    return ::testing::AssertionFailure() << "missing baseline " << baselinePath.toStdString()
                                         << "; the rendered image is at " << actualImagePath(name).toStdString();
  }
  return matchesImage(actual, expected, name);
}

} // namespace mocap::test
