#pragma once

#include "mocap/model/take.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// File formats the studio reads or writes, chosen by extension.
enum class TakeFormat
{
  C3d,  ///< read and write
  Trc,  ///< read and write
  Csv,  ///< write only
  Bvh,  ///< write only
  Fbx,  ///< write only: the markers as animated nulls (fbx_writer), Z-up unless writeMarkersFbx is told otherwise
};

/// The format named by `path`'s extension (case-insensitive). Throws InvalidArgument for an
/// unknown extension, listing the known ones.
[[nodiscard]] TakeFormat formatFromPath(const std::filesystem::path& path);
[[nodiscard]] std::string_view formatName(TakeFormat format);

/// Reads a take in the format its extension names; tolerated file quirks go to `warnings`, and
/// those that mean data is missing (truncation) or wrong to `dataLoss` as well (with the
/// unacknowledged findings the take's history carried: carryDataLoss). A TRC file's
/// sample states and history come from its provenance sidecar when there is one.
/// Throws IoError, FormatError, or InvalidArgument for a format that cannot be read.
[[nodiscard]] Take readTake(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                            std::vector<std::string>* dataLoss = nullptr);

/// Writes `take` atomically in the format its extension names. TRC and CSV cannot hold sample
/// states or history, so a take that has them also gets the sidecar provenanceSidecarPath(path)
/// (a stale sidecar of a take without them is removed).
void writeTake(const Take& take, const std::filesystem::path& path);

/// What writeTake(take, path in `format`) leaves out, in words to show the user: "" when the file
/// holds everything, else e.g. "the TRC file holds marker positions only: 34 model outputs (…) are
/// not written". TRC, BVH and FBX leave model outputs out; C3D and CSV keep them. O(#points).
[[nodiscard]] std::string leftOutOnWriting(const Take& take, TakeFormat format);

} // namespace mocap
