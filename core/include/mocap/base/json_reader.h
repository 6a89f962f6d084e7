#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// A parsed JSON value (RFC 8259): null, boolean, number, string, array or object. Objects keep
/// their keys sorted; a document with a repeated key in one object is refused.
class JsonValue
{
public:
  enum class Type { Null, Boolean, Number, String, Array, Object };

  JsonValue() = default;
  [[nodiscard]] Type type() const { return m_type; }
  [[nodiscard]] bool isNull() const { return m_type == Type::Null; }
  [[nodiscard]] bool isBoolean() const { return m_type == Type::Boolean; }
  [[nodiscard]] bool isNumber() const { return m_type == Type::Number; }
  [[nodiscard]] bool isString() const { return m_type == Type::String; }
  [[nodiscard]] bool isArray() const { return m_type == Type::Array; }
  [[nodiscard]] bool isObject() const { return m_type == Type::Object; }

  /// The value as the type asked for; throws InvalidArgument naming `what` when it is another type.
  [[nodiscard]] bool boolean(const std::string& what) const;
  [[nodiscard]] double number(const std::string& what) const;
  [[nodiscard]] const std::string& string(const std::string& what) const;
  [[nodiscard]] const std::vector<JsonValue>& array(const std::string& what) const;
  /// The member `key` of an object, or nullptr when absent; throws when this is not an object.
  [[nodiscard]] const JsonValue* find(const std::string& key, const std::string& what) const;
  [[nodiscard]] const std::map<std::string, JsonValue>& object(const std::string& what) const;

private:
  friend class JsonParser;
  Type m_type = Type::Null;
  bool m_boolean = false;
  double m_number = 0.0;
  std::string m_string;
  std::vector<JsonValue> m_array;
  std::shared_ptr<std::map<std::string, JsonValue>> m_object;
};

/// Parses one JSON document (strict RFC 8259, on nlohmann-json's SAX parser). Throws
/// FormatError(sourceName, byte offset, message) for malformed text (including ill-formed UTF-8
/// and unpaired surrogates), a repeated key, trailing content or nesting deeper than 256. The
/// offset is that of the byte where the problem was found. O(text size).
[[nodiscard]] JsonValue parseJson(std::string_view text, const std::string& sourceName);

} // namespace mocap
