// `mocap track IN -o OUT [--template TAKE_OR_MARKERSET] [--max-speed MM_PER_FRAME] [--keep-fragments]
// [--rate HZ] [--save-marker-set FILE.json] [--json]`: unlabelled points (a C3D/TRC whose markers
// are unlabelled fragments, or a CSV of frame,x,y,z points) into labelled trajectories
// (core/include/mocap/tracking/take_tracking.h).
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/marker_set_io.h"
#include "mocap/io/take_io.h"
#include "mocap/tracking/take_tracking.h"

#include <iostream>
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

std::string reportJson(const std::string& input, const std::string& output, const Take& result,
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

} // namespace

int runTrack(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {"--json", "--keep-fragments"},
                            {"-o", "--output", "--template", "--max-speed", "--rate", "--save-marker-set"});
  const auto [input, output] = arguments.inputAndOutput();
  TrackOptions options;
  const double maxSpeedMm = arguments.number("--max-speed", 1e-6, 1e6).value_or(0.0);
  options.retrack = !arguments.has("--keep-fragments");
  std::optional<MarkerSet> set;
  if (const auto templ = arguments.value("--template"))
    set = loadTemplate(*templ);

  Take result;
  TrackReport report;
  if (lowerExtension(input) == "csv") {
    const double rate = arguments.number("--rate", 1e-3, 1e6).value_or(100.0);
    const LengthUnit units = set ? set->units : LengthUnit::Millimetre;
    options.tracker.maxSpeed = maxSpeedMm / millimetresPer(units);
    result = trackPointCloud(readPointCloudCsv(input, rate), set ? &*set : nullptr, options, &report);
  } else {
    std::vector<std::string> warnings;
    const Take take = readTake(input, &warnings);
    for (const auto& w : warnings)
      std::cerr << input << ": warning: " << w << '\n';
    options.tracker.maxSpeed = maxSpeedMm / millimetresPer(take.units());
    result = trackTake(take, set ? &*set : nullptr, options, &report);
  }
  writeTake(result, output);
  if (const auto markerSetFile = arguments.value("--save-marker-set"))
    writeMarkerSet(markerSetFromTake(result), *markerSetFile);
  if (arguments.has("--json")) {
    std::cout << reportJson(input, output, result, report);
  } else {
    std::cout << output << ": " << report.labelledFragments << " of " << report.fragments
              << " fragments labelled (" << report.labelledSamples << " samples), " << report.unlabelledFragments
              << " left unlabelled (" << report.unlabelledSamples << " samples)\n";
  }
  return kExitOk;
}

} // namespace mocap::cli
