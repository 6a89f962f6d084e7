#include "mocap/base/file_io.h"

#include "mocap/base/error.h"
#include "mocap/base/text.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <system_error>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mocap {

namespace {
std::string describeErrno()
{
  return std::strerror(errno);
}

struct FileCloser
{
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// Makes a rename in `directory` durable. Best effort: the file is already in place, and some
// file systems refuse to sync a directory (EINVAL), which is no reason to report a failed write.
void syncDirectory(const std::filesystem::path& directory)
{
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
    return;
  (void)::fsync(fd);
  ::close(fd);
}

} // namespace

std::string readFileBytes(const std::filesystem::path& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw IoError(path.string() + ": is a directory");
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file)
    throw IoError(path.string() + ": cannot open (" + describeErrno() + ")");
  std::string bytes;
  if (std::fseek(file.get(), 0, SEEK_END) == 0) {
    const long size = std::ftell(file.get());
    if (size > 0)
      bytes.resize(static_cast<std::size_t>(size));
    std::rewind(file.get());
  }
  std::size_t got = bytes.empty() ? 0 : std::fread(bytes.data(), 1, bytes.size(), file.get());
  bytes.resize(got);
  // Pipes and files that grow while read: take the rest too.
  char chunk[65536];
  while (true) {
    const std::size_t n = std::fread(chunk, 1, sizeof chunk, file.get());
    if (n == 0)
      break;
    bytes.append(chunk, n);
  }
  if (std::ferror(file.get()))
    throw IoError(path.string() + ": read failed (" + describeErrno() + ")");
  return bytes;
}

MappedFile::MappedFile(const std::filesystem::path& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat info {};
  if (fd >= 0 && ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    void* mapped = ::mmap(nullptr, static_cast<std::size_t>(info.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped != MAP_FAILED) {
      m_data = static_cast<const unsigned char*>(mapped);
      m_size = static_cast<std::size_t>(info.st_size);
      m_mapped = true;
      ::close(fd);
      return;
    }
  }
  if (fd >= 0)
    ::close(fd);
  m_fallback = readFileBytes(path);  // empty files, pipes, or mmap refused: read (and report errors)
  m_data = reinterpret_cast<const unsigned char*>(m_fallback.data());
  m_size = m_fallback.size();
}

MappedFile::~MappedFile()
{
  if (m_mapped)
    ::munmap(const_cast<unsigned char*>(m_data), m_size);
}

AtomicFileWriter::AtomicFileWriter(const std::filesystem::path& path) : m_path(path)
{
  const std::filesystem::path directory = path.parent_path().empty() ? "." : path.parent_path();
  std::random_device random;
  m_temporary = directory / ("." + path.filename().string() + ".tmp" + std::to_string(random()));
  m_file = std::fopen(m_temporary.c_str(), "wb");
  if (!m_file)
    throw IoError(path.string() + ": cannot create (" + describeErrno() + ")");
}

AtomicFileWriter::~AtomicFileWriter()
{
  if (m_file) {
    std::fclose(m_file);
    std::error_code ignored;
    std::filesystem::remove(m_temporary, ignored);
  }
}

void AtomicFileWriter::write(std::string_view bytes)
{
  if (!m_file)
    throw IoError(m_path.string() + ": write after commit");
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), m_file) != bytes.size())
    fail("write failed");
}

void AtomicFileWriter::patch(std::size_t offset, std::string_view bytes)
{
  if (!m_file)
    throw IoError(m_path.string() + ": write after commit");
  if (std::fseek(m_file, static_cast<long>(offset), SEEK_SET) != 0)
    fail("seek failed");
  write(bytes);
  if (std::fseek(m_file, 0, SEEK_END) != 0)
    fail("seek failed");
}

void AtomicFileWriter::fail(const std::string& what)
{
  const std::string reason = describeErrno();
  std::fclose(m_file);
  m_file = nullptr;
  std::error_code ignored;
  std::filesystem::remove(m_temporary, ignored);
  throw IoError(m_path.string() + ": " + what + " (" + reason + ")");
}

void AtomicFileWriter::commit()
{
  if (!m_file)
    throw IoError(m_path.string() + ": committed twice");
  if (std::fflush(m_file) != 0)
    fail("write failed");
  // On the disk before the rename: else a crash could leave the new name on an empty file.
  if (::fsync(::fileno(m_file)) != 0)
    fail("cannot flush to disk");
  std::fclose(m_file);
  m_file = nullptr;
  std::error_code ec;
  std::filesystem::rename(m_temporary, m_path, ec);
  if (ec) {
    std::filesystem::remove(m_temporary, ec);
    throw IoError(m_path.string() + ": cannot replace (" + ec.message() + ")");
  }
  syncDirectory(m_path.parent_path().empty() ? std::filesystem::path(".") : m_path.parent_path());
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes)
{
  AtomicFileWriter file(path);
  file.write(bytes);
  file.commit();
}

std::filesystem::path temporaryPathBeside(const std::filesystem::path& path)
{
  const std::filesystem::path directory = path.parent_path().empty() ? "." : path.parent_path();
  std::random_device random;
  return directory / ("." + path.filename().string() + ".tmp" + std::to_string(random()) + path.extension().string());
}

void publishFile(const std::filesystem::path& temporary, const std::filesystem::path& path)
{
  std::error_code ec;
  const auto failed = [&](const std::string& what) {
    std::filesystem::remove(temporary, ec);
    throw IoError(path.string() + ": " + what);
  };
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    failed("cannot reopen the written file (" + describeErrno() + ")");
  const bool flushed = ::fsync(fd) == 0;
  const std::string reason = flushed ? std::string() : describeErrno();
  ::close(fd);
  if (!flushed)
    failed("cannot flush to disk (" + reason + ")");
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    failed("cannot replace (" + ec.message() + ")");
  syncDirectory(path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path());
}

std::string lowerExtension(const std::filesystem::path& path)
{
  std::string ext = path.extension().string();
  if (!ext.empty() && ext.front() == '.')
    ext.erase(0, 1);
  return toLower(ext);
}

} // namespace mocap
