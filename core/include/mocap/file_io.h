#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// The whole file in one read. Throws IoError naming the file when it cannot be read.
[[nodiscard]] std::string readFileBytes(const std::filesystem::path& path);

/// A whole file mapped read-only into memory (falls back to reading it when it cannot be
/// mapped, e.g. a pipe). Readers decode straight from the page cache without a copy.
class MappedFile
{
public:
  /// Throws IoError naming the file when it cannot be opened or read.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  [[nodiscard]] const unsigned char* data() const { return m_data; }
  [[nodiscard]] std::size_t size() const { return m_size; }

private:
  const unsigned char* m_data = nullptr;
  std::size_t m_size = 0;
  bool m_mapped = false;
  std::string m_fallback;
};

/// Writes `bytes` to a temporary file beside `path`, flushes it and renames it over `path`,
/// so `path` is either the old file or the complete new one, never a partial write.
/// Throws IoError (and removes the temporary file) when any step fails.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// Lower-case extension without the dot ("c3d" for "take.C3D").
[[nodiscard]] std::string lowerExtension(const std::filesystem::path& path);

} // namespace mocap
