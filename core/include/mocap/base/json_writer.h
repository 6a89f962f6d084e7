#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// A small streaming JSON writer for the CLI's machine-readable output: objects, arrays,
/// strings (escaped; ill-formed UTF-8 becomes U+FFFD), numbers (shortest round-trip form; NaN
/// and infinities become null), booleans and null. Commas and nesting are tracked; misuse throws InvalidArgument.
class JsonWriter
{
public:
  /// `indent` 0 writes one line; otherwise nested values are indented by that many spaces.
  explicit JsonWriter(int indent = 2) : m_indent(indent) {}

  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  /// The next value's key; only inside an object.
  JsonWriter& key(std::string_view name);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(double number);
  JsonWriter& value(std::int64_t number);
  JsonWriter& value(int number) { return value(static_cast<std::int64_t>(number)); }
  JsonWriter& value(bool flag);
  JsonWriter& null();

  /// The document; throws InvalidArgument while an object or array is still open.
  [[nodiscard]] const std::string& str() const;

private:
  void beforeValue();
  void newline();

  enum class Scope { Object, Array };
  std::string m_out;
  std::vector<Scope> m_scopes;
  std::vector<bool> m_hasItems;
  bool m_keyPending = false;
  int m_indent;
};

/// `text` as a quoted JSON string; each ill-formed UTF-8 sequence in it becomes U+FFFD.
[[nodiscard]] std::string jsonQuote(std::string_view text);

} // namespace mocap
