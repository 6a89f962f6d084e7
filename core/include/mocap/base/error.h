#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace mocap {

/// Base of every exception core throws for bad input or failed I/O.
/// Expected outcomes (an unfillable gap, a tolerated file quirk) are data, not exceptions.
class Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// A file's content is malformed. what() reads "<file>: <message> at byte <offset>".
class FormatError : public Error
{
public:
  FormatError(const std::string& file, std::uint64_t offset, const std::string& message);
  FormatError(const std::string& file, const std::string& message);

  [[nodiscard]] const std::string& file() const { return m_file; }
  /// Byte offset of the problem, or -1 when it has no single position (e.g. a line-based format).
  [[nodiscard]] std::int64_t offset() const { return m_offset; }

private:
  std::string m_file;
  std::int64_t m_offset = -1;
};

/// The file could not be opened, read or written.
class IoError : public Error
{
public:
  using Error::Error;
};

/// A caller passed an argument outside its documented range.
class InvalidArgument : public Error
{
public:
  using Error::Error;
};

} // namespace mocap
