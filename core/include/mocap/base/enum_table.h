#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace mocap {

/// One name of an enum value, as files, JSON and the command line spell it.
template <typename Enum>
struct EnumName
{
  Enum value;
  std::string_view name;
};

/// The names of an enum's values, written once and read both ways: name() for output, parse()
/// for input, names() for the "expected one of …" of an error. A value may have several entries
/// (aliases accepted on input); its first is its name. Every member is O(N).
template <typename Enum, std::size_t N>
struct EnumTable
{
  std::array<EnumName<Enum>, N> entries;

  /// The first name of `value`, or `unknown` for a value the table does not list (an enum read
  /// from bytes may hold anything).
  [[nodiscard]] constexpr std::string_view name(Enum value, std::string_view unknown) const
  {
    for (const EnumName<Enum>& entry : entries)
      if (entry.value == value)
        return entry.name;
    return unknown;
  }

  /// The value named exactly `name` (case and spaces count), or nullopt.
  [[nodiscard]] constexpr std::optional<Enum> parse(std::string_view name) const
  {
    for (const EnumName<Enum>& entry : entries)
      if (entry.name == name)
        return entry.value;
    return std::nullopt;
  }

  /// Each value's first name in table order, joined by `separator`: "a|b|c".
  [[nodiscard]] std::string names(std::string_view separator = "|") const
  {
    std::string joined;
    for (std::size_t i = 0; i < N; ++i) {
      if (name(entries[i].value, {}) != entries[i].name)
        continue;  // an alias
      if (!joined.empty())
        joined += separator;
      joined += entries[i].name;
    }
    return joined;
  }
};

} // namespace mocap
