#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace mocap::cli {

/// `mocap`'s usage text, made from the commands' CLI11 definitions so it cannot drift from them.
/// `mocap --help` lists every command's synopsis and description (the README's command table
/// is this text); `mocap COMMAND --help` prints the command's synopsis, its description and
/// CLI11's table of its options.
class UsageFormatter : public CLI::Formatter
{
public:
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override;
};

/// The one-line reminder a usage error ends with: the command's positionals and required options,
/// then where to read the rest, e.g. "usage: mocap info FILE [OPTIONS] (mocap info --help for more)".
[[nodiscard]] std::string usageHint(const CLI::App& command);

} // namespace mocap::cli
