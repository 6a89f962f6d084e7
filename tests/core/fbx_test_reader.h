#pragma once
// A tiny binary FBX reader for the tests: walks the node tree of what our writer wrote, checking
// every end offset and null record on the way, so a test can assert structure and values without
// the writer's own code. Arrays must be raw (encoding 0), which is all the writer writes.

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace mocap::test {

struct FbxProperty
{
  char type = 0;
  std::int64_t integer = 0;     ///< C Y I L
  double number = 0.0;          ///< F D
  std::string text;             ///< S R
  std::vector<double> numbers;  ///< f d i l b, as doubles
  std::vector<std::int64_t> integers;  ///< i l b, exactly
};

struct FbxTestNode
{
  std::string name;
  std::vector<FbxProperty> properties;
  std::vector<FbxTestNode> children;

  /// The first child called `childName`, or throws.
  [[nodiscard]] const FbxTestNode& at(std::string_view childName) const
  {
    for (const FbxTestNode& c : children)
      if (c.name == childName)
        return c;
    throw std::runtime_error("no child " + std::string(childName) + " in " + name);
  }
  [[nodiscard]] std::vector<const FbxTestNode*> all(std::string_view childName) const
  {
    std::vector<const FbxTestNode*> found;
    for (const FbxTestNode& c : children)
      if (c.name == childName)
        found.push_back(&c);
    return found;
  }
};

class FbxTestReader
{
public:
  explicit FbxTestReader(std::string bytes) : m_bytes(std::move(bytes)) {}

  /// The top-level nodes; throws std::runtime_error on anything malformed.
  std::vector<FbxTestNode> read()
  {
    if (m_bytes.compare(0, 23, std::string("Kaydara FBX Binary  \0\x1a\0", 23)) != 0)
      throw std::runtime_error("bad magic");
    m_at = 23;
    version = take<std::uint32_t>();
    std::vector<FbxTestNode> nodes;
    while (true) {
      FbxTestNode node;
      if (!readNode(node))
        break;
      nodes.push_back(std::move(node));
    }
    footerOffset = m_at;
    return nodes;
  }

  std::uint32_t version = 0;
  std::size_t footerOffset = 0;

private:
  template <typename T>
  T take()
  {
    if (m_at + sizeof(T) > m_bytes.size())
      throw std::runtime_error("truncated at " + std::to_string(m_at));
    T value;
    std::memcpy(&value, m_bytes.data() + m_at, sizeof(T));
    m_at += sizeof(T);
    return value;
  }

  std::string takeBytes(std::size_t n)
  {
    if (m_at + n > m_bytes.size())
      throw std::runtime_error("truncated string at " + std::to_string(m_at));
    std::string s = m_bytes.substr(m_at, n);
    m_at += n;
    return s;
  }

  template <typename T>
  void takeArray(FbxProperty& p)
  {
    const auto count = take<std::uint32_t>();
    if (take<std::uint32_t>() != 0)
      throw std::runtime_error("compressed array");
    if (take<std::uint32_t>() != count * sizeof(T))
      throw std::runtime_error("array byte length disagrees");
    for (std::uint32_t i = 0; i < count; ++i) {
      const T v = take<T>();
      p.numbers.push_back(static_cast<double>(v));
      if constexpr (std::is_integral_v<T>)
        p.integers.push_back(static_cast<std::int64_t>(v));
    }
  }

  FbxProperty readProperty()
  {
    FbxProperty p;
    p.type = take<char>();
    switch (p.type) {
    case 'C': p.integer = take<std::uint8_t>(); break;
    case 'Y': p.integer = take<std::int16_t>(); break;
    case 'I': p.integer = take<std::int32_t>(); break;
    case 'L': p.integer = take<std::int64_t>(); break;
    case 'F': p.number = static_cast<double>(take<float>()); break;
    case 'D': p.number = take<double>(); break;
    case 'S':
    case 'R': p.text = takeBytes(take<std::uint32_t>()); break;
    case 'f': takeArray<float>(p); break;
    case 'd': takeArray<double>(p); break;
    case 'i': takeArray<std::int32_t>(p); break;
    case 'l': takeArray<std::int64_t>(p); break;
    case 'b': takeArray<std::uint8_t>(p); break;
    default: throw std::runtime_error(std::string("unknown property type ") + p.type);
    }
    return p;
  }

  /// False at a null record.
  bool readNode(FbxTestNode& node)
  {
    const auto end = take<std::uint32_t>();
    const auto count = take<std::uint32_t>();
    const auto listLength = take<std::uint32_t>();
    const auto nameLength = take<std::uint8_t>();
    if (end == 0) {
      if (count != 0 || listLength != 0 || nameLength != 0)
        throw std::runtime_error("bad null record");
      return false;
    }
    node.name = takeBytes(nameLength);
    const std::size_t listStart = m_at;
    for (std::uint32_t i = 0; i < count; ++i)
      node.properties.push_back(readProperty());
    if (m_at - listStart != listLength)
      throw std::runtime_error("property list length disagrees in " + node.name);
    if (m_at < end) {
      while (true) {
        FbxTestNode child;
        if (!readNode(child))
          break;
        node.children.push_back(std::move(child));
      }
    }
    if (m_at != end)
      throw std::runtime_error("end offset disagrees in " + node.name);
    return true;
  }

  std::string m_bytes;
  std::size_t m_at = 0;
};

/// The top-level nodes of `bytes`.
inline std::vector<FbxTestNode> readFbxForTest(const std::string& bytes)
{
  return FbxTestReader(bytes).read();
}

/// The node called `name` among `nodes`, or throws.
inline const FbxTestNode& fbxNode(const std::vector<FbxTestNode>& nodes, std::string_view name)
{
  for (const FbxTestNode& n : nodes)
    if (n.name == name)
      return n;
  throw std::runtime_error("no top-level node " + std::string(name));
}

} // namespace mocap::test
