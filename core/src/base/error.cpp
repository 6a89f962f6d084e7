#include "mocap/base/error.h"

namespace mocap {

FormatError::FormatError(const std::string& file, std::uint64_t offset, const std::string& message)
    : Error(file + ": " + message + " at byte " + std::to_string(offset)), m_file(file),
      m_offset(static_cast<std::int64_t>(offset))
{
}

FormatError::FormatError(const std::string& file, const std::string& message)
    : Error(file + ": " + message), m_file(file)
{
}

} // namespace mocap
