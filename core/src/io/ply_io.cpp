#include "mocap/io/ply_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>

namespace mocap {

namespace {

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property
{
  std::string name;
  Scalar type = Scalar::Float32;
  bool list = false;
  Scalar countType = Scalar::UInt8;
};

struct Element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
};

std::size_t scalarSize(Scalar type)
{
  switch (type) {
  case Scalar::Int8:
  case Scalar::UInt8: return 1;
  case Scalar::Int16:
  case Scalar::UInt16: return 2;
  case Scalar::Int32:
  case Scalar::UInt32:
  case Scalar::Float32: return 4;
  case Scalar::Float64: return 8;
  }
  return 0;
}

class PlyParser
{
public:
  PlyParser(std::string sourceName, std::string_view bytes) : m_path(std::move(sourceName)), m_bytes(bytes) {}

  Mesh parse()
  {
    readHeader();
    Mesh mesh;
    for (const Element& element : m_elements) {
      if (element.name == "vertex")
        readVertices(element, mesh);
      else if (element.name == "face")
        readFaces(element, mesh);
      else
        for (std::size_t i = 0; i < element.count; ++i)
          for (const Property& p : element.properties)
            skipProperty(p);
    }
    for (const MeshFace& face : mesh.faces)
      for (const Eigen::Index v : face.vertices)
        if (v < 0 || v >= mesh.vertexCount())
          fail("face index " + std::to_string(v) + " out of range (" + std::to_string(mesh.vertexCount()) +
               " vertices)");
    return mesh;
  }

private:
  [[noreturn]] void fail(const std::string& message) const
  {
    throw FormatError(m_path, static_cast<std::uint64_t>(m_position), message);
  }

  static bool parseScalar(std::string_view name, Scalar& type)
  {
    static const std::pair<const char*, Scalar> names[] = {
        {"char", Scalar::Int8},     {"int8", Scalar::Int8},       {"uchar", Scalar::UInt8},
        {"uint8", Scalar::UInt8},   {"short", Scalar::Int16},     {"int16", Scalar::Int16},
        {"ushort", Scalar::UInt16}, {"uint16", Scalar::UInt16},   {"int", Scalar::Int32},
        {"int32", Scalar::Int32},   {"uint", Scalar::UInt32},     {"uint32", Scalar::UInt32},
        {"float", Scalar::Float32}, {"float32", Scalar::Float32}, {"double", Scalar::Float64},
        {"float64", Scalar::Float64}};
    for (const auto& [text, value] : names)
      if (name == text) {
        type = value;
        return true;
      }
    return false;
  }

  std::string_view headerLine()
  {
    const std::size_t end = m_bytes.find('\n', m_position);
    if (end == std::string_view::npos)
      fail("header has no end_header line");
    std::string_view line = m_bytes.substr(m_position, end - m_position);
    m_position = end + 1;
    return trim(line);
  }

