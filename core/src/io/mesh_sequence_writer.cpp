#include "mocap/io/mesh_sequence_writer.h"

#include "mocap/base/error.h"
#include "mocap/io/obj_io.h"
#include "mocap/io/ply_io.h"

#include <cstdio>
#include <system_error>

namespace mocap {

MeshSequenceWriter::MeshSequenceWriter(std::filesystem::path out, const Mesh& mesh, MeshSequenceFormat format,
                                       std::string name, float startFrame)
    : m_out(std::move(out)), m_mesh(mesh), m_format(format), m_name(std::move(name))
{
  if (m_format == MeshSequenceFormat::ObjPlusPc2) {
    m_cache.emplace(m_out, mesh.vertexCount(), startFrame, 1.0f);
    return;
  }
  std::error_code ec;
  m_createdFolder = std::filesystem::create_directories(m_out, ec);
  if (ec || !std::filesystem::is_directory(m_out))
    throw IoError(m_out.string() + ": cannot create the folder" + (ec ? " (" + ec.message() + ")" : std::string()));
  if (m_format == MeshSequenceFormat::PlySequence) {
    const std::filesystem::path neutral = m_out / (m_name + "_neutral.obj");
    writeObj(neutral, mesh);
    m_written.push_back(neutral);
  }
}

MeshSequenceWriter::~MeshSequenceWriter()
{
  if (!m_finished)
    removeWrittenFiles();  // the PC2's temporary file goes with m_cache
}

void MeshSequenceWriter::add(const Eigen::Ref<const MeshVertices>& vertices)
{
  if (m_finished)
    throw InvalidArgument("MeshSequenceWriter: a frame after finish()");
  if (m_cache) {
    m_cache->addFrame(vertices);
    ++m_count;
    return;
  }
  char number[32];
  std::snprintf(number, sizeof number, "_%04lld", m_count + 1);
  const bool ply = m_format == MeshSequenceFormat::PlySequence;
  const std::filesystem::path file = m_out / (m_name + number + (ply ? ".ply" : ".obj"));
  if (ply)
    writePly(file, m_mesh, vertices);
  else
    writeObj(file, m_mesh, vertices);
  m_written.push_back(file);
  ++m_count;
}

void MeshSequenceWriter::finish()
{
  if (m_finished)
    return;
  if (m_cache) {
    m_cache->finish();
    // The OBJ comes after the cache, so a failure before here leaves neither; if the OBJ cannot be
    // written, the cache goes too rather than stand without its mesh.
    m_written.push_back(m_out);
    writeObj(restObjPath(m_out), m_mesh);
  }
  m_finished = true;
}

std::filesystem::path MeshSequenceWriter::restObjPath(const std::filesystem::path& cachePath)
{
  return std::filesystem::path(cachePath).replace_extension(".obj");
}

void MeshSequenceWriter::removeWrittenFiles() noexcept
{
  std::error_code ignored;
  for (const std::filesystem::path& file : m_written)
    std::filesystem::remove(file, ignored);
  if (m_createdFolder)
    std::filesystem::remove(m_out, ignored);  // only when empty: removes nothing else
}

} // namespace mocap
