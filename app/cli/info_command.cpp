#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/gaps.h"
#include "mocap/json_writer.h"
#include "mocap/take_io.h"

#include <cstdio>
#include <iostream>

namespace mocap::cli {

namespace {

void writeJson(const std::string& file, TakeFormat format, const Take& take, const std::vector<Gap>& gaps,
               const std::vector<std::string>& warnings)
{
  JsonWriter json;
  json.beginObject();
  json.key("file").value(file);
  json.key("format").value(formatName(format));
  json.key("marker_count").value(static_cast<std::int64_t>(take.markerCount()));
  json.key("markers").beginArray();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    const auto validCount = take.valid().col(m).count();
    json.beginObject();
    json.key("label").value(take.label(m));
    json.key("valid_fraction")
        .value(take.frameCount() ? static_cast<double>(validCount) / static_cast<double>(take.frameCount()) : 0.0);
    json.endObject();
  }
  json.endArray();
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
  json.key("valid_fraction").value(take.validFraction());
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
  json.key("warnings").beginArray();
  for (const auto& w : warnings)
    json.value(w);
  json.endArray();
  json.endObject();
  std::cout << json.str() << '\n';
}

void writeText(const std::string& file, TakeFormat format, const Take& take, const std::vector<Gap>& gaps,
               const std::vector<std::string>& warnings)
{
  for (const auto& w : warnings)
    std::cerr << file << ": warning: " << w << '\n';
  std::cout << "file:            " << file << '\n'
            << "format:          " << formatName(format) << '\n'
            << "markers:         " << take.markerCount() << '\n'
            << "frames:          " << take.frameCount() << " (first frame " << take.firstFrame() << ")\n"
            << "frame rate:      " << take.frameRate() << " Hz\n"
            << "units:           " << unitName(take.units()) << '\n'
            << "analog channels: " << take.analog().channelCount();
  if (take.analog().channelCount() > 0)
    std::cout << " at " << take.analog().rate << " Hz";
  std::cout << '\n' << "events:          " << take.events().size() << '\n';
  char fraction[32];
  std::snprintf(fraction, sizeof fraction, "%.2f %%", 100.0 * take.validFraction());
  std::cout << "valid samples:   " << fraction << '\n' << "gaps:            " << gaps.size() << '\n';
  for (const Gap& gap : gaps)
    std::cout << "  " << take.label(gap.marker) << "  frame " << take.firstFrame() + gap.firstFrame << "  length "
              << gap.length << '\n';
}

} // namespace

int runInfo(const std::vector<std::string>& args)
{
  const Arguments arguments(args, {"--json"});
  arguments.expectPositionals(1, "one FILE");
  const std::string& file = arguments.positionals()[0];
  const TakeFormat format = formatFromPath(file);
  std::vector<std::string> warnings;
  const Take take = readTake(file, &warnings);
  const std::vector<Gap> gaps = findGaps(take);
  if (arguments.has("--json"))
    writeJson(file, format, take, gaps, warnings);
  else
    writeText(file, format, take, gaps, warnings);
  return kExitOk;
}

} // namespace mocap::cli
