// `mocap track IN -o OUT [--template TAKE_OR_MARKERSET] [--max-speed MM_PER_FRAME] [--keep-fragments]
// [--rate HZ] [--save-marker-set FILE.json] [--json]`: unlabelled points (a C3D/TRC whose markers
// are unlabelled fragments, or a CSV of frame,x,y,z points) into labelled trajectories
// (core/include/mocap/tracking/take_tracking.h).
#include "take_input.h"
#include "take_output.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"
#include "mocap/tracking/take_tracking.h"

#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

MarkerSet loadTemplate(const std::string& path)
{
  if (lowerExtension(path) == "json")
    return readMarkerSet(path);
  std::vector<std::string> warnings;
  return markerSetFromTake(readTake(path, &warnings));
}

std::string trackReportJson(const std::string& input, const std::string& output, const Take& result,
                            const TrackReport& report)
{
  JsonWriter json;
  json.beginObject();
  json.key("input").value(input);
  json.key("output").value(output);
  json.key("labelled").value(report.labelled);
  json.key("input_labelled_markers").value(static_cast<std::int64_t>(report.labelledMarkers));
  json.key("input_unlabelled_markers").value(static_cast<std::int64_t>(report.unlabelledMarkers));
  json.key("gate").value(report.gate);
  json.key("fragments").value(static_cast<std::int64_t>(report.fragments));
  json.key("labelled_fragments").value(static_cast<std::int64_t>(report.labelledFragments));
  json.key("unlabelled_fragments").value(static_cast<std::int64_t>(report.unlabelledFragments));
  json.key("labelled_samples").value(static_cast<std::int64_t>(report.labelledSamples));
  json.key("unlabelled_samples").value(static_cast<std::int64_t>(report.unlabelledSamples));
  json.key("anchor_frame").value(report.anchorFrame >= 0 ? result.firstFrame() + report.anchorFrame : -1);
  json.key("scale").value(report.scale);
  json.key("markers").value(static_cast<std::int64_t>(result.markerCount()));
  json.key("valid_fraction").value(result.validFraction());
  json.endObject();
  return json.str() + "\n";
}

struct TrackArguments
{
  std::string input, output;
  std::optional<std::string> templ, saveMarkerSet;
  double maxSpeedMm = 0.0;  // 0: the tracker's own gate
  bool keepFragments = false;
  double rate = 100.0;  // of a CSV, which does not say
  bool json = false;
};

int runTrack(const TrackArguments& arguments)
{
  const std::string& input = arguments.input;
  const std::string& output = arguments.output;
  (void)formatFromPath(output);  // reject an unknown output type before the read
  TrackOptions options;
  const double maxSpeedMm = arguments.maxSpeedMm;
  options.retrack = !arguments.keepFragments;
  std::optional<MarkerSet> set;
  if (arguments.templ)
    set = loadTemplate(*arguments.templ);

  Take result;
  TrackReport report;
  if (lowerExtension(input) == "csv") {
    const double rate = arguments.rate;
    const LengthUnit units = set ? set->units : LengthUnit::Millimetre;
    options.tracker.maxSpeed = maxSpeedMm / millimetresPer(units);
    result = trackPointCloud(readPointCloudCsv(input, rate), set ? &*set : nullptr, options, &report);
  } else {
    const Take take = readInputTake(input);
    options.tracker.maxSpeed = maxSpeedMm / millimetresPer(take.units());
    result = trackTake(take, set ? &*set : nullptr, options, &report);
  }
  writeOutputTake(result, output);
  if (arguments.saveMarkerSet)
    writeMarkerSet(markerSetFromTake(result), *arguments.saveMarkerSet);
  if (arguments.json) {
    std::cout << trackReportJson(input, output, result, report);
  } else {
    std::cout << output << ": " << report.labelledFragments << " of " << report.fragments
              << " fragments labelled (" << report.labelledSamples << " samples), " << report.unlabelledFragments
              << " left unlabelled (" << report.unlabelledSamples << " samples)\n";
  }
  return kExitOk;
}

} // namespace

Command addTrack(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "track", "unlabelled points (C3D/TRC fragments or CSV frame,x,y,z) into labelled trajectories");
  const auto a = std::make_shared<TrackArguments>();
  command->add_option("IN", a->input, "unlabelled points: a C3D/TRC of fragments or a CSV of frame,x,y,z")->required();
  command->add_option("-o,--output", a->output, "the labelled take; its extension names the format")
      ->required()
      ->type_name("OUT");
  command->add_option("--template", a->templ, "the labels: a labelled take or a marker-set JSON file")
      ->type_name("TAKE_OR_MARKERSET");
  numberIn(command->add_option("--max-speed", a->maxSpeedMm, "gate of the point tracker (default: from the data)")
               ->type_name("MM_PER_FRAME"),
           1e-6, 1e6);
  command->add_flag("--keep-fragments", a->keepFragments, "label the fragments as delivered, without re-tracking");
  numberIn(command->add_option("--rate", a->rate, "frame rate of a CSV input")->type_name("HZ"), 1e-3, 1e6)
      ->capture_default_str();
  command->add_option("--save-marker-set", a->saveMarkerSet, "also write the result's marker set")
      ->type_name("FILE.json");
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runTrack(*a); }};
}

} // namespace mocap::cli
