#include "mocap/base/json_reader.h"

#include "mocap/base/error.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <iterator>
#include <utility>

namespace mocap {

namespace {

constexpr std::size_t kMaxDepth = 256;

/// A pointer into the text that publishes how far it has been advanced. nlohmann's SAX events
/// carry no position, and the parser reads its input one byte at a time through this iterator, so
/// the furthest point read tells our own errors (a repeated key, nesting too deep) where they are.
class ReadHead
{
public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  ReadHead(const char* at, const char** furthest) : m_at(at), m_furthest(furthest) {}
  reference operator*() const { return *m_at; }
  ReadHead& operator++()
  {
    *m_furthest = ++m_at;
    return *this;
  }
  ReadHead operator++(int)
  {
    ReadHead before = *this;
    ++*this;
    return before;
  }
  bool operator==(const ReadHead& other) const { return m_at == other.m_at; }
  bool operator!=(const ReadHead& other) const { return m_at != other.m_at; }

private:
  const char* m_at;
  const char** m_furthest;
};

/// The offset of the opening quote of the string whose closing quote is at `close`: the nearest
/// earlier quote that is not escaped by an odd run of backslashes.
std::size_t openingQuote(std::string_view text, std::size_t close)
{
  for (std::size_t i = close; i-- > 0;) {
    if (text[i] != '"')
      continue;
    std::size_t backslashes = 0;
    while (backslashes < i && text[i - 1 - backslashes] == '\\')
      ++backslashes;
    if (backslashes % 2 == 0)
      return i;
  }
  return 0;
}

/// nlohmann's what() without its "[json.exception.parse_error.101] parse error at line L, column
/// C: " prefix: FormatError adds the file and the byte offset itself.
std::string describe(const nlohmann::json::exception& error)
{
  std::string_view text = error.what();
  if (const std::size_t id = text.find("] "); !text.empty() && text[0] == '[' && id != std::string_view::npos)
    text.remove_prefix(id + 2);
  if (text.rfind("parse error", 0) == 0)
    if (const std::size_t colon = text.find(": "); colon != std::string_view::npos)
      text.remove_prefix(colon + 2);
  return std::string(text);
}

} // namespace

/// The SAX handler that builds our JsonValue tree while nlohmann parses (RFC 8259 strictly: no
/// comments, no trailing commas, well-formed UTF-8 and surrogate pairs), and refuses what
/// nlohmann would accept but we do not: a repeated key, nesting deeper than kMaxDepth.
class JsonParser
{
public:
  JsonParser(std::string_view text, const std::string& sourceName)
      : m_text(text), m_source(sourceName), m_furthest(text.data())
  {
  }

  JsonValue document()
  {
    const ReadHead begin(m_text.data(), &m_furthest);
    const ReadHead end(m_text.data() + m_text.size(), &m_furthest);
    // Every error throws from a handler below, so a false return cannot happen; guard it anyway.
    if (!nlohmann::json::sax_parse(begin, end, this, nlohmann::json::input_format_t::json, true, false))
      fail(offsetRead(), "invalid JSON");
    return std::move(m_root);
  }

  // nlohmann's SAX interface (nlohmann::json_sax); each returns true to continue.
  bool null() { return add(JsonValue()); }
  bool boolean(bool flag)
  {
    JsonValue value;
    value.m_type = JsonValue::Type::Boolean;
    value.m_boolean = flag;
    return add(std::move(value));
  }
  // Integers become doubles like every other number: the callers read them through number().
  bool number_integer(nlohmann::json::number_integer_t number)
  {
    return add(numberValue(number == 0 && zeroWasNegative() ? -0.0 : static_cast<double>(number)));
  }
  bool number_unsigned(nlohmann::json::number_unsigned_t number)
  {
    return add(numberValue(static_cast<double>(number)));
  }
  bool number_float(nlohmann::json::number_float_t number, const nlohmann::json::string_t& /*text*/)
  {
    return add(numberValue(number));
  }
  bool string(nlohmann::json::string_t& text)
  {
    JsonValue value;
    value.m_type = JsonValue::Type::String;
    value.m_string = std::move(text);
    return add(std::move(value));
  }
  bool binary(nlohmann::json::binary_t& /*bytes*/) { return false; }  // only CBOR and the like have binary values
  bool start_object(std::size_t /*size*/)
  {
    JsonValue value;
    value.m_type = JsonValue::Type::Object;
    value.m_object = std::make_shared<std::map<std::string, JsonValue>>();
    return open(std::move(value));
  }
  bool key(nlohmann::json::string_t& name)
  {
    // A repeated name would silently drop data (which one counts is up to the reader): refuse it.
    // The key's closing quote is the last byte read.
    if (m_open.back()->m_object->count(name) != 0)
      fail(openingQuote(m_text, offsetRead()), "repeated key \"" + name + "\"");
    m_key = std::move(name);
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t /*size*/)
  {
    JsonValue value;
    value.m_type = JsonValue::Type::Array;
    return open(std::move(value));
  }
  bool end_array() { return close(); }
  bool parse_error(std::size_t position, const std::string& /*lastToken*/, const nlohmann::json::exception& error)
  {
    // nlohmann's position counts the bytes read up to and including the one that failed (and the
    // end of the input as one more): the offending byte's 0-based offset is one less.
    const std::size_t offset = position > 0 ? position - 1 : 0;
    if (m_complete)
      fail(offset, "unexpected text after the JSON value");
    if (offset >= m_text.size())
      fail(offset, "unexpected end of JSON (" + describe(error) + ")");
    fail(offset, describe(error));
  }

private:
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const
  {
    throw FormatError(m_source, static_cast<std::uint64_t>(offset), message);
  }

