#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mocap {

/// A parsed JSON value (RFC 8259): the small documents the tools read (mesh bindings), so a
/// plain tree is enough.
struct JsonValue
{
  enum class Type { Null, Bool, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  ///< members in file order

  /// The member `key` of an object, or nullptr (also for a value that is not an object). O(#members).
  [[nodiscard]] const JsonValue* find(std::string_view key) const;
};

/// Parses one JSON document (`source` names it in errors). Strings keep \uXXXX escapes decoded to
/// UTF-8. Nesting deeper than 256 levels is refused so hostile input cannot exhaust the stack.
/// Throws FormatError ("SOURCE: ... at byte N") for malformed text or trailing garbage. O(size).
[[nodiscard]] JsonValue parseJson(std::string_view text, const std::string& source);

} // namespace mocap
