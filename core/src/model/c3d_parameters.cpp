#include "mocap/model/c3d_parameters.h"

#include "mocap/base/text.h"

#include <algorithm>

namespace mocap {

std::size_t C3dParameter::elementCount() const
{
  std::size_t count = 1;
  for (int d : dimensions)
    count *= static_cast<std::size_t>(std::max(d, 0));
  return count;
}

std::vector<std::string> C3dParameter::strings() const
{
  std::vector<std::string> out;
  if (type != C3dType::Char)
    return out;
  if (dimensions.size() <= 1) {
    out.emplace_back(trim(chars));
    return out;
  }
  const std::size_t length = static_cast<std::size_t>(std::max(dimensions[0], 0));
  const std::size_t count = length == 0 ? 0 : elementCount() / length;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t start = i * length;
    if (start >= chars.size())
      out.emplace_back();
    else
      out.emplace_back(trim(std::string_view(chars).substr(start, length)));
  }
  return out;
}

std::optional<double> C3dParameter::number(std::size_t i) const
{
  if (type == C3dType::Char || i >= numbers.size())
    return std::nullopt;
  return numbers[i];
}

std::optional<std::uint16_t> C3dParameter::unsignedInt16(std::size_t i) const
{
  const auto value = number(i);
  if (!value)
    return std::nullopt;
  if (type != C3dType::Int16) {
    // A float or byte value outside 0…65535 (or NaN) is no unsigned 16-bit count: none, not a
    // wrapped or clamped number (converting it would be undefined behaviour; the fuzzer found one).
    if (!(*value >= 0.0 && *value <= 65535.0))
      return std::nullopt;
    return static_cast<std::uint16_t>(*value);
  }
  return static_cast<std::uint16_t>(static_cast<std::int16_t>(*value));
}

namespace {
std::vector<int> vectorDimensions(std::size_t count, bool scalar)
{
  if (scalar && count == 1)
    return {};
  return {static_cast<int>(count)};
}
} // namespace

C3dParameter C3dParameter::makeInt16(std::string name, const std::vector<int>& values, bool scalar)
{
  C3dParameter p;
  p.name = std::move(name);
  p.type = C3dType::Int16;
  p.dimensions = vectorDimensions(values.size(), scalar);
  for (int v : values)
    p.numbers.push_back(static_cast<double>(static_cast<std::int16_t>(v)));
  return p;
}

C3dParameter C3dParameter::makeFloat(std::string name, const std::vector<double>& values, bool scalar)
{
  C3dParameter p;
  p.name = std::move(name);
  p.type = C3dType::Float;
  p.dimensions = vectorDimensions(values.size(), scalar);
  for (double v : values)
    p.numbers.push_back(static_cast<double>(static_cast<float>(v)));
  return p;
}

C3dParameter C3dParameter::makeStrings(std::string name, const std::vector<std::string>& values)
{
  C3dParameter p;
  p.name = std::move(name);
  p.type = C3dType::Char;
  std::size_t length = 1;
  for (const auto& v : values)
    length = std::max(length, v.size());
  p.dimensions = {static_cast<int>(length), static_cast<int>(values.size())};
  for (const auto& v : values) {
    p.chars += v;
    p.chars.append(length - v.size(), ' ');
  }
  return p;
}

C3dParameter C3dParameter::makeString(std::string name, const std::string& value)
{
  C3dParameter p;
  p.name = std::move(name);
  p.type = C3dType::Char;
  p.dimensions = {static_cast<int>(value.size())};
  p.chars = value;
  return p;
}

const C3dParameter* C3dGroup::find(std::string_view parameterName) const
{
  for (const auto& p : parameters)
    if (equalsIgnoreCase(p.name, parameterName))
      return &p;
  return nullptr;
}

C3dParameter* C3dGroup::find(std::string_view parameterName)
{
  return const_cast<C3dParameter*>(static_cast<const C3dGroup*>(this)->find(parameterName));
}

const C3dGroup* C3dParameterTree::group(std::string_view name) const
{
  for (const auto& g : m_groups)
    if (equalsIgnoreCase(g.name, name))
      return &g;
  return nullptr;
}

C3dGroup* C3dParameterTree::group(std::string_view name)
{
  return const_cast<C3dGroup*>(static_cast<const C3dParameterTree*>(this)->group(name));
}

C3dGroup& C3dParameterTree::ensureGroup(std::string_view name, std::string_view description)
{
  if (C3dGroup* existing = group(name))
    return *existing;
  int nextId = 1;
  for (const auto& g : m_groups)
    nextId = std::max(nextId, g.id + 1);
  C3dGroup g;
  g.id = nextId;
  g.name = toUpper(name);
  g.description = std::string(description);
  m_groups.push_back(std::move(g));
  return m_groups.back();
}

const C3dParameter* C3dParameterTree::find(std::string_view groupName, std::string_view parameterName) const
{
  const C3dGroup* g = group(groupName);
  return g ? g->find(parameterName) : nullptr;
}

void C3dParameterTree::set(std::string_view groupName, C3dParameter parameter)
{
  C3dGroup& g = ensureGroup(groupName);
  if (C3dParameter* existing = g.find(parameter.name)) {
    parameter.name = existing->name;
    if (parameter.description.empty())
      parameter.description = existing->description;
    parameter.locked = existing->locked;
    *existing = std::move(parameter);
    return;
  }
  g.parameters.push_back(std::move(parameter));
}

void C3dParameterTree::remove(std::string_view groupName, std::string_view parameterName)
{
  C3dGroup* g = group(groupName);
  if (!g)
    return;
  auto& ps = g->parameters;
  ps.erase(std::remove_if(ps.begin(), ps.end(),
                          [&](const C3dParameter& p) { return equalsIgnoreCase(p.name, parameterName); }),
           ps.end());
}

void C3dParameterTree::removeGroup(std::string_view groupName)
{
  m_groups.erase(std::remove_if(m_groups.begin(), m_groups.end(),
                                [&](const C3dGroup& g) { return equalsIgnoreCase(g.name, groupName); }),
                 m_groups.end());
}

std::optional<double> C3dParameterTree::number(std::string_view groupName, std::string_view parameterName,
                                               std::size_t i) const
{
  const C3dParameter* p = find(groupName, parameterName);
  return p ? p->number(i) : std::nullopt;
}

std::vector<double> C3dParameterTree::numbers(std::string_view groupName, std::string_view parameterName) const
{
  const C3dParameter* p = find(groupName, parameterName);
  if (!p || p->type == C3dType::Char)
    return {};
  return p->numbers;
}

std::vector<std::string> C3dParameterTree::strings(std::string_view groupName,
                                                   std::string_view parameterName) const
{
  const C3dParameter* p = find(groupName, parameterName);
  return p ? p->strings() : std::vector<std::string>{};
}

std::optional<std::string> C3dParameterTree::string(std::string_view groupName,
                                                    std::string_view parameterName) const
{
  const auto all = strings(groupName, parameterName);
  if (all.empty())
    return std::nullopt;
  return all.front();
}

} // namespace mocap
