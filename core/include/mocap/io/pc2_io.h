#pragma once

#include "mocap/base/file_io.h"
#include "mocap/model/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// A PC2 point cache (Blender's Mesh Cache modifier, 3ds Max): a 32-byte header ("POINTCACHE2\0",
/// version 1, #points, start frame, sample rate, #samples as int32/float32 little endian), then
/// every sample's points as float32 x, y, z.
struct PointCache
{
  float startFrame = 0.0f;
  float sampleRate = 1.0f;  ///< frames per sample (1: one sample per frame)
  /// One #points × 3 block per sample.
  std::vector<Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>> samples;
};

/// Reads a PC2 file. Throws IoError when it cannot be read and FormatError for a wrong magic or
/// version, negative counts, samples of no points or a size that does not match the header.
/// O(file size).
[[nodiscard]] PointCache readPc2(const std::filesystem::path& path);
/// Parses PC2 bytes as readPc2 does; `sourceName` names them in errors.
[[nodiscard]] PointCache parsePc2(std::string_view bytes, const std::string& sourceName);

/// Streams a PC2 file one frame at a time (a cache of a long take does not fit in memory), writing
/// atomically: the file appears only at finish(). Throws IoError on a failed write and
/// InvalidArgument for a frame of the wrong size or a non-finite coordinate.
class Pc2Writer
{
public:
  Pc2Writer(const std::filesystem::path& path, Eigen::Index pointCount, float startFrame, float sampleRate);

  void addFrame(const Eigen::Ref<const MeshVertices>& points);
  /// Patches the sample count into the header and renames the file into place.
  void finish();

private:
  AtomicFileWriter m_file;
  std::string m_header;
  std::string m_buffer;
  Eigen::Index m_pointCount;
  std::int32_t m_samples = 0;
};

} // namespace mocap
