#include "mocap/io/take_io.h"

#include "mocap/base/enum_table.h"
#include "mocap/io/bvh_writer.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/io/csv_writer.h"
#include "mocap/io/fbx_writer.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/text.h"
#include "mocap/model/data_loss_record.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/provenance.h"
#include "mocap/io/trc_io.h"

namespace mocap {

namespace {

// The name of a format is its file extension.
constexpr EnumTable<TakeFormat, 5> kFormats{{{
    {TakeFormat::C3d, "c3d"},
    {TakeFormat::Trc, "trc"},
    {TakeFormat::Csv, "csv"},
    {TakeFormat::Bvh, "bvh"},
    {TakeFormat::Fbx, "fbx"},
}}};

} // namespace

TakeFormat formatFromPath(const std::filesystem::path& path)
{
  const std::string ext = lowerExtension(path);
  if (const auto format = kFormats.parse(ext))
    return *format;
  throw InvalidArgument(path.string() + ": unknown file type '" + ext + "' (expected .c3d, .trc, .csv, .bvh or .fbx)");
}

std::string_view formatName(TakeFormat format)
{
  return kFormats.name(format, "unknown");
}

namespace {

/// Puts the sidecar's provenance into a TRC take; an unreadable sidecar is a warning, not a
/// failure to open the take.
void readSidecar(Take& take, const std::filesystem::path& path, std::vector<std::string>* warnings)
{
  const std::filesystem::path sidecar = provenanceSidecarPath(path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(sidecar, error))
    return;
  try {
    applyProvenanceJson(take, readFileBytes(sidecar), sidecar.string(), warnings);
  } catch (const Error& e) {
    if (warnings)
      warnings->push_back(std::string("provenance sidecar ignored: ") + e.what());
  }
}

void writeSidecar(const Take& take, const std::filesystem::path& path)
{
  const std::filesystem::path sidecar = provenanceSidecarPath(path);
  if (hasProvenance(take)) {
    writeFileAtomically(sidecar, provenanceJson(take));
  } else {
    std::error_code ignored;
    std::filesystem::remove(sidecar, ignored);
  }
}

} // namespace

Take readTake(const std::filesystem::path& path, std::vector<std::string>* warnings, std::vector<std::string>* dataLoss)
{
  switch (formatFromPath(path)) {
  case TakeFormat::C3d: return readC3d(path, warnings, dataLoss);
  case TakeFormat::Trc: {
    std::vector<std::string> own;  // as parseC3d: recorded with the take even when not asked for
    std::vector<std::string>& findings = dataLoss ? *dataLoss : own;
    const std::size_t firstNew = findings.size();
    Take take = readTrc(path, warnings, &findings);
    readSidecar(take, path, warnings);  // the history an earlier save kept
    carryDataLoss(take, path.string(), findings, firstNew, warnings);
    return take;
  }
  case TakeFormat::Csv:
  case TakeFormat::Bvh:
  case TakeFormat::Fbx: break;
  }
  throw InvalidArgument(path.string() + ": reading ." + lowerExtension(path) +
                        " files is not supported (read .c3d or .trc)");
}

void writeTake(const Take& take, const std::filesystem::path& path)
{
  switch (formatFromPath(path)) {
  case TakeFormat::C3d: writeC3d(take, path); return;
  case TakeFormat::Trc: writeTrc(take, path); writeSidecar(take, path); return;
  case TakeFormat::Csv: writeCsv(take, path); writeSidecar(take, path); return;
  case TakeFormat::Bvh: writeBvh(take, path); return;
  case TakeFormat::Fbx: writeMarkersFbx(path, take, FbxUpAxis::Z); return;
  }
}

std::string leftOutOnWriting(const Take& take, TakeFormat format)
{
  const bool markersOnly = format == TakeFormat::Trc || format == TakeFormat::Bvh || format == TakeFormat::Fbx;
  const std::string outputs = describeModelOutputs(take);
  if (!markersOnly || outputs.empty())
    return {};
  return "the " + toUpper(formatName(format)) + " file holds marker positions only: " + outputs + " not written";
}

} // namespace mocap
