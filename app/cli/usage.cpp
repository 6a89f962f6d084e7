#include "usage.h"

#include <vector>

namespace mocap::cli {

namespace {

constexpr std::size_t kWidth = 100;        // columns the synopses are wrapped to
constexpr const char* kContinuation = "      ";  // indent of a synopsis' further lines
constexpr const char* kDescription = "                        ";  // indent of a command's description in the list

bool isFlag(const CLI::Option& option)
{
  return option.get_expected_max() == 0;
}

// How the synopsis shows `option`: "FILE", "TAKE [TAKE...]", "-o OUT", "--json",
// "--export-subset K OUT.c3d"; brackets when it may be left out.
std::string synopsisToken(const CLI::Option& option)
{
  std::string token;
  if (option.get_positional()) {
    token = option.get_name();
    if (option.get_expected_max() > 1)
      token += " [" + option.get_name() + "...]";
  } else {
    const auto& shortNames = option.get_snames();
    token = shortNames.empty() ? "--" + option.get_lnames().front() : "-" + shortNames.front();
    if (!isFlag(option))
      token += " " + option.get_type_name();
  }
  return option.get_required() ? token : "[" + token + "]";
}

std::vector<const CLI::Option*> userOptions(const CLI::App& command)
{
  return command.get_options([&command](const CLI::Option* option) { return option != command.get_help_ptr(); });
}

// The tokens wrapped to kWidth columns (not counting `prefix`, so a synopsis breaks at the same
// places after "usage: mocap " as in the command list), kContinuation before every further line.
std::string wrapped(const std::string& prefix, const std::vector<std::string>& tokens)
{
  std::string text, line;
  for (const std::string& token : tokens) {
    if (line.empty()) {
      line = token;
    } else if (line.size() + 1 + token.size() > kWidth) {
      text += (text.empty() ? prefix : "") + line + '\n';
      line = kContinuation + token;
    } else {
      line += ' ' + token;
    }
  }
  return text + (text.empty() ? prefix : "") + line + '\n';
}

// "info FILE [--json]", wrapped, after `prefix` on the first line.
std::string synopsis(const CLI::App& command, const std::string& prefix)
{
  std::vector<std::string> tokens{command.get_name()};
  for (const CLI::Option* option : userOptions(command))
    tokens.push_back(synopsisToken(*option));
  return wrapped(prefix, tokens);
}

std::string commandList(const CLI::App& mocap)
{
  std::string text = "usage: mocap COMMAND [ARGUMENTS]  (mocap COMMAND --help: that command's options)\n"
                     "commands:\n";
  for (const CLI::App* command : mocap.get_subcommands([](const CLI::App*) { return true; }))
    text += synopsis(*command, "  ") + kDescription + command->get_description() + '\n';
  return text;
}

} // namespace

std::string UsageFormatter::make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const
{
  if (app->get_parent() == nullptr)
    return commandList(*app);
  return synopsis(*app, "usage: mocap ") + app->get_description() + "\n" + make_positionals(app) +
         make_groups(app, mode);
}

std::string usageHint(const CLI::App& command)
{
  std::string text = "usage: mocap " + command.get_name();
  bool optional = false;
  for (const CLI::Option* option : userOptions(command)) {
    if (option->get_required())
      text += " " + synopsisToken(*option);
    else
      optional = true;
  }
  return text + (optional ? " [OPTIONS]" : "") + " (mocap " + command.get_name() + " --help for more)";
}

} // namespace mocap::cli
