#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mocap::cli {

/// One command's arguments split into positionals, `--flag` switches and `--option VALUE`
/// (or `--option=VALUE`) pairs; a known option may also be a short `-o VALUE`. Unknown flags, a missing value and a wrong number of
/// positionals raise UsageError.
class Arguments
{
public:
  Arguments(const std::vector<std::string>& args, const std::set<std::string>& knownFlags,
            const std::set<std::string>& knownOptions = {});

  [[nodiscard]] bool has(const std::string& flag) const { return m_flags.count(flag) != 0; }
  [[nodiscard]] std::optional<std::string> value(const std::string& option) const;
  /// The option's value as a number in [min, max]; UsageError when it is not one.
  [[nodiscard]] std::optional<double> number(const std::string& option, double min, double max) const;
  /// The option's value as an integer in [min, max]; UsageError when it is not one.
  [[nodiscard]] std::optional<long long> integer(const std::string& option, long long min, long long max) const;
  [[nodiscard]] const std::vector<std::string>& positionals() const { return m_positionals; }
  /// Throws UsageError unless there are exactly `count` positionals, naming them in `what`.
  void expectPositionals(std::size_t count, const std::string& what) const;
  /// The one input file and `-o`/`--output` of an IN -o OUT command, whose format OUT's extension
  /// must name; UsageError otherwise.
  [[nodiscard]] std::pair<std::string, std::string> inputAndOutput() const;

private:
  std::vector<std::string> m_positionals;
  std::set<std::string> m_flags;
  std::map<std::string, std::string> m_values;
};

/// `value` with `decimals` decimals for text tables; "-" when it is not finite.
[[nodiscard]] std::string fixedNumber(double value, int decimals);

/// Splits "a,b,c" into its fields; UsageError when a field is empty.
[[nodiscard]] std::vector<std::string> splitList(const std::string& text, const std::string& option);

} // namespace mocap::cli
