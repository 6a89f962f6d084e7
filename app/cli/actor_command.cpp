// `mocap actor`: an actor profile from a neutral frame or take and, optionally, a range-of-motion
// take (issue 32): the neutral marker positions, the binding and each shape's extent.
#include "take_input.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "rig_input.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/deform/actor_calibration.h"
#include "mocap/deform/actor_profile_io.h"
#include "mocap/deform/retarget.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

struct ActorArguments
{
  std::string rigPath, shapesPath, bindingPath, neutral, out, name;
  std::optional<std::string> rom, stabilize;
  ActorRangeOptions range;
  bool json = false;
};

/// TAKE:FRAME split into the take and the frame; TAKE alone (or a file whose name has a colon).
std::pair<std::string, std::optional<long long>> takeAndFrame(const std::string& text)
{
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || std::filesystem::exists(text))
    return {text, std::nullopt};
  const std::string frame = text.substr(colon + 1);
  std::size_t used = 0;
  long long number = 0;
  try {
    number = std::stoll(frame, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (frame.empty() || used != frame.size())
    throw UsageError("--neutral: '" + frame + "' is not a frame number (TAKE or TAKE:FRAME)");
  return {text.substr(0, colon), number};
}

Take readStabilized(const std::string& path, const std::optional<std::string>& stabilize, LengthUnit units)
{
  Take take = readInputTake(path);
  if (take.units() != units)
    take.convertUnits(units);
  if (stabilize)
    (void)stabilizeTake(take, splitList(*stabilize, "--stabilize"));
  return take;
}

void printJson(const ActorArguments& arguments, const ActorProfile& profile, const std::optional<ActorRange>& range)
{
  JsonWriter json;
  json.beginObject();
  json.key("name").value(profile.name);
  json.key("markers").value(static_cast<std::int64_t>(profile.labels.size()));
  json.key("neutral").value(profile.neutralSource);
  json.key("range_of_motion");
  if (range)
    json.value(profile.romSource);
  else
    json.null();
  json.key("shapes").beginArray();
  for (std::size_t s = 0; s < profile.shapes.size(); ++s) {
    const auto i = static_cast<Eigen::Index>(s);
    json.beginObject();
    json.key("name").value(profile.shapes[s]);
    json.key("extent").value(profile.extent(i));
    json.key("rom_max").value(profile.romMaximum(i));
    if (range) {
      json.key("reached").value(static_cast<bool>(range->reached[s]));
      json.key("clipped").value(static_cast<bool>(range->clipped[s]));
    }
    json.endObject();
  }
  json.endArray();
  json.key("output").value(arguments.out);
  json.endObject();
  std::cout << json.str() << '\n';
}

void printSummary(const ActorArguments& arguments, const ActorProfile& profile, const std::optional<ActorRange>& range)
{
  std::cout << "actor " << profile.name << ": neutral of " << profile.labels.size() << " markers from "
            << profile.neutralSource << '\n';
  if (range) {
    std::string unreached, clipped;
    int reached = 0;
    for (std::size_t s = 0; s < profile.shapes.size(); ++s) {
      reached += range->reached[s] ? 1 : 0;
      if (!range->reached[s])
        unreached += (unreached.empty() ? "" : ", ") + profile.shapes[s];
      if (range->clipped[s])
        clipped += (clipped.empty() ? "" : ", ") + profile.shapes[s];
    }
    std::cout << "range of motion: " << reached << " of " << profile.shapes.size() << " shapes reached\n";
    if (!unreached.empty())
      std::cout << "not reached (extent 1, as the rig): " << unreached << '\n';
    if (!clipped.empty())
      std::cout << "warning: at the calibration's bound " << numberText(arguments.range.maximumWeight)
                << ", so not measured (extent 1; the markers may not see them): " << clipped << '\n';
  }
  std::cout << "wrote " << arguments.out << '\n';
}

int runActor(const ActorArguments& arguments)
{
  if (lowerExtension(arguments.out) != "json")
    throw UsageError("-o must be a .json file (the actor profile), not '" + arguments.out + "'");
  const auto [neutralPath, neutralFrame] = takeAndFrame(arguments.neutral);
  const BlendshapeRig rig = readInputRig(arguments.rigPath, arguments.shapesPath, std::nullopt);
  const MeshBinding binding = readBinding(arguments.bindingPath, rig.neutral.vertexCount());
  std::vector<std::string> labels;
  for (const MarkerBinding& marker : binding.markers)
    labels.push_back(marker.label);
  Take neutralTake = readInputTake(neutralPath);
  const LengthUnit units = neutralTake.units();
  if (arguments.stabilize)
    (void)stabilizeTake(neutralTake, splitList(*arguments.stabilize, "--stabilize"));
  const std::string takeName = std::filesystem::path(neutralPath).filename().string();
  const PointSet neutral = neutralFrame ? neutralFromFrame(neutralTake, labels, *neutralFrame)
                                        : neutralFromTake(neutralTake, labels);
  const std::string name = arguments.name.empty() ? std::filesystem::path(arguments.out).stem().string() : arguments.name;
  ActorProfile profile =
      makeActorProfile(name, binding, rig, neutral, units,
                       neutralFrame ? takeName + ":" + std::to_string(*neutralFrame) : takeName + " (median)");
  std::optional<ActorRange> range;
  if (arguments.rom) {
    const Take rom = readStabilized(*arguments.rom, arguments.stabilize, units);
    range = calibrateActorRange(profile, rig, rom, std::filesystem::path(*arguments.rom).filename().string(),
                                arguments.range);
  }
  writeActorProfile(arguments.out, profile);
  if (arguments.json)
    printJson(arguments, profile, range);
  else
    printSummary(arguments, profile, range);
  return kExitOk;
}

} // namespace

Command addActor(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "actor", "an actor profile: neutral marker positions and, from a range-of-motion take, each shape's extent");
  const auto a = std::make_shared<ActorArguments>();
  command->add_option("--rig", a->rigPath, "the rig: its neutral (.obj, .ply) with --shapes, or a glTF rig (.glb, .gltf)")
      ->required()
      ->type_name("NEUTRAL.obj|RIG.glb");
  command->add_option("--shapes", a->shapesPath, "folder with one OBJ per shape, named after it")->type_name("DIR");
  command->add_option("--binding", a->bindingPath, "the binding mocap bind wrote")->required()->type_name("BIND.json");
  command->add_option("--neutral", a->neutral,
                      "the actor's neutral: one frame of a take, or a neutral take (each marker's median)")
      ->required()
      ->type_name("TAKE[:FRAME]");
  command->add_option("--rom", a->rom, "a range-of-motion take reaching each shape's maximum once")->type_name("TAKE");
  command->add_option("--stabilize", a->stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABELS");
  numberIn(command->add_option("--rom-bound", a->range.maximumWeight,
                               "the calibration solve's upper bound on a weight (above 1, so an exaggerated shape is "
                               "measured, not clipped)")
               ->type_name("W"),
           1.0, 100.0)
      ->capture_default_str();
  command->add_option("--name", a->name, "the actor's name (default: the output's name)")->type_name("NAME");
  command->add_option("-o", a->out, "the actor profile")->required()->type_name("ACTOR.json");
  command->add_flag("--json", a->json, "print JSON: each shape's extent, ROM maximum, reached and clipped");
  return {command, [a] { return runActor(*a); }};
}

} // namespace mocap::cli
