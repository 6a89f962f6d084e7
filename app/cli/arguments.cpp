#include "arguments.h"

#include "cli_error.h"

namespace mocap::cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags,
                     const std::set<std::string>& knownOptions)
{
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
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

void Arguments::expectPositionals(std::size_t count, const std::string& what) const
{
  if (m_positionals.size() != count)
    throw UsageError("expected " + what + ", got " + std::to_string(m_positionals.size()) + " argument(s)");
}

} // namespace mocap::cli
