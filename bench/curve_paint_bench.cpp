// Painting the curve view (issue 29 moved this out of a timed unit test): a 1600 × 400 view of
// three selected markers of the sample take with a full-length smoothing-like preview, the take
// repeated 1×, 10× and 100× along time. Each pixel column draws the min-max of its frames, so the
// cost grows with the pass over the samples only, well under the frame ratio; the 1× run is the
// reference in the same run. Run as `QT_QPA_PLATFORM=offscreen build/bin/curve_paint_bench`.
#include "document/take_document.h"
#include "views/curve_view.h"
#include "checkout_paths.h"

#include "mocap/io/take_io.h"
#include "mocap/model/sample_patch.h"
#include "mocap/model/take.h"

#include <QApplication>
#include <QImage>

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

using namespace mocap;

/// The sample take played `times` times in a row (its markers and validity repeated).
Take repeatedSample(Eigen::Index times)
{
  const Take sample = readTake(std::string(checkout::sampleDir()) + "/Facial-Sing.c3d");
  Take take(sample.labels(), sample.frameCount() * times, sample.frameRate());
  for (Eigen::Index r = 0; r < times; ++r)
    for (Eigen::Index f = 0; f < sample.frameCount(); ++f)
      for (Eigen::Index m = 0; m < sample.markerCount(); ++m) {
        const Eigen::Index to = r * sample.frameCount() + f;
        take.setPosition(to, m, sample.position(f, m));
        take.valid()(to, m) = sample.isValid(f, m);
      }
  return take;
}

/// A preview over every frame of markers 0–2, 1 % off the take, as smoothing would show it.
std::vector<SamplePatch> fullPreview(const Take& take)
{
  std::vector<SamplePatch> preview;
  for (Eigen::Index m = 0; m < 3; ++m) {
    std::vector<Eigen::Index> rows;
    Eigen::Matrix<double, Eigen::Dynamic, 3> positions(take.frameCount(), 3);
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      rows.push_back(f);
      positions.row(f) = 1.01 * take.position(f, m).transpose();
    }
    preview.push_back(makePatch(m, rows, positions, SampleState().with(SampleOperation::Smoothed)));
  }
  return preview;
}

void BM_PaintCurves(benchmark::State& state)
{
  ui::TakeDocument document;
  document.setTake(repeatedSample(state.range(0)));
  document.setSelection({0, 1, 2});
  document.setPreview(fullPreview(document.take()));
  ui::CurveView view(document);
  view.resize(1600, 400);
  QImage image(view.size(), QImage::Format_ARGB32_Premultiplied);
  for (auto _ : state)
    view.render(&image);
  state.counters["frames"] = static_cast<double>(document.take().frameCount());
}

BENCHMARK(BM_PaintCurves)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv)
{
  QApplication application(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
