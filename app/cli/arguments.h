#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mocap::cli {

/// One command's arguments split into positionals, `--flag` switches and `--option VALUE`
/// (or `--option=VALUE`) pairs. Unknown flags, a missing value and a wrong number of
/// positionals raise UsageError.
class Arguments
{
public:
  Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags,
            const std::set<std::string>& knownOptions = {});

  [[nodiscard]] bool has(const std::string& flag) const { return m_flags.count(flag) != 0; }
  [[nodiscard]] std::optional<std::string> value(const std::string& option) const;
  [[nodiscard]] const std::vector<std::string>& positionals() const { return m_positionals; }
  /// Throws UsageError unless there are exactly `count` positionals, naming them in `what`.
  void expectPositionals(std::size_t count, const std::string& what) const;

private:
  std::vector<std::string> m_positionals;
  std::set<std::string> m_flags;
  std::map<std::string, std::string> m_values;
};

} // namespace mocap::cli
