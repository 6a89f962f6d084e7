#pragma once

#include <set>
#include <string>
#include <vector>

namespace mocap::cli {

/// One command's arguments split into positionals and `--flag` switches.
/// Unknown flags and a wrong number of positionals raise UsageError.
class Arguments
{
public:
  Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags);

  [[nodiscard]] bool has(const std::string& flag) const { return m_flags.count(flag) != 0; }
  [[nodiscard]] const std::vector<std::string>& positionals() const { return m_positionals; }
  /// Throws UsageError unless there are exactly `count` positionals, naming them in `what`.
  void expectPositionals(std::size_t count, const std::string& what) const;

private:
  std::vector<std::string> m_positionals;
  std::set<std::string> m_flags;
};

} // namespace mocap::cli
