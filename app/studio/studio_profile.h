#pragma once

#include <Eigen/Core>

namespace mocap::studio {

class MainWindow;

/// What opening the take cost: wall time, and the UI thread's longest stall meanwhile.
struct OpenFigures
{
  double seconds = 0.0;
  double stallMs = 0.0;
};

/// mocap-studio --profile: steps through the first `maxFrames` frames as playback does, then
/// runs Track and Label, the swap search and each cleaning step's preview as a user would (each
/// undone after), and prints one JSON object: frame times, and the UI thread's longest stall
/// (ms) during each of these, during the open and for the autosave's copy; with a reference video
/// shown (--video), also while the timeline is scrubbed with it, and with it paused for reference.
/// Returns the exit code.
int profileStudio(MainWindow& window, const OpenFigures& open, Eigen::Index maxFrames);

} // namespace mocap::studio
