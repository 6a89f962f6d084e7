#include "cli_error.h"
#include "commands.h"

#include "mocap/model/data_loss_record.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_points.h"
#include "mocap/base/json_writer.h"
#include "mocap/model/provenance.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/io/take_io.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

/// How a C3D file's data section was read ("layout"; null for other formats).
void writeLayoutJson(JsonWriter& json, const std::optional<C3dLayoutReport>& layout)
{
  json.key("layout");
  if (!layout) {
    json.null();
    return;
  }
  json.beginObject();
  json.key("data_start_block").value(static_cast<std::int64_t>(layout->dataStartBlock));
  json.key("data_start_source").value(layout->dataStartSource);
  json.key("storage").value(layout->isFloat ? "float" : "integer");
  json.key("frame_bytes").value(static_cast<std::int64_t>(layout->frameBytes));
  json.key("frame_words").value(static_cast<std::int64_t>(layout->frameBytes / 2));
  json.key("analog_values_per_frame").value(static_cast<std::int64_t>(layout->analogValuesPerFrame));
  json.key("declared_frames").value(static_cast<std::int64_t>(layout->declaredFrames));
  json.key("data_bytes").value(static_cast<std::int64_t>(layout->dataBytes));
  json.key("declared_data_bytes").value(static_cast<std::int64_t>(layout->declaredDataBytes));
  json.endObject();
}

/// How many points of each type the take holds ("point_types"), every type listed.
void writePointTypesJson(JsonWriter& json, const Take& take)
{
  const auto counts = pointTypeCounts(take);
  json.key("point_types").beginObject();
  for (std::size_t type = 0; type < counts.size(); ++type)
    json.key(pointTypeName(static_cast<PointType>(type))).value(static_cast<std::int64_t>(counts[type]));
  json.endObject();
}

/// "data_loss": the findings of lost or wrong data this read raises, as text (as before: scripts
/// read strings). "data_loss_findings": those and the ones the take's history holds as
/// acknowledged (no longer raised, still listed), each with its kind.
void writeDataLossJson(JsonWriter& json, const Take& take, const std::vector<std::string>& dataLoss)
{
  json.key("data_loss").beginArray();
  for (const std::string& text : dataLoss)
    json.value(text);
  json.endArray();
  const auto finding = [&json](const std::string& text, bool acknowledged) {
    json.beginObject();
    json.key("finding").value(text);
    json.key("kind").value(dataLossKindName(dataLossKind(text)));
    json.key("acknowledged").value(acknowledged);
    json.endObject();
  };
  json.key("data_loss_findings").beginArray();
  for (const std::string& text : dataLoss)
    finding(text, false);
  for (const DataLossRecord& record : dataLossRecords(take))
    if (record.acknowledged)
      finding(recordedFindingText(record), true);
  json.endArray();
}

void writeInfoJson(const std::string& file, TakeFormat format, const Take& take, const std::vector<Gap>& gaps,
                   const std::vector<std::string>& warnings, const std::vector<std::string>& dataLoss,
                   const std::optional<C3dLayoutReport>& layout)
{
  JsonWriter json;
  json.beginObject();
  json.key("file").value(file);
  json.key("format").value(formatName(format));
  json.key("marker_count").value(static_cast<std::int64_t>(take.markerCount()));
  const std::vector<StateCounts> counts = stateCounts(take);
  json.key("markers").beginArray();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const auto validCount = take.valid().col(m).count();
    const StateCounts& c = counts[static_cast<std::size_t>(m)];
    json.beginObject();
    json.key("label").value(take.label(m));
    json.key("valid_fraction")
        .value(take.frameCount() ? static_cast<double>(validCount) / static_cast<double>(take.frameCount()) : 0.0);
    writeStateCountsJson(json, c);
    json.endObject();
  }
  json.endArray();
  json.key("totals").beginObject();  // the per-marker counts summed
  writeStateCountsJson(json, totalCounts(counts));
  json.endObject();
  json.key("frames").value(static_cast<std::int64_t>(take.frameCount()));
  json.key("frame_rate").value(take.frameRate());
  json.key("duration").value(static_cast<double>(take.frameCount()) / take.frameRate());
  json.key("units").value(unitName(take.units()));
  json.key("first_frame").value(take.firstFrame());
  json.key("analog_channels").value(static_cast<std::int64_t>(take.analog().channelCount()));
  json.key("analog_rate").value(take.analog().rate);
  json.key("analog_labels").beginArray();
  for (const auto& channel : take.analog().channels)
    json.value(channel.label);
  json.endArray();
  json.key("events").beginArray();
  for (const auto& e : take.events())
    json.beginObject().key("label").value(e.label).key("context").value(e.context).key("time").value(e.time).endObject();
  json.endArray();
  json.key("valid_fraction").value(markerValidFraction(take));
  json.key("gap_count").value(static_cast<std::int64_t>(gaps.size()));
  json.key("gaps").beginArray();
  for (const Gap& gap : gaps) {
    json.beginObject();
    json.key("marker").value(take.label(gap.marker));
    json.key("first_frame").value(take.firstFrame() + gap.firstFrame);
    json.key("length").value(static_cast<std::int64_t>(gap.length));
    json.endObject();
  }
  json.endArray();
  json.key("history");
  writeHistoryJson(json, take.history());
  json.key("warnings").beginArray();
  for (const auto& w : warnings)
    json.value(w);
  json.endArray();
  writeDataLossJson(json, take, dataLoss);
  writeLayoutJson(json, layout);
  writePointTypesJson(json, take);
  json.endObject();
  std::cout << json.str() << '\n';
}

