#include "mocap/base/json_reader.h"

#include "mocap/base/error.h"

#include <charconv>
#include <cmath>

namespace mocap {

namespace {

constexpr int kMaxDepth = 256;

void appendUtf8(std::string& out, unsigned code)
{
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

} // namespace

class JsonParser
{
public:
  JsonParser(std::string_view text, const std::string& sourceName) : m_text(text), m_source(sourceName) {}

  JsonValue document()
  {
    JsonValue value = parseValue(0);
    skipBlanks();
    if (m_pos != m_text.size())
      fail("unexpected text after the JSON value");
    return value;
  }

private:
  [[noreturn]] void fail(const std::string& message) const
  {
    throw FormatError(m_source, static_cast<std::uint64_t>(m_pos), message);
  }
  void skipBlanks()
  {
    while (m_pos < m_text.size() &&
           (m_text[m_pos] == ' ' || m_text[m_pos] == '\t' || m_text[m_pos] == '\n' || m_text[m_pos] == '\r'))
      ++m_pos;
  }
  char peek()
  {
    skipBlanks();
    if (m_pos >= m_text.size())
      fail("unexpected end of JSON");
    return m_text[m_pos];
  }
  void expect(char c)
  {
    if (peek() != c)
      fail(std::string("expected '") + c + "'");
    ++m_pos;
  }
  void literal(std::string_view word)
  {
    if (m_text.substr(m_pos, word.size()) != word)
      fail("invalid literal");
    m_pos += word.size();
  }

  JsonValue parseValue(int depth)
  {
    if (depth > kMaxDepth)
      fail("JSON nested too deeply");
    JsonValue value;
    const char c = peek();
    if (c == '{') {
      value.m_type = JsonValue::Type::Object;
      value.m_object = std::make_shared<std::map<std::string, JsonValue>>();
      ++m_pos;
      if (peek() == '}') {
        ++m_pos;
        return value;
      }
      while (true) {
        if (peek() != '"')
          fail("expected a string key");
        const std::size_t keyStart = m_pos;
        std::string key = parseString();
        expect(':');
        // A repeated name would silently drop data (which one counts is up to the reader): refuse it.
        if (value.m_object->count(key) != 0) {
          m_pos = keyStart;
          fail("repeated key \"" + key + "\"");
        }
        (*value.m_object)[key] = parseValue(depth + 1);
        if (peek() == ',') {
          ++m_pos;
          continue;
        }
        expect('}');
        return value;
      }
    }
    if (c == '[') {
      value.m_type = JsonValue::Type::Array;
      ++m_pos;
      if (peek() == ']') {
        ++m_pos;
        return value;
      }
      while (true) {
        value.m_array.push_back(parseValue(depth + 1));
        if (peek() == ',') {
          ++m_pos;
          continue;
        }
        expect(']');
        return value;
      }
    }
    if (c == '"') {
      value.m_type = JsonValue::Type::String;
      value.m_string = parseString();
    } else if (c == 't' || c == 'f') {
      value.m_type = JsonValue::Type::Boolean;
      value.m_boolean = c == 't';
      literal(c == 't' ? "true" : "false");
    } else if (c == 'n') {
      literal("null");
    } else {
      value.m_type = JsonValue::Type::Number;
      value.m_number = parseNumber();
    }
    return value;
  }

  double parseNumber()
  {
    const char* begin = m_text.data() + m_pos;
    const char* end = m_text.data() + m_text.size();
    double number = 0.0;
    const auto result = std::from_chars(begin, end, number);
    if (result.ec != std::errc() || !std::isfinite(number))
      fail("invalid number");
    m_pos += static_cast<std::size_t>(result.ptr - begin);
    return number;
  }

  unsigned hex4()
  {
    if (m_pos + 4 > m_text.size())
      fail("truncated \\u escape");
    unsigned code = 0;
    const auto result = std::from_chars(m_text.data() + m_pos, m_text.data() + m_pos + 4, code, 16);
    if (result.ec != std::errc() || result.ptr != m_text.data() + m_pos + 4)
      fail("invalid \\u escape");
    m_pos += 4;
    return code;
  }

  std::string parseString()
  {
    ++m_pos;  // opening quote
    std::string out;
    while (true) {
      if (m_pos >= m_text.size())
        fail("unterminated string");
      const char c = m_text[m_pos++];
      if (c == '"')
        return out;
      if (static_cast<unsigned char>(c) < 0x20)
        fail("control character in a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (m_pos >= m_text.size())
        fail("unterminated string");
      const char e = m_text[m_pos++];
      switch (e) {
      case '"': out += '"'; break;
      case '\\': out += '\\'; break;
      case '/': out += '/'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case 'u': {
        unsigned code = hex4();
        if (code >= 0xD800 && code < 0xDC00 && m_text.substr(m_pos, 2) == "\\u") {
          m_pos += 2;
          const unsigned low = hex4();
          if (low < 0xDC00 || low > 0xDFFF)
            fail("invalid surrogate pair");
          code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        appendUtf8(out, code);
        break;
      }
      default: fail("invalid escape");
      }
    }
  }

  std::string_view m_text;
  const std::string& m_source;
  std::size_t m_pos = 0;
};

namespace {

[[noreturn]] void wrongType(const std::string& what, const char* expected)
{
  throw InvalidArgument(what + " must be " + expected);
}

} // namespace

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
