#include "mocap/json_reader.h"

#include "mocap/error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace mocap {

const JsonValue* JsonValue::find(std::string_view key) const
{
  for (const auto& [name, value] : object)
    if (name == key)
      return &value;
  return nullptr;
}

namespace {

class JsonParser
{
public:
  JsonParser(std::string_view text, const std::string& source) : m_text(text), m_source(source) {}

  JsonValue document()
  {
    JsonValue value = parseValue(0);
    skipSpace();
    if (m_pos != m_text.size())
      fail("unexpected text after the document");
    return value;
  }

private:
  [[noreturn]] void fail(const std::string& message) const
  {
    throw FormatError(m_source, static_cast<std::uint64_t>(m_pos), message);
  }

  void skipSpace()
  {
    while (m_pos < m_text.size() &&
           (m_text[m_pos] == ' ' || m_text[m_pos] == '\t' || m_text[m_pos] == '\n' || m_text[m_pos] == '\r'))
      ++m_pos;
  }

  bool consume(char c)
  {
    skipSpace();
    if (m_pos < m_text.size() && m_text[m_pos] == c) {
      ++m_pos;
      return true;
    }
    return false;
  }

  void expect(char c)
  {
    if (!consume(c))
      fail(std::string("expected '") + c + "'");
  }

  bool literal(std::string_view word)
  {
    if (m_text.substr(m_pos, word.size()) != word)
      return false;
    m_pos += word.size();
    return true;
  }

  JsonValue parseValue(int depth)
  {
    if (depth > 256)
      fail("nested too deeply");
    skipSpace();
    if (m_pos >= m_text.size())
      fail("unexpected end of text");
    JsonValue value;
    const char c = m_text[m_pos];
    if (c == '{') {
      ++m_pos;
      value.type = JsonValue::Type::Object;
      if (consume('}'))
        return value;
      do {
        skipSpace();
        std::string key = parseString();
        expect(':');
        value.object.emplace_back(std::move(key), parseValue(depth + 1));
      } while (consume(','));
      expect('}');
    } else if (c == '[') {
      ++m_pos;
      value.type = JsonValue::Type::Array;
      if (consume(']'))
        return value;
      do
        value.array.push_back(parseValue(depth + 1));
      while (consume(','));
      expect(']');
    } else if (c == '"') {
      value.type = JsonValue::Type::String;
      value.string = parseString();
    } else if (literal("true") || literal("false")) {
      value.type = JsonValue::Type::Bool;
      value.boolean = c == 't';
    } else if (literal("null")) {
      value.type = JsonValue::Type::Null;
    } else {
      value.type = JsonValue::Type::Number;
      value.number = parseNumber();
    }
    return value;
  }

  double parseNumber()
  {
    const std::size_t start = m_pos;
    while (m_pos < m_text.size() && (std::isdigit(static_cast<unsigned char>(m_text[m_pos])) ||
                                     m_text[m_pos] == '-' || m_text[m_pos] == '+' || m_text[m_pos] == '.' ||
                                     m_text[m_pos] == 'e' || m_text[m_pos] == 'E'))
      ++m_pos;
    double number = 0.0;
    const auto [end, error] = std::from_chars(m_text.data() + start, m_text.data() + m_pos, number);
    if (m_pos == start || error != std::errc() || end != m_text.data() + m_pos || !std::isfinite(number)) {
      m_pos = start;
      fail("expected a value");
    }
    return number;
  }

  static void appendUtf8(std::string& out, std::uint32_t code)
  {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  std::string parseString()
  {
    if (m_pos >= m_text.size() || m_text[m_pos] != '"')
      fail("expected a string");
    ++m_pos;
    std::string out;
    while (true) {
      if (m_pos >= m_text.size())
        fail("unterminated string");
      const char c = m_text[m_pos++];
      if (c == '"')
        return out;
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
        std::uint32_t code = 0;
        const auto [end, error] =
            std::from_chars(m_text.data() + m_pos, m_text.data() + std::min(m_pos + 4, m_text.size()), code, 16);
        if (error != std::errc() || end != m_text.data() + m_pos + 4)
          fail("bad \\u escape");
        m_pos += 4;
        appendUtf8(out, code);
        break;
      }
      default: fail("bad escape in string");
      }
    }
  }

  std::string_view m_text;
  const std::string& m_source;
  std::size_t m_pos = 0;
};

} // namespace

JsonValue parseJson(std::string_view text, const std::string& source)
{
  return JsonParser(text, source).document();
}

} // namespace mocap
