#include "take_input.h"
#include "take_output.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/io/fbx_writer.h"
#include "mocap/io/take_io.h"
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
  std::optional<std::string> units, up;
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

int runConvert(const ConvertArguments& arguments)
{
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
      mocap.add_subcommand("convert", "convert between .c3d .trc (read/write) and .csv .bvh .fbx (write)");
  const auto arguments = std::make_shared<ConvertArguments>();
  command->add_option("IN", arguments->input, "the take to read")->required();
  command->add_option("OUT", arguments->output, "the file to write; its extension names the format")->required();
  // parseLengthUnit also reads "metres", "Centimeter", ...: it is the check.
  command->add_option("--units", arguments->units, "rescale the positions to these units")
      ->type_name("mm|cm|m")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            return parseLengthUnit(text) ? "" : "'" + text + "' is not mm, cm or m";
          },
          "", "length unit"));
  oneOf(command->add_option("--up", arguments->up, "FBX: the take's up axis, declared in the file (default z)"),
        std::string("y|z"));
  numberIn(command->add_option("--reduce", arguments->reduce,
                               "FBX: keep each curve's fewest keys whose linear interpolation stays within this "
                               "many mm of every frame")
               ->type_name("MM"),
           0.0, 1000.0);
  return {command, [arguments] { return runConvert(*arguments); }};
}

} // namespace mocap::cli
