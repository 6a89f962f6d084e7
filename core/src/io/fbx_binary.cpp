#include "mocap/io/fbx_binary.h"

#include "mocap/base/error.h"

#include <cstring>
#include <limits>

namespace mocap {

namespace {

constexpr std::size_t kNullRecordBytes = 13;

// The footer's fixed bytes, as the FBX SDK (and every exporter that wants the SDK to open its
// files) writes them.
constexpr unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                         0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
constexpr unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                            0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

// Appends the little-endian bytes of a trivially copyable value (x86-64 and ARM64 are little-endian).
template <typename T>
void appendValue(std::string& out, T value)
{
  static_assert(std::numeric_limits<T>::is_specialized);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void putUint32(std::string& out, std::size_t at, std::size_t value)
{
  const auto v = static_cast<std::uint32_t>(value);
  std::memcpy(out.data() + at, &v, sizeof(v));
}

std::uint32_t checkedLength(std::size_t length, const char* what)
{
  if (length > std::numeric_limits<std::uint32_t>::max())
    throw InvalidArgument(std::string("FBX: ") + what + " is too long for a 32-bit length");
  return static_cast<std::uint32_t>(length);
}

// One node record: its header with the end offset patched after the children. O(node size).
void appendNode(std::string& out, const FbxNode& node)
{
  if (node.name().size() > 255)
    throw InvalidArgument("FBX: the node name '" + node.name().substr(0, 32) + "…' is longer than 255 bytes");
  const std::size_t start = out.size();
  appendValue<std::uint32_t>(out, 0);  // end offset, patched below
  appendValue<std::uint32_t>(out, node.propertyCount());
  appendValue<std::uint32_t>(out, checkedLength(node.propertyBytes().size(), "a property list"));
  out += static_cast<char>(node.name().size());
  out += node.name();
  out += node.propertyBytes();
  for (const FbxNode& child : node.children())
    appendNode(out, child);
  if (!node.children().empty() || node.propertyCount() == 0)
    out.append(kNullRecordBytes, '\0');
  if (out.size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidArgument("FBX: the file would be larger than FBX 7.4's 4 GiB");
  putUint32(out, start, out.size());
}

} // namespace

FbxNode::FbxNode(std::string name) : m_name(std::move(name)) {}

FbxNode& FbxNode::child(std::string name)
{
  return m_children.emplace_back(std::move(name));
}

void FbxNode::beginProperty(char type)
{
  m_properties += type;
  ++m_propertyCount;
}

FbxNode& FbxNode::addBool(bool value)
{
  beginProperty('C');
  m_properties += value ? '\1' : '\0';
  return *this;
}

FbxNode& FbxNode::addInt16(std::int16_t value)
{
  beginProperty('Y');
  appendValue(m_properties, value);
  return *this;
}

FbxNode& FbxNode::addInt32(std::int32_t value)
{
  beginProperty('I');
  appendValue(m_properties, value);
  return *this;
}

FbxNode& FbxNode::addInt64(std::int64_t value)
{
  beginProperty('L');
  appendValue(m_properties, value);
  return *this;
}

FbxNode& FbxNode::addFloat(float value)
{
  beginProperty('F');
  appendValue(m_properties, value);
  return *this;
}

FbxNode& FbxNode::addDouble(double value)
{
  beginProperty('D');
  appendValue(m_properties, value);
  return *this;
}

FbxNode& FbxNode::addString(std::string_view value)
{
  beginProperty('S');
  appendValue(m_properties, checkedLength(value.size(), "a string"));
  m_properties += value;
  return *this;
}

FbxNode& FbxNode::addRaw(std::string_view bytes)
{
  beginProperty('R');
  appendValue(m_properties, checkedLength(bytes.size(), "a raw property"));
  m_properties += bytes;
  return *this;
}

// An array: element count, encoding 0 (raw), byte length, the elements.
void FbxNode::addArray(char type, std::uint32_t count, const void* data, std::size_t bytes)
{
  beginProperty(type);
  appendValue(m_properties, count);
  appendValue<std::uint32_t>(m_properties, 0);
  appendValue(m_properties, checkedLength(bytes, "an array"));
  m_properties.append(static_cast<const char*>(data), bytes);
}

FbxNode& FbxNode::addFloats(const std::vector<float>& values)
{
  addArray('f', checkedLength(values.size(), "an array"), values.data(), values.size() * sizeof(float));
  return *this;
}

FbxNode& FbxNode::addDoubles(const std::vector<double>& values)
{
  addArray('d', checkedLength(values.size(), "an array"), values.data(), values.size() * sizeof(double));
  return *this;
}

FbxNode& FbxNode::addInt32s(const std::vector<std::int32_t>& values)
{
  addArray('i', checkedLength(values.size(), "an array"), values.data(), values.size() * sizeof(std::int32_t));
  return *this;
}

FbxNode& FbxNode::addInt64s(const std::vector<std::int64_t>& values)
{
  addArray('l', checkedLength(values.size(), "an array"), values.data(), values.size() * sizeof(std::int64_t));
  return *this;
}

FbxNode& FbxNode::addBools(const std::vector<bool>& values)
{
  std::string bytes;
  bytes.reserve(values.size());
  for (const bool value : values)
    bytes += value ? '\1' : '\0';
  addArray('b', checkedLength(values.size(), "an array"), bytes.data(), bytes.size());
  return *this;
}

std::string fbxBinary(const std::vector<const FbxNode*>& topLevel)
{
  std::string out("Kaydara FBX Binary  \0\x1a\0", 23);
  appendValue(out, kFbxVersion);
  for (const FbxNode* node : topLevel)
    appendNode(out, *node);
  out.append(kNullRecordBytes, '\0');
  out.append(reinterpret_cast<const char*>(kFooterId), sizeof(kFooterId));
  out.append(4, '\0');
  const std::size_t padding = 16 - out.size() % 16;  // a whole 16 when already aligned, as the SDK does
  out.append(padding, '\0');
  appendValue(out, kFbxVersion);
  out.append(120, '\0');
  out.append(reinterpret_cast<const char*>(kFooterMagic), sizeof(kFooterMagic));
  return out;
}

} // namespace mocap
