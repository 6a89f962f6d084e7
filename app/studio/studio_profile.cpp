#include "studio_profile.h"

#include "main_window.h"
#include "ui_stall_meter.h"

#include "actions/labelling_actions.h"
#include "document/job_runner.h"
#include "document/take_document.h"
#include "panels/cleaning_panel.h"
#include "panels/cleaning_step.h"
#include "panels/reference_video_panel.h"
#include "document/reference_video.h"
#include "mocap/base/random.h"
#include "views/face_mesh_scene.h"
#include "views/session_scene.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <iostream>
#include <vector>

namespace mocap::studio {
namespace {

double msSince(const QElapsedTimer& clock)
{
  return static_cast<double>(clock.nsecsElapsed()) * 1e-6;
}

// Prints `"name": {"mean_ms": …, …}` of playback, stepping through frames as playback does: the
// views that changed ask for an update, and the event loop paints them (the 3D render included)
// before the next frame.
void profilePlayback(MainWindow& window, Eigen::Index maxFrames)
{
  auto& document = window.document();
  const Eigen::Index frames = std::min(document.take().frameCount(), maxFrames);
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(frames));
  const ui::FaceMeshScene& mesh = window.sessionScene().faceMesh();
  double deformSum = 0.0;
  Eigen::Index deformCount = 0;
  QElapsedTimer total;
  total.start();
  for (Eigen::Index f = 0; f < frames; ++f) {
    QElapsedTimer clock;
    clock.start();
    document.setCurrentFrame(f);
    QApplication::processEvents();
    times.push_back(msSince(clock));
    if (mesh.lastDeformMs() >= 0.0) {
      deformSum += mesh.lastDeformMs();
      ++deformCount;
    }
  }
  const double seconds = static_cast<double>(total.nsecsElapsed()) * 1e-9;
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  auto percentile = [&](double p) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1))];
  };
  double mean = 0.0;
  for (double t : times)
    mean += t;
  mean /= std::max<double>(static_cast<double>(times.size()), 1.0);
  std::cout << ", \"frames\": " << frames << ", \"seconds\": " << seconds << ", \"mean_ms\": " << mean
            << ", \"median_ms\": " << percentile(0.5) << ", \"p95_ms\": " << percentile(0.95)
            << ", \"max_ms\": " << (sorted.empty() ? 0.0 : sorted.back());
  if (deformCount > 0)  // with --mesh: the face rig's deform alone, per frame
    std::cout << ", \"mesh_deform_ms_mean\": " << deformSum / static_cast<double>(deformCount);
}

// Undoes what an operation pushed, so the next one starts from the opened take.
void undoBackTo(ui::TakeDocument& document, int index)
{
  while (document.undoStack()->index() > index)
    document.undoStack()->undo();
}

// The longest UI stall while each cleaning step computes its preview, as `"name": ms` pairs.
void profilePreviews(MainWindow& window, UiStallMeter& meter)
{
  ui::CleaningPanel* panel = window.cleaningPanel();
  std::cout << ", \"preview_stall_ms\": {";
  bool first = true;
  // Serves the event loop until the panel's preview is current (or `seconds` passed), woken by
  // the end of its job (or every 50 ms: a debounce timer may start the next one).
  auto waitForPreview = [panel](double seconds) {
    QElapsedTimer clock;
    clock.start();
    while (!panel->previewReady() && static_cast<double>(clock.elapsed()) < 1000.0 * seconds) {
      QEventLoop wait;
      QObject::connect(&panel->jobs(), &ui::JobRunner::finished, &wait, &QEventLoop::quit);
      QTimer::singleShot(50, &wait, &QEventLoop::quit);
      wait.exec();
    }
  };
  for (ui::CleaningStep* step : panel->steps()) {
    panel->setCurrentStep(step);
    if (panel->isVisible())
      waitForPreview(30.0);  // the tab change's own preview (made only while the dock shows)
    meter.start();
    panel->refresh();
    waitForPreview(600.0);
    std::cout << (first ? "" : ", ") << '"' << step->title().toStdString() << "\": " << meter.stop();
    first = false;
  }
  std::cout << '}';
}

