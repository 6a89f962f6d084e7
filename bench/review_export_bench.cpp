// Review video export (issue 16): the sample take's 3D view rendered off screen and encoded at
// 1280 × 720, under Xvfb/llvmpipe (run it as `xvfb-run -a -s "-screen 0 1920x1080x24"
// build/bin/review_export_bench`). Target: ≥ 10 frames/s end to end (items_per_second of
// BM_ExportReview). References in the same run: rendering alone (BM_RenderView, what the studio's
// own view costs per frame at that size) and composing + encoding alone (BM_ComposeAndEncode).
#include "main_window.h"

#include "dialogs/review_export.h"
#include "document/take_document.h"
#include "mocap/video/review_frame.h"
#include "mocap/video/review_video_writer.h"
#include "views/review_scene.h"
#include "views/vtk_viewport.h"
#include "checkout_paths.h"

#include <QApplication>
#include <QSettings>
#include <QSurfaceFormat>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace {

using namespace mocap;

constexpr int kWidth = 1280, kHeight = 720;
constexpr Eigen::Index kFrames = 100;

std::unique_ptr<studio::MainWindow> g_window;  // made and destroyed in main, inside the application

studio::MainWindow& sampleWindow()
{
  return *g_window;
}

ui::ReviewSource reviewSource()
{
  ui::ReviewSource source = sampleWindow().reviewSource();
  source.resetCamera = true;
  return source;
}

std::filesystem::path outputPath(const char* name)
{
  return std::filesystem::temp_directory_path() / name;
}

void BM_RenderView(benchmark::State& state)
{
  const ReviewLayout layout = reviewLayout(kWidth, kHeight, false);
  ui::ReviewScene scene(reviewSource(), QSize(layout.view.width, layout.view.height));
  if (!scene.usable()) {
    state.SkipWithError("no GL context (run under xvfb-run)");
    return;
  }
  scene.frameCamera(0, sampleWindow().document().take().frameCount() - 1);
  Eigen::Index frame = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(scene.render(frame++ % sampleWindow().document().take().frameCount()));
  state.SetItemsProcessed(state.iterations());
}

void BM_ComposeAndEncode(benchmark::State& state)
{
  const ReviewLayout layout = reviewLayout(kWidth, kHeight, false);
  VideoImage view;
  view.width = layout.view.width;
  view.height = layout.view.height;
  view.rgb.assign(VideoImage::byteCount(view.width, view.height), 90);
  ReviewVideoWriter writer(outputPath("mocap_review_bench_encode.mp4"), kWidth, kHeight, 100.0);
  long long frame = 0;
  for (auto _ : state) {
    view.rgb[static_cast<std::size_t>(frame % 1000) * 3] = 255;  // not the same frame twice
    writer.write(composeReviewFrame(layout, view, nullptr, {"Facial-Sing", reviewTimeText(1, frame++, 100.0), ""}));
  }
  writer.finish();
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(writer.encoding().codec);
}

void BM_ExportReview(benchmark::State& state)
{
  ui::ReviewRequest request;
  request.output = outputPath("mocap_review_bench.mp4");
  request.size = QSize(kWidth, kHeight);
  request.first = 900;
  request.last = 900 + kFrames - 1;
  request.takeName = "Facial-Sing";
  std::string codec;
  for (auto _ : state) {
    const ui::ReviewOutcome outcome = ui::exportReview(reviewSource(), request, {});
    if (!outcome.done) {
      state.SkipWithError(outcome.error.toStdString().c_str());
      return;
    }
    codec = outcome.encoding.codec;
  }
  state.SetItemsProcessed(state.iterations() * kFrames);
  state.SetLabel(codec);
}

BENCHMARK(BM_RenderView)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ComposeAndEncode)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ExportReview)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

} // namespace

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(ui::VtkViewport::defaultFormat());
  QApplication application(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("MocapStudio"));
  QApplication::setApplicationName(QStringLiteral("Mocap Review Bench"));
  QSettings().clear();
  g_window = std::make_unique<studio::MainWindow>();
  if (const QString error = g_window->openFile(QString::fromUtf8(mocap::checkout::sampleDir()) + QStringLiteral("/Facial-Sing.c3d"), true); !error.isEmpty())
    return 1;
  (void)g_window->selectLabels({QStringLiteral("section5-1"), QStringLiteral("section3-4")});
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  g_window.reset();
  return 0;
}
