#include "mocap/batch/clean_report_json.h"

#include "mocap/base/json_writer.h"
#include "mocap/model/marker_points.h"

#include <cstdint>

namespace mocap {

std::string cleanReportJson(const std::string& input, const std::string& output, const Take& take,
                            const CleanOptions& options, const CleanReport& report)
{
  JsonWriter json;
  json.beginObject();
  json.key("input").value(input);
  json.key("output").value(output);
  json.key("stabilize").beginObject();
  json.key("markers").beginArray();
  for (Eigen::Index m : report.stabilizeMarkers)
    json.value(take.label(m));
  json.endArray();
  json.key("unknown_head_poses").value(static_cast<std::int64_t>(report.unknownHeadPoses));
  json.key("kept_stabilized").value(options.keepStabilized);
  json.endObject();
  json.key("spikes").beginObject();
  json.key("method").value(options.spikes ? spikeMethodName(options.spikes->method) : "off");
  json.key("count").value(static_cast<std::int64_t>(report.spikes.size()));
  json.key("repaired_samples").value(static_cast<std::int64_t>(report.repairedSamples));
  json.key("flagged").beginArray();
  for (const SpikeFlag& flag : report.spikes)
    json.beginObject()
        .key("marker")
        .value(take.label(flag.marker))
        .key("frame")
        .value(take.firstFrame() + flag.frame)
        .endObject();
  json.endArray();
  json.endObject();
  json.key("fill").beginObject();
  json.key("method").value(options.fill ? fillMethodName(options.fill->method) : "off");
  if (options.fill) {
    // The options used, so a report says what was left alone on purpose.
    json.key("options").beginObject();
    const FillOptions& fill = *options.fill;
    const Eigen::Index longest = longestGapFrames(fill, take.frameRate());
    json.key("max_gap_frames").value(static_cast<std::int64_t>(longest));  // 0: unlimited
    json.key("max_gap_seconds").value(static_cast<double>(longest) / take.frameRate());
    json.key("unlimited").value(longest == 0);
    json.key("extrapolate").value(fill.extrapolate);
    json.key("min_valid_fraction").value(fill.minValidFraction);
    json.key("neighbours").value(static_cast<std::int64_t>(fill.neighbours));
    json.endObject();
  }
  std::int64_t filledGaps = 0;
  for (const GapFillReport& gap : report.gaps)
    filledGaps += gap.filled ? 1 : 0;
  json.key("filled_gaps").value(filledGaps);
  json.key("unfilled_gaps").value(static_cast<std::int64_t>(report.gaps.size()) - filledGaps);
  json.key("filled_samples").value(static_cast<std::int64_t>(report.filledSamples));
  json.key("gaps").beginArray();
  for (const GapFillReport& gap : report.gaps) {
    json.beginObject();
    json.key("marker").value(take.label(gap.gap.marker));
    json.key("first_frame").value(take.firstFrame() + gap.gap.firstFrame);
    json.key("length").value(static_cast<std::int64_t>(gap.gap.length));
    json.key("filled").value(gap.filled);
    json.key("method").value(gap.method);
    if (!gap.filled) {
      json.key("reason").value(gap.reason);
      json.key("cause").value(unfilledCauseName(gap.cause));
    }
    json.endObject();
  }
  json.endArray();
  json.key("unfilled").beginArray();  // the gaps left open, with why: nothing hidden
  for (const GapFillReport& gap : report.gaps) {
    if (gap.filled)
      continue;
    json.beginObject();
    json.key("marker").value(take.label(gap.gap.marker));
    json.key("first_frame").value(take.firstFrame() + gap.gap.firstFrame);
    json.key("length").value(static_cast<std::int64_t>(gap.gap.length));
    json.key("cause").value(unfilledCauseName(gap.cause));
    json.key("reason").value(gap.reason);
    json.endObject();
  }
  json.endArray();
  json.endObject();
  json.key("smooth").beginObject();
  json.key("method").value(options.smooth ? smoothMethodName(options.smooth->method) : "off");
  json.key("smoothed_samples").value(static_cast<std::int64_t>(report.smoothedSamples));
  json.endObject();
  json.key("valid_fraction").value(markerValidFraction(take));
  json.key("model_outputs").beginObject();  // points no step touched (angles, forces...)
  json.key("untouched").value(static_cast<std::int64_t>(report.modelOutputs.size()));
  json.key("labels").beginArray();
  for (const Eigen::Index m : report.modelOutputs)
    json.value(take.label(m));
  json.endArray();
  json.endObject();
  json.endObject();
  return json.str() + "\n";
}

} // namespace mocap
