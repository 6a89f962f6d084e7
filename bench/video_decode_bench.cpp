// Reference-video decoding (issue 16): a 1280×720 H.264 video at 30 fps, 30 s (the sample take's
// length; x264's default 250-frame GOP), written here with OpenCV (MJPEG AVI where FFmpeg has no
// H.264 encoder) to $TMPDIR/mocap_video_bench.mp4, which the studio's --profile scrub can reuse.
// Targets: sequential decode ≥ 4× real time on one core (items/s ≥ 120), a random seek < 100 ms.
// References in the same run: OpenCV's own sequential read without the RGB conversion
// VideoSource adds, and OpenCV's own seek (set the frame, read) to the same random frames.
#include "mocap/base/random.h"
#include "mocap/video/video_source.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

namespace {

constexpr int kFrames = 900;
constexpr double kRate = 30.0;

/// The bench video, written once: moving shapes over a gradient, so the encoder has real work.
const std::filesystem::path& benchVideo()
{
  static const std::filesystem::path path = [] {
    const auto dir = std::filesystem::temp_directory_path();
    std::filesystem::path file = dir / "mocap_video_bench.mp4";
    cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('a', 'v', 'c', '1'), kRate,
                           cv::Size(1280, 720));
    if (!writer.isOpened()) {
      file = dir / "mocap_video_bench.avi";
      writer.open(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kRate,
                  cv::Size(1280, 720));
    }
    for (int f = 0; f < kFrames; ++f) {
      cv::Mat image(720, 1280, CV_8UC3);
      for (int y = 0; y < 720; ++y)
        image.row(y).setTo(cv::Scalar(y / 3, (y + 2 * f) % 256, 128));
      cv::circle(image, cv::Point(100 + 3 * f, 360), 80, cv::Scalar(255, 255, 255), cv::FILLED);
      cv::putText(image, std::to_string(f), cv::Point(900, 200), cv::FONT_HERSHEY_SIMPLEX, 4.0,
                  cv::Scalar(0, 0, 0), 6);
      writer.write(image);
    }
    return file;
  }();
  return path;
}

void BM_SequentialDecode(benchmark::State& state)
{
  const std::filesystem::path& path = benchVideo();  // written before the timing starts
  for (auto _ : state) {
    mocap::VideoSource video(path, mocap::VideoSource::FrameTimes::Later);  // decoding alone
    for (Eigen::Index f = 0; f < video.info().frames; ++f)
      benchmark::DoNotOptimize(video.frame(f));
  }
  state.SetItemsProcessed(state.iterations() * kFrames);
  state.SetLabel("frames/s; real time is 30");
}

void BM_SequentialDecodeOpenCvReference(benchmark::State& state)
{
  const std::filesystem::path& path = benchVideo();
  for (auto _ : state) {
    cv::VideoCapture capture(path.string(), cv::CAP_FFMPEG);
    cv::Mat frame;
    while (capture.read(frame))
      benchmark::DoNotOptimize(frame.data);
  }
  state.SetItemsProcessed(state.iterations() * kFrames);
}

void BM_RandomSeek(benchmark::State& state)
{
  mocap::VideoSource video(benchVideo());
  mocap::Random random(5);
  for (auto _ : state)
    benchmark::DoNotOptimize(video.frame(static_cast<Eigen::Index>(random.uniform() * (kFrames - 1))));
  state.SetLabel("time per random frame; target < 100 ms");
}

void BM_RandomSeekOpenCvReference(benchmark::State& state)
{
  cv::VideoCapture capture(benchVideo().string(), cv::CAP_FFMPEG);
  mocap::Random random(5);  // the same frames as BM_RandomSeek
  cv::Mat frame;
  for (auto _ : state) {
    capture.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(static_cast<Eigen::Index>(random.uniform() * (kFrames - 1))));
    capture.read(frame);
    benchmark::DoNotOptimize(frame.data);
  }
}

// Opening as the studio's UI thread does (the header and one frame), and with the check of the
// first and last frames' timestamps (the variable-frame-rate test) the studio's worker then runs.
void BM_OpenHeader(benchmark::State& state)
{
  const std::filesystem::path& path = benchVideo();
  for (auto _ : state) {
    mocap::VideoSource video(path, mocap::VideoSource::FrameTimes::Later);
    benchmark::DoNotOptimize(video.info().frames);
  }
  state.SetLabel("the UI thread's part of Add Reference Video");
}

void BM_OpenAndCheckFrameTimes(benchmark::State& state)
{
  const std::filesystem::path& path = benchVideo();
  for (auto _ : state) {
    mocap::VideoSource video(path);
    benchmark::DoNotOptimize(video.info().frames);
  }
}

} // namespace

// Wall time: FFmpeg decodes on its own threads (run under `taskset -c 0` for one core).
BENCHMARK(BM_SequentialDecode)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SequentialDecodeOpenCvReference)->Unit(benchmark::kMillisecond)->UseRealTime();
// A fixed count, so both see the same 60 random frames (left to itself the library stops after
// 4 or 5 of them at these times, which says little about a mean).
constexpr int kSeeks = 60;
BENCHMARK(BM_RandomSeek)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(kSeeks);
BENCHMARK(BM_RandomSeekOpenCvReference)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(kSeeks);
BENCHMARK(BM_OpenHeader)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenAndCheckFrameTimes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
