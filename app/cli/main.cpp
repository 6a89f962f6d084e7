// `mocap`: the batch command line over mocap::core. Each command lives in its own file and defines
// its options with CLI11; this file builds the command tree, runs the chosen command and maps
// errors to exit codes (1 bad input, 2 bad usage).
#include "cli_error.h"
#include "commands.h"
#include "usage.h"

#include "mocap/base/error.h"

#include <iostream>
#include <memory>

// Its helpers live in the command line's namespace, not at file scope with a using-directive that
// would carry on into the files compiled after it in the same batch (cmake/mocap_unity_build.cmake).
namespace mocap::cli {
namespace {

/// A usage error: one line saying what is wrong, one with the command's synopsis and where to
/// read more.
int usageError(const CLI::App& command, const std::string& message)
{
  const bool top = command.get_parent() == nullptr;
  std::cerr << "mocap" << (top ? "" : " " + command.get_name()) << ": " << message << '\n'
            << (top ? std::string("usage: mocap COMMAND [ARGUMENTS] (mocap --help lists the commands)")
                    : usageHint(command))
            << '\n';
  return kExitBadUsage;
}

/// The command the arguments chose, or `mocap` itself when none was.
const CLI::App& chosen(const CLI::App& mocap, const std::vector<Command>& commands)
{
  for (const Command& command : commands)
    if (command.app->parsed())
      return *command.app;
  return mocap;
}

/// The error for a first argument that names no command, or "" when it names one (or is an
/// option, which CLI11 reports).
std::string unknownCommand(const CLI::App& mocap, int argc, char** argv)
{
  if (argc < 2)
    return "no command given";
  const std::string first = argv[1];
  if (first.empty() || first[0] == '-')
    return {};
  for (const CLI::App* command : mocap.get_subcommands([](const CLI::App*) { return true; }))
    if (command->get_name() == first)
      return {};
  return "unknown command '" + first + "'";
}

} // namespace
} // namespace mocap::cli

int main(int argc, char** argv)
{
  using namespace mocap::cli;
  CLI::App mocap("the batch command line of Mocap Studio", "mocap");
  mocap.formatter(std::make_shared<UsageFormatter>());
  mocap.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // a repeated option: the last wins
  mocap.require_subcommand(1);
  const std::vector<Command> commands = {
      addInfo(mocap),     addConvert(mocap),  addClean(mocap),      addBatch(mocap),      addSummarize(mocap),  addEvalFill(mocap), addEvalSpikes(mocap),
      addEvalSmooth(mocap), addSmoothTable(mocap), addPfa(mocap),   addTrack(mocap),    addFixSwaps(mocap),
      addEvalTrack(mocap), addBind(mocap),    addDeform(mocap),     addRig(mocap),      addSolve(mocap),     addActor(mocap),    addReview(mocap),
      addStream(mocap),
  };
  if (argc >= 2 && std::string(argv[1]) == "help") {
    std::cout << mocap.help();
    return kExitOk;
  }
  if (const std::string unknown = unknownCommand(mocap, argc, argv); !unknown.empty())
    return usageError(mocap, unknown);
  try {
    mocap.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << mocap.help();  // CLI11 hands this to the chosen command
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    return usageError(chosen(mocap, commands), e.what());
  }
  const CLI::App& command = chosen(mocap, commands);
  try {
    for (const Command& c : commands)
      if (c.app == &command)
        return c.run();
    return usageError(mocap, "no command given");
  } catch (const UsageError& e) {
    return usageError(command, e.what());
  } catch (const mocap::InvalidArgument& e) {
    std::cerr << e.what() << '\n';
    return kExitBadUsage;
  } catch (const mocap::Error& e) {
    std::cerr << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "mocap " << command.get_name() << ": " << e.what() << '\n';
    return kExitBadInput;
  }
}
