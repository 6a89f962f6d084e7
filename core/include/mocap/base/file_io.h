#pragma once

#include <cstdio>
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

/// Writes `bytes` to a temporary file beside `path`, flushes it to the disk (fsync) and renames
/// it over `path` (then syncs the folder), so `path` is either the old file or the complete new
/// one, never a partial write, also after a power cut.
/// Throws IoError (and removes the temporary file) when any step fails.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// writeFileAtomically for output too large to hold at once: bytes are streamed to a temporary
/// file beside `path`, and commit() flushes it to the disk and renames it over `path`. Destroyed without
/// commit() (e.g. by an exception), it removes the temporary file and leaves `path` untouched.
/// Every method throws IoError naming `path` when a step fails.
class AtomicFileWriter
{
public:
  explicit AtomicFileWriter(const std::filesystem::path& path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(std::string_view bytes);
  /// Overwrites already written bytes at `offset` (e.g. a header with counts known at the end).
  void patch(std::size_t offset, std::string_view bytes);
  void commit();

private:
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path m_path;
  std::filesystem::path m_temporary;
  std::FILE* m_file = nullptr;
};

/// A fresh name for a temporary file beside `path` ending in `path`'s own extension (".x.mp4.tmp123.mp4"
/// for "x.mp4"), for writers that pick a format by extension and write the file themselves (a video
/// encoder); publishFile() then puts it in place.
[[nodiscard]] std::filesystem::path temporaryPathBeside(const std::filesystem::path& path);

/// Flushes the complete file `temporary` to the disk and renames it over `path` (then syncs the
/// folder), as AtomicFileWriter::commit does for its own file. Throws IoError naming `path` (and
/// removes `temporary`) when a step fails.
void publishFile(const std::filesystem::path& temporary, const std::filesystem::path& path);

/// Lower-case extension without the dot ("c3d" for "take.C3D").
[[nodiscard]] std::string lowerExtension(const std::filesystem::path& path);

} // namespace mocap
