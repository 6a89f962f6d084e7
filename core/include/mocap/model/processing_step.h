#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mocap {

/// One applied processing step of a take's history (what, with which parameters, on which
/// markers and frames, when, by which tool), so a saved take still says how it was made.
struct ProcessingStep
{
  std::string operation;  ///< what was done, e.g. "fill gaps", "repair spikes", "smooth"
  /// Parameter name → value as the tool showed them (e.g. {"method", "auto"}, {"max gap", "50 frames"}).
  std::vector<std::pair<std::string, std::string>> parameters;
  std::vector<std::string> markers;  ///< labels of the markers it changed; empty: all markers
  std::int64_t firstFrame = 0;       ///< first frame, in the take's numbering (Take::firstFrame() based)
  std::int64_t lastFrame = -1;       ///< last frame; lastFrame < firstFrame: the whole take
  std::int64_t samples = 0;          ///< samples it changed
  std::string time;                  ///< UTC, ISO 8601 ("2026-12-01T19:30:00Z")
  std::string tool;                  ///< e.g. "mocap-studio", "mocap clean"

  /// Equal steps; parameters compare as a set (files store them sorted by name).
  friend bool operator==(const ProcessingStep& a, const ProcessingStep& b)
  {
    auto sorted = [](std::vector<std::pair<std::string, std::string>> p) {
      std::sort(p.begin(), p.end());
      return p;
    };
    return a.operation == b.operation && sorted(a.parameters) == sorted(b.parameters) && a.markers == b.markers &&
           a.firstFrame == b.firstFrame && a.lastFrame == b.lastFrame && a.samples == b.samples &&
           a.time == b.time && a.tool == b.tool;
  }
};

/// The current time as UTC ISO 8601 with seconds ("2026-12-01T19:30:00Z"). O(1).
[[nodiscard]] std::string currentUtcTime();

} // namespace mocap
