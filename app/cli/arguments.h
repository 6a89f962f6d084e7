#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace mocap::cli {

// Checks that restrict an option's value; each adds the range or the choices to the option's help
// (so they are stated once, here) and returns the option. A bad value is a usage error naming the
// option, as in "--noise: -1 not in [0, 10000]".

/// A number in [min, max].
CLI::Option* numberIn(CLI::Option* option, double min, double max);

/// A decimal whole number in [min, max], handed on in plain decimal so "010" is ten (CLI11
/// alone would read it as octal).
CLI::Option* wholeNumberIn(CLI::Option* option, long long min, long long max);

/// One of `names`, which the usage shows as `a|b|c`.
CLI::Option* oneOf(CLI::Option* option, const std::vector<std::string>& names);
/// One of the names in `choices`, written "a|b|c" as core's enum tables give them (e.g.
/// spikeMethodNames()), so the command line accepts exactly what core reads.
CLI::Option* oneOf(CLI::Option* option, const std::string& choices);

/// `value` as the shortest text that reads back to it, for defaults shown in the usage.
[[nodiscard]] std::string numberText(double value);

/// `value` with `decimals` decimals for text tables; "-" when it is not finite.
[[nodiscard]] std::string fixedNumber(double value, int decimals);

/// Splits "a,b,c" into its fields; UsageError when a field is empty.
[[nodiscard]] std::vector<std::string> splitList(const std::string& text, const std::string& option);

} // namespace mocap::cli
