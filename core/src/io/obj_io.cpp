#include "mocap/io/obj_io.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>

namespace mocap {

namespace {

class ObjParser
{
public:
  ObjParser(std::string sourceName, std::string_view text) : m_path(std::move(sourceName)), m_text(text) {}

  Mesh parse()
  {
    std::vector<double> vertices, uvs, normals;
    Mesh mesh;
    std::size_t position = 0;
    while (position < m_text.size()) {
      std::size_t end = m_text.find('\n', position);
      if (end == std::string_view::npos)
        end = m_text.size();
      ++m_line;
      m_rest = m_text.substr(position, end - position);
      position = end + 1;
      const std::string_view keyword = token();
      if (keyword == "v")
        readNumbers(vertices, 3);
      else if (keyword == "vt")
        readNumbers(uvs, 2);
      else if (keyword == "vn")
        readNumbers(normals, 3);
      else if (keyword == "f")
        mesh.faces.push_back(readFace(vertices.size() / 3, uvs.size() / 2, normals.size() / 3));
    }
    mesh.vertices = Eigen::Map<const MeshVertices>(vertices.data(), static_cast<Eigen::Index>(vertices.size() / 3), 3);
    mesh.uvs = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>>(
        uvs.data(), static_cast<Eigen::Index>(uvs.size() / 2), 2);
    mesh.normals = Eigen::Map<const MeshVertices>(normals.data(), static_cast<Eigen::Index>(normals.size() / 3), 3);
    return mesh;
  }

private:
  [[noreturn]] void fail(const std::string& message) const
  {
    throw FormatError(m_path, "line " + std::to_string(m_line) + ": " + message);
  }

  std::string_view token()
  {
    std::size_t start = 0;
    while (start < m_rest.size() && (m_rest[start] == ' ' || m_rest[start] == '\t' || m_rest[start] == '\r'))
      ++start;
    std::size_t end = start;
    while (end < m_rest.size() && m_rest[end] != ' ' && m_rest[end] != '\t' && m_rest[end] != '\r')
      ++end;
    const std::string_view result = m_rest.substr(start, end - start);
    m_rest = m_rest.substr(end);
    return result;
  }

  // The first `count` numbers of the line (OBJ allows an optional w or vertex colours after them).
  void readNumbers(std::vector<double>& out, int count)
  {
    for (int i = 0; i < count; ++i) {
      const std::string_view text = token();
      double value = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        fail("expected a finite number, not '" + std::string(text) + "'");
      out.push_back(value);
    }
  }

  Eigen::Index index(std::string_view text, std::size_t count, const char* what) const
  {
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value == 0)
      fail(std::string("bad ") + what + " index '" + std::string(text) + "'");
    const long long resolved = value < 0 ? static_cast<long long>(count) + value : value - 1;
    if (resolved < 0 || resolved >= static_cast<long long>(count))
      fail(std::string(what) + " index " + std::to_string(value) + " out of range (" + std::to_string(count) +
           " defined)");
    return static_cast<Eigen::Index>(resolved);
  }

  MeshFace readFace(std::size_t vertexCount, std::size_t uvCount, std::size_t normalCount)
  {
    MeshFace face;
    for (std::string_view corner = token(); !corner.empty(); corner = token()) {
      const std::size_t slash1 = corner.find('/');
      face.vertices.push_back(index(corner.substr(0, slash1), vertexCount, "vertex"));
      if (slash1 == std::string_view::npos)
        continue;
      const std::size_t slash2 = corner.find('/', slash1 + 1);
      const std::string_view uv = corner.substr(slash1 + 1, slash2 == std::string_view::npos ? std::string_view::npos
                                                                                             : slash2 - slash1 - 1);
      if (!uv.empty())
        face.uvs.push_back(index(uv, uvCount, "uv"));
      if (slash2 != std::string_view::npos)
        face.normals.push_back(index(corner.substr(slash2 + 1), normalCount, "normal"));
    }
    if (face.vertices.size() < 3)
      fail("a face needs at least 3 corners");
    if ((!face.uvs.empty() && face.uvs.size() != face.vertices.size()) ||
        (!face.normals.empty() && face.normals.size() != face.vertices.size()))
      fail("some corners of the face have uv or normal indices and others do not");
    for (std::size_t i = 0; i < face.vertices.size(); ++i)
      for (std::size_t j = i + 1; j < face.vertices.size(); ++j)
        if (face.vertices[i] == face.vertices[j])
          fail("the face repeats vertex " + std::to_string(face.vertices[i] + 1));
    return face;
  }

  std::string m_path;
  std::string_view m_text;
  std::string_view m_rest;
  std::size_t m_line = 0;
};

void appendCorner(std::string& out, const MeshFace& face, std::size_t i)
{
  out += std::to_string(face.vertices[i] + 1);
  if (face.uvs.empty() && face.normals.empty())
    return;
  out += '/';
  if (!face.uvs.empty())
    out += std::to_string(face.uvs[i] + 1);
  if (!face.normals.empty()) {
    out += '/';
    out += std::to_string(face.normals[i] + 1);
  }
}

template <typename Rows>
void appendRows(std::string& out, const char* keyword, const Rows& rows)
{
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    out += keyword;
    for (Eigen::Index c = 0; c < rows.cols(); ++c) {
      out += ' ';
      appendNumber(out, rows(r, c));
    }
    out += '\n';
  }
}

} // namespace

Mesh readObj(const std::filesystem::path& path)
{
  const MappedFile file(path);
  return parseObj(std::string_view(reinterpret_cast<const char*>(file.data()), file.size()), path.string());
}

Mesh parseObj(std::string_view text, const std::string& sourceName)
{
  return ObjParser(sourceName, text).parse();
}

std::string objText(const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices)
{
  if (vertices.rows() != mesh.vertexCount())
    throw InvalidArgument("objText: " + std::to_string(vertices.rows()) + " positions for a mesh of " +
                          std::to_string(mesh.vertexCount()) + " vertices");
  std::string out;
  out.reserve(static_cast<std::size_t>(vertices.rows() + mesh.uvs.rows() + mesh.normals.rows()) * 40 +
              mesh.faces.size() * 40);
  appendRows(out, "v", vertices);
  appendRows(out, "vt", mesh.uvs);
  appendRows(out, "vn", mesh.normals);
  for (const MeshFace& face : mesh.faces) {
    out += 'f';
    for (std::size_t i = 0; i < face.vertices.size(); ++i) {
      out += ' ';
      appendCorner(out, face, i);
    }
    out += '\n';
  }
  return out;
}

void writeObj(const std::filesystem::path& path, const Mesh& mesh, const Eigen::Ref<const MeshVertices>& vertices)
{
  writeFileAtomically(path, objText(mesh, vertices));
}

} // namespace mocap
