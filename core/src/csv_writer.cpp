#include "mocap/csv_writer.h"

#include "mocap/error.h"
#include "mocap/file_io.h"

#include <charconv>
#include <cstdint>
#include <limits>

namespace mocap {

namespace {

// Shortest text that reads back to the same double. O(1).
void appendNumber(std::string& out, double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, static_cast<std::size_t>(result.ptr - buffer));
}

// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled. O(field).
void appendField(std::string& out, const std::string& field)
{
  if (field.find_first_of(",\"\r\n") == std::string::npos) {
    out += field;
    return;
  }
  out += '"';
  for (char c : field) {
    if (c == '"')
      out += '"';
    out += c;
  }
  out += '"';
}

} // namespace

std::string formatCsv(const Take& take)
{
  const Eigen::Index frames = take.frameCount();
  const Eigen::Index markers = take.markerCount();
  if (take.firstFrame() > std::numeric_limits<std::int64_t>::max() - frames)
    throw InvalidArgument("first frame " + std::to_string(take.firstFrame()) +
                          " overflows the frame numbers");

  std::string out;
  out.reserve(static_cast<std::size_t>(64 + 32 * markers + frames * (24 + 30 * markers)));
  out += "Frame,Time";
  for (const std::string& label : take.labels()) {
    for (const char* axis : {":X", ":Y", ":Z"}) {
      out += ',';
      appendField(out, label + axis);
    }
  }
  out += '\n';

  for (Eigen::Index f = 0; f < frames; ++f) {
    out += std::to_string(take.firstFrame() + f);
    out += ',';
    appendNumber(out, take.timeOf(f));
    for (Eigen::Index m = 0; m < markers; ++m) {
      const Eigen::Vector3d p = take.position(f, m);
      if (!take.isValid(f, m) || !p.allFinite()) {
        out += ",,,";
        continue;
      }
      for (Eigen::Index axis = 0; axis < 3; ++axis) {
        out += ',';
        appendNumber(out, p[axis]);
      }
    }
    out += '\n';
  }
  return out;
}

void writeCsv(const Take& take, const std::filesystem::path& path)
{
  writeFileAtomically(path, formatCsv(take));
}

} // namespace mocap