  void readHeader()
  {
    if (headerLine() != "ply")
      fail("not a PLY file (no 'ply' magic line)");
    for (std::string_view line = headerLine(); line != "end_header"; line = headerLine()) {
      std::vector<std::string_view> words;
      for (const std::string_view word : split(line, ' '))
        if (!word.empty())
          words.push_back(word);
      if (words.empty() || words[0] == "comment" || words[0] == "obj_info")
        continue;
      if (words[0] == "format") {
        if (words.size() < 2)
          fail("format line without a format");
        if (words[1] == "binary_big_endian")
          fail("binary_big_endian PLY is not supported (convert it to ascii or little endian)");
        if (words[1] != "ascii" && words[1] != "binary_little_endian")
          fail("unknown PLY format '" + std::string(words[1]) + "'");
        m_ascii = words[1] == "ascii";
      } else if (words[0] == "element" && words.size() == 3) {
        Element element;
        element.name = std::string(words[1]);
        unsigned long long count = 0;
        const auto [end, error] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), count);
        if (error != std::errc() || end != words[2].data() + words[2].size() || count > m_bytes.size())
          fail("bad element count '" + std::string(words[2]) + "'");
        element.count = static_cast<std::size_t>(count);
        m_elements.push_back(element);
      } else if (words[0] == "property" && !m_elements.empty()) {
        Property property;
        const bool ok = words.size() == 5 && words[1] == "list"
                            ? parseScalar(words[2], property.countType) && parseScalar(words[3], property.type)
                            : words.size() == 3 && parseScalar(words[1], property.type);
        if (!ok)
          fail("bad property line '" + std::string(line) + "'");
        property.list = words.size() == 5;
        property.name = std::string(words.back());
        m_elements.back().properties.push_back(property);
      } else {
        fail("unexpected header line '" + std::string(line) + "'");
      }
    }
  }

  double binaryValue(Scalar type)
  {
    const std::size_t size = scalarSize(type);
    if (m_position + size > m_bytes.size())
      fail("file ends inside the body");
    const char* p = m_bytes.data() + m_position;
    m_position += size;
    // Hosts are little endian (x86-64, AArch64) like the file, so memcpy decodes it.
    switch (type) {
    case Scalar::Int8: { std::int8_t v; std::memcpy(&v, p, 1); return v; }
    case Scalar::UInt8: { std::uint8_t v; std::memcpy(&v, p, 1); return v; }
    case Scalar::Int16: { std::int16_t v; std::memcpy(&v, p, 2); return v; }
    case Scalar::UInt16: { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
    case Scalar::Int32: { std::int32_t v; std::memcpy(&v, p, 4); return v; }
    case Scalar::UInt32: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
    case Scalar::Float32: { float v; std::memcpy(&v, p, 4); return static_cast<double>(v); }
    case Scalar::Float64: { double v; std::memcpy(&v, p, 8); return v; }
    }
    return 0.0;
  }

  double asciiValue()
  {
    while (m_position < m_bytes.size() && std::isspace(static_cast<unsigned char>(m_bytes[m_position])))
      ++m_position;
    std::size_t end = m_position;
    while (end < m_bytes.size() && !std::isspace(static_cast<unsigned char>(m_bytes[end])))
      ++end;
    double value = 0.0;
    const auto [stop, error] = std::from_chars(m_bytes.data() + m_position, m_bytes.data() + end, value);
    if (end == m_position || error != std::errc() || stop != m_bytes.data() + end)
      fail(m_position >= m_bytes.size() ? "file ends inside the body" : "expected a number");
    m_position = end;
    return value;
  }

  double value(Scalar type) { return m_ascii ? asciiValue() : binaryValue(type); }

  std::size_t listCount(const Property& property)
  {
    const double count = value(property.countType);
    if (!(count >= 0.0) || count > 1e6 || count != std::floor(count))
      fail("bad list length");
    return static_cast<std::size_t>(count);
  }

  void skipProperty(const Property& property)
  {
    const std::size_t count = property.list ? listCount(property) : 1;
    for (std::size_t i = 0; i < count; ++i)
      (void)value(property.type);
  }

  void readVertices(const Element& element, Mesh& mesh)
  {
    int axis[3] = {-1, -1, -1};
    for (std::size_t p = 0; p < element.properties.size(); ++p)
      for (int a = 0; a < 3; ++a)
        if (element.properties[p].name == std::string(1, static_cast<char>('x' + a)) && !element.properties[p].list)
          axis[a] = static_cast<int>(p);
    if (axis[0] < 0 || axis[1] < 0 || axis[2] < 0)
      fail("the vertex element lacks x, y or z");
    mesh.vertices.resize(static_cast<Eigen::Index>(element.count), 3);
    for (std::size_t i = 0; i < element.count; ++i)
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (property.list) {
          skipProperty(property);
          continue;
        }
        const double v = value(property.type);
        for (int a = 0; a < 3; ++a)
          if (axis[a] == static_cast<int>(p)) {
            if (!std::isfinite(v))
              fail("vertex " + std::to_string(i) + " has a coordinate that is not finite");
            mesh.vertices(static_cast<Eigen::Index>(i), a) = v;
          }
      }
  }

  /// A corner of face `face`: a whole number. Float lists and ascii text can hold any value, and
  /// converting one outside Eigen::Index's range is undefined; the range check is in parse().
  Eigen::Index vertexIndex(Scalar type, std::size_t face)
  {
    const double index = value(type);
    if (!(std::abs(index) <= 1e15) || index != std::floor(index))
      fail("face " + std::to_string(face) + " has a vertex index that is not a whole number");
    return static_cast<Eigen::Index>(index);
  }

  void readFaces(const Element& element, Mesh& mesh)
  {
    for (std::size_t i = 0; i < element.count; ++i) {
      MeshFace face;
      for (const Property& property : element.properties) {
        if (!property.list || (property.name != "vertex_indices" && property.name != "vertex_index")) {
          skipProperty(property);
          continue;
        }
        const std::size_t count = listCount(property);
        if (count < 3)
          fail("face " + std::to_string(i) + " has fewer than 3 corners");
        for (std::size_t c = 0; c < count; ++c)
          face.vertices.push_back(vertexIndex(property.type, i));
      }
      if (face.vertices.empty())
        fail("the face element has no vertex_indices list");
      mesh.faces.push_back(std::move(face));
    }
  }

  std::string m_path;
  std::string_view m_bytes;
  std::size_t m_position = 0;
  bool m_ascii = true;
  std::vector<Element> m_elements;
};

template <typename T>
void appendBinary(std::string& out, T value)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

} // namespace

Mesh readPly(const std::filesystem::path& path)
{
  const MappedFile file(path);
  return parsePly(std::string_view(reinterpret_cast<const char*>(file.data()), file.size()), path.string());
}

Mesh parsePly(std::string_view bytes, const std::string& sourceName)
{
  Mesh mesh = PlyParser(sourceName, bytes).parse();
  try {
    checkMesh(mesh);
  } catch (const InvalidArgument& e) {
    throw FormatError(sourceName, e.what());
  }
  return mesh;
}

std::string plyBytes(const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices)
{
  if (vertices.rows() != mesh.vertexCount())
    throw InvalidArgument("plyBytes: " + std::to_string(vertices.rows()) + " positions for a mesh of " +
                          std::to_string(mesh.vertexCount()) + " vertices");
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment written by mocap\nelement vertex " << vertices.rows()
         << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << mesh.faces.size()
         << "\nproperty list int int vertex_indices\nend_header\n";
  std::string out = header.str();
  out.reserve(out.size() + static_cast<std::size_t>(vertices.rows()) * 24 + mesh.faces.size() * 20);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    for (int a = 0; a < 3; ++a)
      appendBinary(out, vertices(v, a));
  for (const MeshFace& face : mesh.faces) {
    appendBinary(out, static_cast<std::int32_t>(face.vertices.size()));
    for (const Eigen::Index v : face.vertices)
      appendBinary(out, static_cast<std::int32_t>(v));
  }
  return out;
}

void writePly(const std::filesystem::path& path, const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices)
{
  writeFileAtomically(path, plyBytes(mesh, vertices));
}

} // namespace mocap