  /// The offset of the last byte the parser has read.
  [[nodiscard]] std::size_t offsetRead() const
  {
    const auto read = static_cast<std::size_t>(m_furthest - m_text.data());
    return read > 0 ? read - 1 : 0;
  }

  /// Whether the integer 0 just read was written "-0": nlohmann reads it as the integer 0, but our
  /// writer writes -0.0 as "-0" and the double must read back with its sign. The lexer has read
  /// the number and the byte after it (a delimiter, in a valid document) unless the text ended.
  [[nodiscard]] bool zeroWasNegative() const
  {
    auto end = static_cast<std::size_t>(m_furthest - m_text.data());
    if (end > 0 && m_text[end - 1] != '0')
      --end;
    return end >= 2 && m_text[end - 2] == '-';
  }

  static JsonValue numberValue(double number)
  {
    JsonValue value;
    value.m_type = JsonValue::Type::Number;
    value.m_number = number;
    return value;
  }

  /// Places `value` in the innermost open container (or as the document) and returns where it now lives.
  JsonValue* place(JsonValue&& value)
  {
    if (m_open.empty()) {
      m_root = std::move(value);
      return &m_root;
    }
    JsonValue& parent = *m_open.back();
    if (parent.m_type == JsonValue::Type::Array) {
      parent.m_array.push_back(std::move(value));
      return &parent.m_array.back();
    }
    JsonValue& member = (*parent.m_object)[m_key];
    member = std::move(value);
    return &member;
  }

  bool add(JsonValue&& value)
  {
    place(std::move(value));
    m_complete = m_open.empty();
    return true;
  }

  // An open container is not moved while it is open: a vector reallocates only when a sibling is
  // appended, which happens after the container closed, and map nodes never move.
  bool open(JsonValue&& container)
  {
    if (m_open.size() == kMaxDepth)
      fail(offsetRead(), "JSON nested too deeply (more than " + std::to_string(kMaxDepth) + " levels)");
    m_open.push_back(place(std::move(container)));
    return true;
  }

  bool close()
  {
    m_open.pop_back();
    m_complete = m_open.empty();
    return true;
  }

  std::string_view m_text;
  const std::string& m_source;
  const char* m_furthest;
  JsonValue m_root;
  std::vector<JsonValue*> m_open;
  std::string m_key;
  bool m_complete = false;
};

namespace {

[[noreturn]] void wrongType(const std::string& what, const char* expected)
{
  throw InvalidArgument(what + " must be " + expected);
}

} // namespace

bool JsonValue::boolean(const std::string& what) const
{
  if (m_type != Type::Boolean)
    wrongType(what, "true or false");
  return m_boolean;
}

double JsonValue::number(const std::string& what) const
{
  if (m_type != Type::Number)
    wrongType(what, "a number");
  return m_number;
}

const std::string& JsonValue::string(const std::string& what) const
{
  if (m_type != Type::String)
    wrongType(what, "a string");
  return m_string;
}

const std::vector<JsonValue>& JsonValue::array(const std::string& what) const
{
  if (m_type != Type::Array)
    wrongType(what, "an array");
  return m_array;
}

const std::map<std::string, JsonValue>& JsonValue::object(const std::string& what) const
{
  if (m_type != Type::Object)
    wrongType(what, "an object");
  return *m_object;
}

const JsonValue* JsonValue::find(const std::string& key, const std::string& what) const
{
  const auto& members = object(what);
  const auto it = members.find(key);
  return it == members.end() ? nullptr : &it->second;
}

JsonValue parseJson(std::string_view text, const std::string& sourceName)
{
  return JsonParser(text, sourceName).document();
}

} // namespace mocap
