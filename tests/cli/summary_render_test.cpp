// The archive report renders in a real browser: headless Chromium screenshots the page of a
// batch, and each plot's colour is on the picture (label gui).
#include "../core/test_support.h"
#include "shell_run.h"

#include "mocap/base/file_io.h"
#include "checkout_paths.h"

#include <QColor>
#include <QImage>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace mocap {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

/// Pixels of `image` within `tolerance` (per channel) of `colour`.
std::size_t pixelsNear(const QImage& image, QColor colour, int tolerance)
{
  std::size_t n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - colour.red()) <= tolerance && std::abs(c.green() - colour.green()) <= tolerance &&
          std::abs(c.blue() - colour.blue()) <= tolerance)
        ++n;
    }
  return n;
}

TEST(SummaryRender, HeadlessChromiumDrawsEveryPlot)
{
  const std::string chromium = checkout::chromium();
  if (chromium.empty())
    GTEST_SKIP() << "chromium not installed";
  test::TempDir dir;
  std::string manifest;
  for (const char* take : {"c3d/sample01/Eb015pi.c3d", "c3d/sample01/Eb015vi.c3d", "c3d/sample02/dec_real.c3d"})
    manifest += test::dataFile(take).string() + "\n";
  manifest += test::sampleTake().string() + "\n";
  writeFileAtomically(dir.file("takes.txt"), manifest);
  const std::string mocap = shellQuote(std::string(checkout::cliProgram()));
  const auto batch =
      test::runShell(mocap + " batch " + shellQuote(dir.file("takes.txt")) + " -o " + shellQuote(dir.file("out")), dir.path());
  ASSERT_EQ(batch.exitCode, 0) << batch.err;
  const auto summary = test::runShell(mocap + " summarize " + shellQuote(dir.file("out")) + " -o " +
                                          shellQuote(dir.file("report.html")),
                                      dir.path());
  ASSERT_EQ(summary.exitCode, 0) << summary.err;

  const fs::path png = dir.file("report.png");
  // --no-sandbox: the test may run as root in a container; the page is our own file.
  const auto render = test::runShell("HOME=" + shellQuote(dir.path()) + " timeout 120 " + shellQuote(chromium) +
                                         " --headless --no-sandbox --disable-gpu --hide-scrollbars"
                                         " --window-size=1000,2200 --screenshot=" +
                                         shellQuote(png) + " " + shellQuote("file://" + dir.file("report.html").string()),
                                     dir.path());
  ASSERT_EQ(render.exitCode, 0) << render.err;
  QImage image;
  ASSERT_TRUE(image.load(QString::fromStdString(png.string()))) << png;
  ASSERT_EQ(image.width(), 1000);
  // The colours of the plots' marks: before and after (valid fraction), the gap histogram, the
  // spikes bars, and the heat map's deep red (the sample's markers missing for long).
  EXPECT_GT(pixelsNear(image, QColor("#ff7f0e"), 12), 20u) << "valid fraction before";
  EXPECT_GT(pixelsNear(image, QColor("#1f77b4"), 12), 20u) << "valid fraction after";
  EXPECT_GT(pixelsNear(image, QColor("#2ca02c"), 12), 100u) << "gap-length histogram";
  EXPECT_GT(pixelsNear(image, QColor("#9467bd"), 12), 100u) << "spikes per marker";
  std::size_t heat = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      heat += c.red() > 200 && c.green() < 200 && c.green() > 30 && std::abs(c.green() - c.blue()) < 8 ? 1u : 0u;
    }
  EXPECT_GT(heat, 50u) << "missing-samples heat map";
}

} // namespace
} // namespace mocap
