#pragma once

#include "mocap/model/mesh.h"
#include "mocap/io/pc2_io.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mocap {

/// How a deformed mesh animation is written for animation tools.
enum class MeshSequenceFormat
{
  ObjSequence,  ///< NAME_0001.obj, NAME_0002.obj… in a folder
  PlySequence,  ///< NAME_neutral.obj (faces, UVs, normals) and NAME_0001.ply… in a folder
  ObjPlusPc2,   ///< OUT.pc2 point cache and the rest mesh as OUT.obj beside it (Blender's Mesh Cache)
};

/// Streams the frames of a deformed mesh to disk, one frame at a time (a long take does not fit
/// in memory). Nothing is left half written: every file is written atomically, the PC2 cache
/// appears only at finish() and its rest OBJ after it, and a writer destroyed before finish()
/// (an exception, a cancelled export) removes the sequence files it wrote so far, and the folder
/// when it created it. A sequence file that replaced an older one of the same name is removed too.
/// Throws IoError on a failed write and InvalidArgument for a frame of the wrong size.
/// Cost: O(#vertices) per frame for PC2, O(#vertices + #corners) per sequence frame.
class MeshSequenceWriter
{
public:
  /// `out` is the .pc2 file for ObjPlusPc2, else the folder (created when missing); `name` is the
  /// file-name stem of sequence files; `startFrame` is the PC2 header's first frame.
  MeshSequenceWriter(std::filesystem::path out, const Mesh& mesh, MeshSequenceFormat format, std::string name,
                     float startFrame);
  ~MeshSequenceWriter();
  MeshSequenceWriter(const MeshSequenceWriter&) = delete;
  MeshSequenceWriter& operator=(const MeshSequenceWriter&) = delete;

  /// Appends the next frame's vertex positions (#vertices × 3).
  void add(const Eigen::Ref<const MeshVertices>& vertices);
  /// Completes the output (PC2: patches the header, renames it into place, then writes the OBJ).
  void finish();

  /// Frames added so far.
  [[nodiscard]] long long frameCount() const { return m_count; }
  /// The rest OBJ written beside a cache at `cachePath` (same stem, .obj).
  [[nodiscard]] static std::filesystem::path restObjPath(const std::filesystem::path& cachePath);

private:
  void removeWrittenFiles() noexcept;

  std::filesystem::path m_out;
  const Mesh& m_mesh;
  MeshSequenceFormat m_format;
  std::string m_name;
  std::optional<Pc2Writer> m_cache;
  std::vector<std::filesystem::path> m_written;
  bool m_createdFolder = false;
  bool m_finished = false;
  long long m_count = 0;
};

} // namespace mocap
