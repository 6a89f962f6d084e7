#include "mocap/take_io.h"

#include "mocap/bvh_writer.h"
#include "mocap/c3d_reader.h"
#include "mocap/c3d_writer.h"
#include "mocap/csv_writer.h"
#include "mocap/error.h"
#include "mocap/file_io.h"
#include "mocap/trc_io.h"

namespace mocap {

TakeFormat formatFromPath(const std::filesystem::path& path)
{
  const std::string ext = lowerExtension(path);
  if (ext == "c3d")
    return TakeFormat::C3d;
  if (ext == "trc")
    return TakeFormat::Trc;
  if (ext == "csv")
    return TakeFormat::Csv;
  if (ext == "bvh")
    return TakeFormat::Bvh;
  throw InvalidArgument(path.string() + ": unknown file type '" + ext + "' (expected .c3d, .trc, .csv or .bvh)");
}

std::string_view formatName(TakeFormat format)
{
  switch (format) {
  case TakeFormat::C3d: return "c3d";
  case TakeFormat::Trc: return "trc";
  case TakeFormat::Csv: return "csv";
  case TakeFormat::Bvh: return "bvh";
  }
  return "unknown";
}

Take readTake(const std::filesystem::path& path, std::vector<std::string>* warnings)
{
  switch (formatFromPath(path)) {
  case TakeFormat::C3d: return readC3d(path, warnings);
  case TakeFormat::Trc: return readTrc(path, warnings);
  case TakeFormat::Csv:
  case TakeFormat::Bvh: break;
  }
  throw InvalidArgument(path.string() + ": reading ." + lowerExtension(path) +
                        " files is not supported (read .c3d or .trc)");
}

void writeTake(const Take& take, const std::filesystem::path& path)
{
  switch (formatFromPath(path)) {
  case TakeFormat::C3d: writeC3d(take, path); return;
  case TakeFormat::Trc: writeTrc(take, path); return;
  case TakeFormat::Csv: writeCsv(take, path); return;
  case TakeFormat::Bvh: writeBvh(take, path); return;
  }
}

} // namespace mocap
