#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Storage type of a C3D parameter, with the values the file uses.
enum class C3dType : std::int8_t
{
  Char = -1,
  Byte = 1,
  Int16 = 2,
  Float = 4,
};

/// One C3D parameter, decoded to host values so it can be written back bit for bit.
/// Arrays are in file order: the first dimension varies fastest. For Char arrays the first
/// dimension is the string length, so a [16, 3] Char parameter holds three 16-char strings.
struct C3dParameter
{
  std::string name;
  std::string description;
  bool locked = false;
  C3dType type = C3dType::Int16;
  std::vector<int> dimensions;   ///< empty for a scalar
  std::vector<double> numbers;   ///< Byte (raw 0..255), Int16 (signed) and Float values
  std::string chars;             ///< Char data

  /// Number of elements the dimensions describe (1 for a scalar).
  [[nodiscard]] std::size_t elementCount() const;
  /// Char data split into strings of dimensions[0] characters, trailing blanks removed.
  [[nodiscard]] std::vector<std::string> strings() const;
  /// Element `i` as a number, or nullopt when absent or not numeric.
  [[nodiscard]] std::optional<double> number(std::size_t i = 0) const;
  /// Element `i` of an Int16 read as unsigned 0..65535 (counts above 32767 are stored negative).
  [[nodiscard]] std::optional<std::uint16_t> unsignedInt16(std::size_t i = 0) const;

  static C3dParameter makeInt16(std::string name, const std::vector<int>& values, bool scalar);
  static C3dParameter makeFloat(std::string name, const std::vector<double>& values, bool scalar);
  static C3dParameter makeStrings(std::string name, const std::vector<std::string>& values);
  static C3dParameter makeString(std::string name, const std::string& value);
};

struct C3dGroup
{
  int id = 0;  ///< positive group number; parameters refer to it
  std::string name;
  std::string description;
  bool locked = false;
  std::vector<C3dParameter> parameters;

  [[nodiscard]] const C3dParameter* find(std::string_view parameterName) const;
  [[nodiscard]] C3dParameter* find(std::string_view parameterName);
};

/// The whole parameter section, groups in file order. Names compare case-insensitively.
class C3dParameterTree
{
public:
  [[nodiscard]] const std::vector<C3dGroup>& groups() const { return m_groups; }
  [[nodiscard]] std::vector<C3dGroup>& groups() { return m_groups; }
  [[nodiscard]] bool empty() const { return m_groups.empty(); }

  [[nodiscard]] const C3dGroup* group(std::string_view name) const;
  [[nodiscard]] C3dGroup* group(std::string_view name);
  /// The group `name`, created (with the next free id) when missing.
  C3dGroup& ensureGroup(std::string_view name, std::string_view description = {});
  [[nodiscard]] const C3dParameter* find(std::string_view groupName, std::string_view parameterName) const;

  /// Replaces (or adds) `parameter` in group `groupName`, keeping an existing description and lock.
  void set(std::string_view groupName, C3dParameter parameter);
  /// Removes a parameter; does nothing when absent.
  void remove(std::string_view groupName, std::string_view parameterName);
  /// Removes a group with its parameters; does nothing when absent.
  void removeGroup(std::string_view groupName);

  // Typed look-ups that return nullopt when the parameter is missing or of the wrong kind.
  [[nodiscard]] std::optional<double> number(std::string_view groupName, std::string_view parameterName,
                                             std::size_t i = 0) const;
  [[nodiscard]] std::vector<double> numbers(std::string_view groupName, std::string_view parameterName) const;
  [[nodiscard]] std::vector<std::string> strings(std::string_view groupName, std::string_view parameterName) const;
  [[nodiscard]] std::optional<std::string> string(std::string_view groupName, std::string_view parameterName) const;

private:
  std::vector<C3dGroup> m_groups;
};

} // namespace mocap
