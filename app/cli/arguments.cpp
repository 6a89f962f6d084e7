#include "arguments.h"

#include "cli_error.h"

namespace mocap::cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags)
{
  for (const std::string& arg : args) {
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      if (knownFlags.count(arg) == 0)
        throw UsageError("unknown option " + arg);
      m_flags.insert(arg);
    } else {
      m_positionals.push_back(arg);
    }
  }
}

void Arguments::expectPositionals(std::size_t count, const std::string& what) const
{
  if (m_positionals.size() != count)
    throw UsageError("expected " + what + ", got " + std::to_string(m_positionals.size()) + " argument(s)");
}

} // namespace mocap::cli
