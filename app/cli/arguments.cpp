#include "arguments.h"

#include "cli_error.h"

#include "mocap/base/number_text.h"

#include <cmath>
#include <cstdio>

namespace mocap::cli {

std::string numberText(double value)
{
  std::string text;
  appendNumber(text, value);
  return text;
}

namespace {

// A transform rather than a check when `check` rewrites the value (CLI11 hands checks a copy).
CLI::Option* withCheck(CLI::Option* option, CLI::Validator check, const std::string& allowed, bool rewrites)
{
  option->description(option->get_description() + " (" + allowed + ")");
  return rewrites ? option->transform(std::move(check)) : option->check(std::move(check));
}

} // namespace

CLI::Option* numberIn(CLI::Option* option, double min, double max)
{
  const std::string range = "[" + numberText(min) + ", " + numberText(max) + "]";
  const CLI::Validator check(
      [min, max, range](const std::string& text) -> std::string {
        std::size_t used = 0;
        double parsed = 0.0;
        try {
          parsed = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(parsed))
          return "'" + text + "' is not a number";
        if (parsed < min || parsed > max)
          return text + " not in " + range;
        return {};
      },
      "", "number");
  return withCheck(option, check, "in " + range, false);
}

CLI::Option* wholeNumberIn(CLI::Option* option, long long min, long long max)
{
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const CLI::Validator check(
      [min, max, range](std::string& text) -> std::string {
        std::size_t used = 0;
        long long parsed = 0;
        try {
          parsed = std::stoll(text, &used, 10);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size())
          return "'" + text + "' is not a whole number";
        if (parsed < min || parsed > max)
          return text + " not in " + range;
        text = std::to_string(parsed);
        return {};
      },
      "", "whole number");
  return withCheck(option, check, "whole number in " + range, true);
}

CLI::Option* oneOf(CLI::Option* option, const std::vector<std::string>& names)
{
  std::string choices, listed;
  for (const std::string& name : names) {
    choices += (choices.empty() ? "" : "|") + name;
    listed += (listed.empty() ? "" : ", ") + name;
  }
  const CLI::Validator check(
      [names, listed](const std::string& text) -> std::string {
        for (const std::string& name : names)
          if (text == name)
            return {};
        return "'" + text + "' is not one of " + listed;
      },
      "", "choice");
  return option->check(check)->type_name(choices);
}

CLI::Option* oneOf(CLI::Option* option, const std::string& choices)
{
  std::vector<std::string> names;
  std::size_t start = 0;
  for (std::size_t bar = choices.find('|'); bar != std::string::npos; bar = choices.find('|', start)) {
    names.push_back(choices.substr(start, bar - start));
    start = bar + 1;
  }
  names.push_back(choices.substr(start));
  return oneOf(option, names);
}

std::string fixedNumber(double value, int decimals)
{
  return fixedText(value, decimals, "-");
}

std::vector<std::string> splitList(const std::string& text, const std::string& option)
{
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string field = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (field.empty())
      throw UsageError(option + " has an empty entry in '" + text + "'");
    fields.push_back(field);
    if (comma == std::string::npos)
      return fields;
    start = comma + 1;
  }
}

} // namespace mocap::cli
