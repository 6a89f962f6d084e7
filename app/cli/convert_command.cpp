#include "take_input.h"
#include "take_output.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "rig_input.h"

#include "mocap/base/file_io.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/io/take_io.h"
#include "mocap/io/weight_output.h"
#include "mocap/math/key_reduction.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

struct ConvertArguments
{
  std::string input, output;
  std::optional<std::string> units, inputUnits, up, rig, shapes, map;
  std::optional<double> reduce;  // FBX: key tolerance in mm
};

/// The markers as FBX, with --reduce each curve keyed within the tolerance (given in mm, applied in
/// the take's units); says how many keys were kept.
void writeFbx(const ConvertArguments& arguments, const Take& take)
{
  KeyCount counted;
  FbxCurveKeys keys;
  if (arguments.reduce)
    keys = {*arguments.reduce / millimetresPer(take.units()), &counted};
  writeMarkersFbx(arguments.output, take, parseFbxUpAxis(arguments.up.value_or("z")).value(), keys);
  noteLeftOut(take, arguments.output);
  if (arguments.reduce)
    std::cout << "kept " << counted.after << " of " << counted.before << " keys, largest error "
              << counted.maxError * millimetresPer(take.units()) << " mm (tolerance " << *arguments.reduce << " mm)\n";
}

/// A Live Link Face recording (IN.csv) as weight curves on --rig: its 52 curves through --map (by
/// default rigMapFromLiveLinkFace) onto the rig's shapes, one row per frame at the recording's rate.
int convertRecording(const ConvertArguments& arguments)
{
  const std::string extension = lowerExtension(arguments.output);
  if (extension != "glb" && extension != "fbx")
    throw UsageError("a Live Link Face recording converts to the rig with animated weights (.glb, .fbx), not '" +
                     arguments.output + "'");
  if (arguments.units || arguments.inputUnits || arguments.reduce)
    throw UsageError("--units, --input-units and --reduce (mm) apply to a take's markers; a recording holds weights");
  if (arguments.up && extension != "fbx")
    throw UsageError("--up applies to .fbx output only");
  std::optional<RetargetMap> map;
  if (arguments.map)
    map = readRetargetMapByNameOrPath(*arguments.map);
  const BlendshapeRig rig = readInputRig(*arguments.rig, arguments.shapes.value_or(""), std::nullopt);
  const LiveLinkFaceRecording recording = readLiveLinkFaceCsv(arguments.input);
  const double rate = liveLinkFaceRate(recording);
  if (!(rate > 0.0))
    throw UsageError(arguments.input + ": a recording needs two rows or more with increasing timecodes");
  const Eigen::MatrixXd weights = liveLinkFaceWeightsOnRig(recording.weights, rig.shapeNames(), map);
  WeightOutput options;
  options.frameRate = rate;
  if (arguments.up)
    options.fbx.up = parseFbxUpAxis(*arguments.up).value();
  options.startSeconds = liveLinkFaceSeconds(recording.timecodes.front());
  writeWeightOutput(arguments.output, rig, weights, options);
  std::cout << "wrote " << recording.timecodes.size() << " frames at " << rate << " Hz from "
            << recording.timecodes.front() << " onto " << rig.shapeCount() << " shapes: " << arguments.output << '\n';
  return kExitOk;
}

int runConvert(const ConvertArguments& arguments)
{
  if (lowerExtension(arguments.input) == "csv") {
    if (!arguments.rig)
      throw UsageError("a .csv IN is read as a Live Link Face recording: give the rig it animates with --rig RIG");
    return convertRecording(arguments);
  }
  if (arguments.rig || arguments.shapes || arguments.map)
    throw UsageError("--rig, --shapes and --map apply to a Live Link Face recording (IN.csv)");
  const std::string& input = arguments.input;
  const std::string& output = arguments.output;
  const TakeFormat format = formatFromPath(output);  // reject an unknown output type before the read
  if ((arguments.up || arguments.reduce) && format != TakeFormat::Fbx)
    throw UsageError("--up and --reduce apply to .fbx output only");
  std::error_code ec;
  if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
    throw UsageError("IN and OUT are the same file; write to a new file");
  std::optional<LengthUnit> units;
  if (arguments.units)
    units = parseLengthUnit(*arguments.units);
  Take take = readInputTake(input);
  if (arguments.inputUnits)  // the file's unit was wrong or missing: the numbers stay, their unit is named
    take.setUnits(*parseLengthUnit(*arguments.inputUnits));
  if (units)
    take.convertUnits(*units);
  if (arguments.up || arguments.reduce)
    writeFbx(arguments, take);
  else
    writeOutputTake(take, output);
  return kExitOk;
}

} // namespace

Command addConvert(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("convert", "convert between .c3d .trc (read/write) and .csv .bvh .fbx (write); a Live Link "
                                      "Face recording (.csv) to a rig's animated weights (.glb, .fbx)");
  const auto arguments = std::make_shared<ConvertArguments>();
  command->add_option("IN", arguments->input, "the take to read")->required();
  command->add_option("OUT", arguments->output, "the file to write; its extension names the format")->required();
  // parseLengthUnit also reads "metres", "Centimeter", ...: it is the check.
  const CLI::Validator lengthUnit(
      [](const std::string& text) -> std::string {
        return parseLengthUnit(text) ? "" : "'" + text + "' is not mm, cm or m";
      },
      "", "length unit");
  command->add_option("--units", arguments->units, "rescale the positions to these units")
      ->type_name("mm|cm|m")
      ->check(lengthUnit);
  command->add_option("--input-units", arguments->inputUnits,
                      "the unit IN's positions are in, when the file names none or the wrong one (nothing is "
                      "rescaled; applied before --units)")
      ->type_name("mm|cm|m")
      ->check(lengthUnit);
  oneOf(command->add_option("--up", arguments->up, "FBX: the take's up axis, declared in the file (default z)"),
        std::string("y|z"));
  numberIn(command->add_option("--reduce", arguments->reduce,
                               "FBX: keep each curve's fewest keys whose linear interpolation stays within this "
                               "many mm of every frame")
               ->type_name("MM"),
           0.0, 1000.0);
  command->add_option("--rig", arguments->rig,
                      "IN.csv: the rig the recording animates, a glTF rig or an OBJ/PLY neutral with --shapes")
      ->type_name("RIG.glb|NEUTRAL.obj");
  command->add_option("--shapes", arguments->shapes, "IN.csv: folder with one OBJ per shape of --rig")->type_name("DIR");
  command->add_option("--map", arguments->map,
                      "IN.csv: the recording's curves onto the rig's shapes: a shipped map (arkit_to_ict, …) or a "
                      "map file (default: by name, arkit_to_ict for ICT names)")
      ->type_name("NAME|MAP.json");
  return {command, [arguments] { return runConvert(*arguments); }};
}

} // namespace mocap::cli