/// "filled 180  edited 415  smoothed 30000  stabilized 0": origins, then operations.
void writeCountsText(const StateCounts& c)
{
  std::cout << "filled " << c.filled << "  edited " << c.edited << "  smoothed " << c.smoothed << "  stabilized "
            << c.stabilized << '\n';
}

/// Samples made rather than measured and what was done to samples, per marker and in total, and
/// the processing history.
void writeProvenanceText(const Take& take)
{
  const std::vector<StateCounts> counts = stateCounts(take);
  std::cout << "samples:         ";
  writeCountsText(totalCounts(counts));
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const StateCounts& c = counts[static_cast<std::size_t>(m)];
    if (c.filled + c.edited + c.smoothed + c.stabilized > 0) {
      std::cout << "  " << take.label(m) << "  ";
      writeCountsText(c);
    }
  }
  std::cout << "history:         " << take.history().size() << " step(s)\n";
  for (const ProcessingStep& step : take.history()) {
    std::cout << "  " << step.time << "  " << step.operation;
    for (const auto& [name, value] : step.parameters)
      std::cout << "  " << name << "=" << value;
    std::cout << "  (" << step.samples << " samples, " << step.tool << ")\n";
  }
}

void writeInfoText(const std::string& file, TakeFormat format, const Take& take, const std::vector<Gap>& gaps,
                   const std::vector<std::string>& warnings)
{
  for (const auto& w : warnings)
    std::cerr << file << ": warning: " << w << '\n';
  std::cout << "file:            " << file << '\n'
            << "format:          " << formatName(format) << '\n'
            << "markers:         " << take.markerCount() << '\n';
  if (const std::string outputs = describeModelOutputs(take); !outputs.empty())
    std::cout << "  of which        " << outputs << ", left out of the valid fraction and gaps\n";
  std::cout
            << "frames:          " << take.frameCount() << " (first frame " << take.firstFrame() << ")\n"
            << "frame rate:      " << take.frameRate() << " Hz\n"
            << "units:           " << unitName(take.units()) << '\n'
            << "analog channels: " << take.analog().channelCount();
  if (take.analog().channelCount() > 0)
    std::cout << " at " << take.analog().rate << " Hz";
  std::cout << '\n' << "events:          " << take.events().size() << '\n';
  char fraction[32];
  std::snprintf(fraction, sizeof fraction, "%.2f %%", 100.0 * markerValidFraction(take));
  std::cout << "valid samples:   " << fraction << '\n' << "gaps:            " << gaps.size() << '\n';
  for (const Gap& gap : gaps)
    std::cout << "  " << take.label(gap.marker) << "  frame " << take.firstFrame() + gap.firstFrame << "  length "
              << gap.length << '\n';
  writeProvenanceText(take);
}

struct InfoArguments
{
  std::string file;
  bool json = false;
};

int runInfo(const InfoArguments& arguments)
{
  const std::string& file = arguments.file;
  const TakeFormat format = formatFromPath(file);
  std::vector<std::string> warnings, dataLoss;
  std::optional<C3dLayoutReport> layout;
  // A C3D file is read by its own reader, which also says how its data section was laid out.
  const Take take = format == TakeFormat::C3d ? readC3d(file, &warnings, &dataLoss, &layout.emplace())
                                              : readTake(file, &warnings, &dataLoss);
  const std::vector<Gap> gaps = findGaps(take);
  if (arguments.json)
    writeInfoJson(file, format, take, gaps, warnings, dataLoss, layout);
  else
    writeInfoText(file, format, take, gaps, warnings);
  return kExitOk;
}

} // namespace

Command addInfo(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "info", "markers, frames, rate, units, analog channels, valid fraction, every gap and the history");
  const auto arguments = std::make_shared<InfoArguments>();
  command->add_option("FILE", arguments->file, "the take (.c3d, .trc)")->required();
  command->add_flag("--json", arguments->json,
                    "print JSON, with per marker the filled/smoothed/edited sample counts, \"data_loss\", how a "
                    "C3D file's data section was read (\"layout\") and \"point_types\"");
  return {command, [arguments] { return runInfo(*arguments); }};
}

} // namespace mocap::cli
