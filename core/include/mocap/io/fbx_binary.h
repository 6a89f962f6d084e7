#pragma once

#include <cstdint>
#include <list>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// One node record of a binary FBX file: a name, a list of typed properties and child nodes.
/// Properties are encoded as they are added (little-endian, type code then value; arrays raw,
/// encoding 0), so a node holds its bytes and writing the file is one pass. O(size of the value)
/// per add.
class FbxNode
{
public:
  explicit FbxNode(std::string name);

  /// Appends a child node and returns it (references stay valid as more children are added).
  FbxNode& child(std::string name);

  FbxNode& addBool(bool value);                   ///< 'C'
  FbxNode& addInt16(std::int16_t value);          ///< 'Y'
  FbxNode& addInt32(std::int32_t value);          ///< 'I'
  FbxNode& addInt64(std::int64_t value);          ///< 'L'
  FbxNode& addFloat(float value);                 ///< 'F'
  FbxNode& addDouble(double value);               ///< 'D'
  FbxNode& addString(std::string_view value);     ///< 'S' (may hold the "\0\1" name–class separator)
  FbxNode& addRaw(std::string_view bytes);        ///< 'R'
  FbxNode& addFloats(const std::vector<float>& values);          ///< 'f'
  FbxNode& addDoubles(const std::vector<double>& values);        ///< 'd'
  FbxNode& addInt32s(const std::vector<std::int32_t>& values);   ///< 'i'
  FbxNode& addInt64s(const std::vector<std::int64_t>& values);   ///< 'l'
  FbxNode& addBools(const std::vector<bool>& values);            ///< 'b' (one byte each)

  [[nodiscard]] const std::string& name() const { return m_name; }
  [[nodiscard]] std::uint32_t propertyCount() const { return m_propertyCount; }
  /// The encoded properties, as they appear in the file.
  [[nodiscard]] const std::string& propertyBytes() const { return m_properties; }
  [[nodiscard]] const std::list<FbxNode>& children() const { return m_children; }

private:
  void beginProperty(char type);
  void addArray(char type, std::uint32_t count, const void* data, std::size_t bytes);

  std::string m_name;
  std::string m_properties;
  std::uint32_t m_propertyCount = 0;
  std::list<FbxNode> m_children;
};

/// The FBX 7.4 version number written in the header and footer.
inline constexpr std::uint32_t kFbxVersion = 7400;
/// FBX time: ticks per second (KTime).
inline constexpr std::int64_t kFbxTicksPerSecond = 46186158000;

/// A binary FBX 7.4 file: the 27-byte header ("Kaydara FBX Binary  \0", 0x1A 0x00, version), each
/// top-level node (end offset, property count, property bytes, name length, name, properties,
/// children and a 13-byte null record after them — also after a node with neither properties nor
/// children, as the SDK writes it), the null record that ends the top level, and the footer the
/// FBX SDK writes (its fixed id, padding to 16 bytes, the version, 120 zero bytes, its closing
/// magic). Offsets are 32-bit in 7.4: throws InvalidArgument when the file would pass 4 GiB or a
/// name exceeds 255 bytes. O(file size).
[[nodiscard]] std::string fbxBinary(const std::vector<const FbxNode*>& topLevel);

} // namespace mocap
