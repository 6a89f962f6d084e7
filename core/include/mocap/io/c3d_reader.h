#pragma once

#include "mocap/model/take.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// Reads a C3D file: all three processor types (Intel, DEC with VAX floats, MIPS big-endian),
/// integer and float storage, POINT:SCALE, the residual word (negative = invalid, low byte the
/// residual, high byte the camera mask), parameters wherever the header points, more than 65535
/// frames (TRIAL:ACTUAL_START_FIELD/END_FIELD) and 255 markers (POINT:LABELS2...), analog data
/// and events. The full parameter tree is kept in Take::parameters().
///
/// What real writers get wrong is tolerated with a warning appended to `warnings`: a missing
/// ANALOG group, DATA_START 0, a missing description-length byte, missing POINT:UNITS, a data
/// section shorter than the frame count (the complete frames are kept).
/// Throws IoError when the file cannot be read and FormatError (file and byte offset) when it
/// is not a C3D file or its header or parameter section is corrupt.
/// O(file size): one read, one bulk conversion pass, no per-sample objects.
///
/// Warnings that mean data the file declares is missing from the take (a truncated data
/// section) also go to `dataLoss`, so callers can make the user acknowledge them. The project's
/// PROCESSING group becomes the take's sample states and history (provenance.h).
[[nodiscard]] Take readC3d(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                           std::vector<std::string>* dataLoss = nullptr);

/// The same from bytes in memory; `sourceName` names the data in error messages.
[[nodiscard]] Take parseC3d(const unsigned char* data, std::size_t size, const std::string& sourceName,
                            std::vector<std::string>* warnings = nullptr,
                            std::vector<std::string>* dataLoss = nullptr);

} // namespace mocap
