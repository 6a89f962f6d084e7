#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/json_writer.h"
#include "mocap/model/sample_patch.h"
#include "mocap/evaluation/smoothing_evaluation.h"
#include "mocap/cleaning/spike_detection.h"
#include "mocap/io/take_io.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

void writeSmoothnessTableJson(const std::string& file, const Take& take, const SmoothnessTable& table,
                              double knotSpacing)
{
  JsonWriter json;
  json.beginObject();
  json.key("take").value(file);
  json.key("measure").value(smoothnessMeasureDefinition());
  json.key("method").value("least-squares clamped B-spline, order = degree (eqs 11-12)");
  json.key("knot_spacing").value(knotSpacing);
  json.key("markers").beginArray();
  for (Eigen::Index m : table.markers)
    json.value(take.label(m));
  json.endArray();
  json.key("raw_smoothness").value(table.rawSmoothness);
  json.key("rows").beginArray();
  for (const SmoothnessRow& row : table.rows) {
    json.beginObject();
    json.key("order").value(row.order);
    json.key("preprocessing").value(!row.preprocessing.empty());
    if (!row.preprocessing.empty())
      json.key("preprocessing_method").value(row.preprocessing);
    json.key("smoothness").value(row.smoothness);
    json.key("per_marker").beginArray();
    for (double v : row.perMarker)
      json.value(v);
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.endObject();
  std::cout << json.str() << '\n';
}

void writeSmoothnessTableText(const std::string& file, const SmoothnessTable& table, double knotSpacing)
{
  char line[160];
  std::cout << "take: " << file << "  markers: " << table.markers.size() << "  knot spacing: " << knotSpacing
            << " frames\nmeasure: " << smoothnessMeasureDefinition() << '\n';
  std::snprintf(line, sizeof line, "%-6s %-16s %14s\n", "order", "preprocessing", "smoothness mm^2");
  std::cout << line;
  std::snprintf(line, sizeof line, "%-6s %-16s %14.6g\n", "raw", "", table.rawSmoothness);
  std::cout << line;
  for (const SmoothnessRow& row : table.rows) {
    std::snprintf(line, sizeof line, "%-6d %-16s %14.6g\n", row.order,
                  row.preprocessing.empty() ? "none" : row.preprocessing.c_str(), row.smoothness);
    std::cout << line;
  }
}

struct SmoothTableArguments
{
  std::string file;
  std::optional<std::string> markers;
  SmoothnessTableOptions options;
  // The paper's preprocessing is its own spike test (eqs 8-10); "robust" uses our default detector.
  std::string spikes = std::string(spikeMethodName(SpikeMethod::Paper));
  bool json = false;
};

int runSmoothTable(const SmoothTableArguments& arguments)
{
  const std::string& file = arguments.file;
  SmoothnessTableOptions options = arguments.options;
  const std::optional<SpikeMethod> spikes = parseSpikeMethod(arguments.spikes);  // none for "off"
  const Take take = readTake(file);
  if (arguments.markers)
    options.markers = markerIndices(take, splitList(*arguments.markers, "--markers"));
  if (spikes) {
    SpikeOptions spikeOptions;
    spikeOptions.method = *spikes;
    options.preprocessName = "spikes-" + std::string(spikeMethodName(*spikes));
    options.preprocess = [spikeOptions](Take& t) {
      applyPatches(t, replaceSpikes(t, detectSpikes(t, spikeOptions)));
    };
  }
  const SmoothnessTable table = smoothnessTable(take, options);
  if (arguments.json)
    writeSmoothnessTableJson(file, take, table, options.knotSpacing);
  else
    writeSmoothnessTableText(file, table, options.knotSpacing);
  return kExitOk;
}

} // namespace

Command addSmoothTable(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand("smooth-table", "the paper's Table 1: smoothness per B-spline order");
  const auto a = std::make_shared<SmoothTableArguments>();
  command->add_option("TAKE", a->file, "the take")->required();
  command->add_option("--markers", a->markers, "the markers measured (default: all)")->type_name("A,B,...");
  numberIn(command->add_option("--knot-spacing", a->options.knotSpacing, "B-spline knot spacing, in frames")
               ->type_name("N"),
           1.0, 1e6)
      ->capture_default_str();
  oneOf(command->add_option("--spikes", a->spikes, "spike repair before smoothing"), spikeMethodNames() + "|off")
      ->capture_default_str();
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runSmoothTable(*a); }};
}

} // namespace mocap::cli
