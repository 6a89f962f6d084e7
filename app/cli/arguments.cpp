#include "arguments.h"

#include "cli_error.h"

#include "mocap/base/number_text.h"
#include "mocap/io/take_io.h"

#include <cmath>
#include <cstdio>

namespace mocap::cli {

namespace {
std::string formatNumber(double value)
{
  std::string text;
  appendNumber(text, value);
  return text;
}
} // namespace

Arguments::Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags,
                     const std::set<std::string>& knownOptions)
{
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() == 2 && arg[0] == '-' && knownOptions.count(arg) != 0) {
      if (i + 1 >= args.size())
        throw UsageError("option " + arg + " needs a value");
      m_values[arg] = args[++i];
      continue;
    }
    if (arg.size() <= 2 || arg.compare(0, 2, "--") != 0) {
      m_positionals.push_back(arg);
      continue;
    }
    const std::size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    if (knownOptions.count(name) != 0) {
      if (equals != std::string::npos)
        m_values[name] = arg.substr(equals + 1);
      else if (i + 1 < args.size())
        m_values[name] = args[++i];
      else
        throw UsageError("option " + name + " needs a value");
    } else if (knownFlags.count(arg) != 0) {
      m_flags.insert(arg);
    } else {
      throw UsageError("unknown option " + arg);
    }
  }
}

std::optional<std::string> Arguments::value(const std::string& option) const
{
  const auto it = m_values.find(option);
  if (it == m_values.end())
    return std::nullopt;
  return it->second;
}

std::optional<double> Arguments::number(const std::string& option, double min, double max) const
{
  const auto text = value(option);
  if (!text)
    return std::nullopt;
  std::size_t used = 0;
  double parsed = 0.0;
  try {
    parsed = std::stod(*text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text->size() || !std::isfinite(parsed))
    throw UsageError(option + " needs a number, not '" + *text + "'");
  if (parsed < min || parsed > max)
    throw UsageError(option + " must be between " + formatNumber(min) + " and " + formatNumber(max) + ", not " + *text);
  return parsed;
}

std::optional<long long> Arguments::integer(const std::string& option, long long min, long long max) const
{
  const auto text = value(option);
  if (!text)
    return std::nullopt;
  std::size_t used = 0;
  long long parsed = 0;
  try {
    parsed = std::stoll(*text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text->size())
    throw UsageError(option + " needs a whole number, not '" + *text + "'");
  if (parsed < min || parsed > max)
    throw UsageError(option + " must be between " + std::to_string(min) + " and " + std::to_string(max) + ", not " +
                     *text);
  return parsed;
}

std::string fixedNumber(double value, int decimals)
{
  if (!std::isfinite(value))
    return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
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

void Arguments::expectPositionals(std::size_t count, const std::string& what) const
{
  if (m_positionals.size() != count)
    throw UsageError("expected " + what + ", got " + std::to_string(m_positionals.size()) + " argument(s)");
}

std::pair<std::string, std::string> Arguments::inputAndOutput() const
{
  expectPositionals(1, "one input file (and -o OUT)");
  const auto output = value("-o") ? value("-o") : value("--output");
  if (!output)
    throw UsageError("missing -o OUT");
  (void)formatFromPath(*output);  // throws for an extension that names no format
  return {m_positionals[0], *output};
}

} // namespace mocap::cli
