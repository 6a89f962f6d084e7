#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/io/bvh_writer.h"
#include "mocap/cleaning/clean_pipeline.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/take_io.h"

#include <iostream>
#include <sstream>

namespace mocap::cli {

namespace {

std::optional<SpikeOptions> spikeOptions(const Arguments& arguments)
{
  SpikeOptions options;
  if (const auto name = arguments.value("--spikes")) {
    if (*name == "off")
      return std::nullopt;
    const auto method = parseSpikeMethod(*name);
    if (!method)
      throw UsageError("--spikes must be paper, robust or off, not '" + *name + "'");
    options.method = *method;
  }
  if (const auto factor = arguments.number("--spike-factor", 1e-6, 1e6))
    options.factor = *factor;
  if (const auto threshold = arguments.number("--spike-threshold", 1e-6, 1e6))
    options.threshold = *threshold;
  return options;
}

std::optional<FillOptions> fillOptions(const Arguments& arguments)
{
  FillOptions options;
  if (const auto name = arguments.value("--fill")) {
    if (*name == "off")
      return std::nullopt;
    const auto method = parseFillMethod(*name);
    if (!method)
      throw UsageError("--fill: unknown method '" + *name + "'");
    options.method = *method;
  }
  const auto maxGap = arguments.integer("--max-gap", 0, 1LL << 40);
  const auto maxGapSeconds = arguments.number("--max-gap-seconds", 0.0, 1e9);
  if (maxGap && maxGapSeconds)
    throw UsageError("give the longest gap as --max-gap N (frames) or --max-gap-seconds S, not both");
  if (maxGap) {
    options.maxGap = static_cast<Eigen::Index>(*maxGap);
    if (*maxGap == 0)
      options.maxGapSeconds = 0.0;  // --max-gap 0: unlimited, as before
  }
  if (maxGapSeconds)
    options.maxGapSeconds = *maxGapSeconds;
  options.extrapolate = arguments.has("--extrapolate");
  if (const auto minValid = arguments.number("--min-valid", 0.0, 1.0))
    options.minValidFraction = *minValid;
  if (const auto neighbours = arguments.integer("--neighbours", 1, 1000))
    options.neighbours = static_cast<int>(*neighbours);
  return options;
}

std::optional<SmoothOptions> smoothOptions(const Arguments& arguments)
{
  SmoothOptions options;
  if (const auto name = arguments.value("--smooth")) {
    if (*name == "off")
      return std::nullopt;
    const auto method = parseSmoothMethod(*name);
    if (!method)
      throw UsageError("--smooth must be bspline, butterworth, gcvspl, savgol or off, not '" + *name + "'");
    options.method = *method;
  }
  if (const auto order = arguments.integer("--order", 2, 7))
    options.degree = static_cast<int>(*order);
  if (const auto spacing = arguments.number("--knot-spacing", 1.0, 1e6))
    options.knotSpacing = *spacing;
  if (const auto cutoff = arguments.number("--cutoff", 1e-6, 1e6))
    options.cutoffHz = *cutoff;
  return options;
}

std::string reportJson(const std::string& input, const std::string& output, const Take& take,
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
  json.key("valid_fraction").value(take.validFraction());
  json.endObject();
  return json.str() + "\n";
}

} // namespace

namespace {

/// One history step per pipeline step that ran, so the written take says how it was cleaned.
void appendHistory(Take& take, const CleanOptions& options, const CleanReport& report)
{
  auto step = [&take](std::string operation, std::vector<std::pair<std::string, std::string>> parameters,
                      std::int64_t samples) {
    ProcessingStep s;
    s.operation = std::move(operation);
    s.parameters = std::move(parameters);
    s.firstFrame = take.firstFrame();
    s.lastFrame = take.firstFrame() + take.frameCount() - 1;
    s.samples = samples;
    s.time = currentUtcTime();
    s.tool = "mocap clean";
    take.history().push_back(std::move(s));
  };
  auto number = [](double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  };
  if (!options.stabilizeLabels.empty()) {
    std::string labels;
    for (const std::string& label : options.stabilizeLabels)
      labels += (labels.empty() ? "" : ",") + label;
    step("stabilize head", {{"reference markers", labels}, {"kept", options.keepStabilized ? "yes" : "no"}}, 0);
  }
  if (options.spikes)
    step("repair spikes",
         {{"method", std::string(spikeMethodName(options.spikes->method))},
          {"factor", number(options.spikes->factor)},
          {"threshold", number(options.spikes->threshold)}},
         static_cast<std::int64_t>(report.spikes.size()));
  if (options.fill) {
    const Eigen::Index longest = longestGapFrames(*options.fill, take.frameRate());
    step("fill gaps",
         {{"method", std::string(fillMethodName(options.fill->method))},
          {"max gap", longest == 0 ? std::string("unlimited") : std::to_string(longest) + " frames"},
          {"extrapolate", options.fill->extrapolate ? "yes" : "no"},
          {"min valid", number(options.fill->minValidFraction)},
          {"neighbours", std::to_string(options.fill->neighbours)}},
         static_cast<std::int64_t>(report.filledSamples));
  }
  if (options.smooth)
    step("smooth", {{"method", std::string(smoothMethodName(options.smooth->method))}},
         static_cast<std::int64_t>(report.smoothedSamples));
}

} // namespace

int runClean(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {"--keep-stabilized", "--extrapolate"},
                            {"-o", "--output", "--spikes", "--spike-factor", "--spike-threshold", "--fill", "--max-gap",
                             "--max-gap-seconds", "--min-valid", "--neighbours", "--smooth", "--order",
                             "--knot-spacing", "--cutoff", "--stabilize", "--report"});
  const auto [input, output] = arguments.inputAndOutput();
  CleanOptions options;
  options.spikes = spikeOptions(arguments);
  options.fill = fillOptions(arguments);
  options.smooth = smoothOptions(arguments);
  if (const auto labels = arguments.value("--stabilize"))
    options.stabilizeLabels = splitList(*labels, "--stabilize");
  options.keepStabilized = arguments.has("--keep-stabilized");

  std::vector<std::string> warnings;
  Take take = readTake(input, &warnings);
  for (const auto& w : warnings)
    std::cerr << input << ": warning: " << w << '\n';
  const CleanReport report = cleanTake(take, options);
  appendHistory(take, options, report);
  if (formatFromPath(output) == TakeFormat::Bvh && report.headMotion && !options.keepStabilized) {
    // BVH carries the head motion in its root joint; the markers go in head space.
    removeHeadMotion(take, *report.headMotion);
    writeBvh(take, output, BvhOptions{report.headMotion->poses});
  } else {
    writeTake(take, output);
  }
  if (const auto reportFile = arguments.value("--report"))
    writeFileAtomically(*reportFile, reportJson(input, output, take, options, report));
  return kExitOk;
}

} // namespace mocap::cli
