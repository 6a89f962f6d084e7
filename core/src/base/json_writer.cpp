#include "mocap/base/json_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace mocap {

std::string jsonQuote(std::string_view text)
{
  // nlohmann's serializer escapes what JSON requires and replaces each ill-formed UTF-8 sequence
  // with U+FFFD, so a label in any 8-bit encoding (C3D files carry no encoding) still gives valid
  // JSON. Other UTF-8 is written as it is, not as \u escapes.
  return nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void JsonWriter::newline()
{
  if (m_indent <= 0)
    return;
  m_out += '\n';
  m_out.append(m_scopes.size() * static_cast<std::size_t>(m_indent), ' ');
}

void JsonWriter::beforeValue()
{
  if (m_scopes.empty()) {
    if (!m_out.empty())
      throw InvalidArgument("JSON document already has a top-level value");
    return;
  }
  if (m_scopes.back() == Scope::Object) {
    if (!m_keyPending)
      throw InvalidArgument("JSON object value written without a key");
    m_keyPending = false;
    return;
  }
  if (m_hasItems.back())
    m_out += ',';
  m_hasItems.back() = true;
  newline();
}

JsonWriter& JsonWriter::key(std::string_view name)
{
  if (m_scopes.empty() || m_scopes.back() != Scope::Object || m_keyPending)
    throw InvalidArgument("JSON key outside an object");
  if (m_hasItems.back())
    m_out += ',';
  m_hasItems.back() = true;
  newline();
  m_out += jsonQuote(name);
  m_out += m_indent > 0 ? ": " : ":";
  m_keyPending = true;
  return *this;
}

JsonWriter& JsonWriter::beginObject()
{
  beforeValue();
  m_out += '{';
  m_scopes.push_back(Scope::Object);
  m_hasItems.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::beginArray()
{
  beforeValue();
  m_out += '[';
  m_scopes.push_back(Scope::Array);
  m_hasItems.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::endObject()
{
  if (m_scopes.empty() || m_scopes.back() != Scope::Object || m_keyPending)
    throw InvalidArgument("unbalanced JSON object");
  const bool hadItems = m_hasItems.back();
  m_scopes.pop_back();
  m_hasItems.pop_back();
  if (hadItems)
    newline();
  m_out += '}';
  return *this;
}

JsonWriter& JsonWriter::endArray()
{
  if (m_scopes.empty() || m_scopes.back() != Scope::Array)
    throw InvalidArgument("unbalanced JSON array");
  const bool hadItems = m_hasItems.back();
  m_scopes.pop_back();
  m_hasItems.pop_back();
  if (hadItems)
    newline();
  m_out += ']';
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text)
{
  beforeValue();
  m_out += jsonQuote(text);
  return *this;
}

JsonWriter& JsonWriter::value(double number)
{
  if (!std::isfinite(number))
    return null();
  beforeValue();
  appendNumber(m_out, number);
  return *this;
}

JsonWriter& JsonWriter::value(std::int64_t number)
{
  beforeValue();
  m_out += std::to_string(number);
  return *this;
}

JsonWriter& JsonWriter::value(bool flag)
{
  beforeValue();
  m_out += flag ? "true" : "false";
  return *this;
}

JsonWriter& JsonWriter::null()
{
  beforeValue();
  m_out += "null";
  return *this;
}

const std::string& JsonWriter::str() const
{
  if (!m_scopes.empty())
    throw InvalidArgument("JSON document has unclosed objects or arrays");
  return m_out;
}

} // namespace mocap