// With a reference video shown: the UI thread's longest stall while the timeline is scrubbed
// as a drag does (a frame change every 16 ms: jumps across the take, steps back and forward),
// first with the video paused (the reference: the rest of the studio redrawing), then showing
// it; and how often the exact video frame was already shown when the next change came.
void profileVideoScrub(MainWindow& window, UiStallMeter& meter)
{
  ui::ReferenceVideoPanel* panel = window.referenceVideoPanel();
  if (panel == nullptr || !panel->video().isOpen())
    return;
  auto& document = window.document();
  const Eigen::Index frames = document.take().frameCount();
  constexpr int kChanges = 240;
  int over30 = 0, over16 = 0;
  auto scrub = [&](int& exact) {
    Random random(7);
    exact = 0;
    document.setCurrentFrame(0);
    QApplication::processEvents();
    meter.start();
    for (int i = 0; i < kChanges; ++i) {
      const Eigen::Index now = document.currentFrame();
      const Eigen::Index next = i % 3 == 0 ? static_cast<Eigen::Index>(random.uniform() * static_cast<double>(frames - 1))
                                           : std::clamp<Eigen::Index>(now + (i % 3 == 1 ? -5 : 1), 0, frames - 1);
      document.setCurrentFrame(next);
      QEventLoop wait;
      QTimer::singleShot(16, &wait, &QEventLoop::quit);
      wait.exec();
      if (panel->video().wantedFrame() == panel->video().imageFrame())
        ++exact;
    }
    const double longest = meter.stop();
    over30 = meter.stallsOver(30.0);
    over16 = meter.stallsOver(16.0);
    return longest;
  };
  int exact = 0;
  panel->video().setActive(false);
  const double without = scrub(exact);
  const int pausedOver30 = over30, pausedOver16 = over16;
  panel->video().setActive(true);
  const double with = scrub(exact);
  std::cout << ", \"video_scrub_stall_ms\": " << with << ", \"scrub_stall_ms_video_paused\": " << without
            << ", \"video_scrub_stalls_over_16ms\": " << over16 << ", \"video_scrub_stalls_over_30ms\": " << over30
            << ", \"paused_scrub_stalls_over_16ms\": " << pausedOver16
            << ", \"paused_scrub_stalls_over_30ms\": " << pausedOver30
            << ", \"video_scrub_changes\": " << kChanges << ", \"video_exact_within_16ms\": " << exact
            << ", \"video_size\": \"" << panel->video().info().width << 'x' << panel->video().info().height << '"';
}

} // namespace

int profileStudio(MainWindow& window, const OpenFigures& open, Eigen::Index maxFrames)
{
  window.resize(1280, 800);
  window.show();
  QApplication::processEvents();
  auto& document = window.document();
  std::cout << "{\"open_seconds\": " << open.seconds << ", \"open_stall_ms\": " << open.stallMs;
  profilePlayback(window, maxFrames);
  std::cout << ", \"take_rate_hz\": " << document.take().frameRate();

  UiStallMeter meter;
  profileVideoScrub(window, meter);
  const int start = document.undoStack()->index();
  meter.start();
  window.labellingActions()->trackAndLabel();
  std::cout << ", \"track_stall_ms\": " << meter.stop();
  undoBackTo(document, start);
  meter.start();
  const auto swaps = window.labellingActions()->findSwaps();
  std::cout << ", \"swaps_stall_ms\": " << meter.stop() << ", \"swaps\": " << (swaps ? swaps->size() : 0);
  profilePreviews(window, meter);

  // Autosave's share of the UI thread: the copy of the take handed to its worker.
  QElapsedTimer copyClock;
  copyClock.start();
  const Take copy = document.take();
  std::cout << ", \"autosave_ui_copy_ms\": " << msSince(copyClock) << ", \"autosave_copy_frames\": " << copy.frameCount()
            << "}\n";
  return 0;
}

} // namespace mocap::studio
