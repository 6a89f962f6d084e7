#pragma once

#include "mocap/model/take.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// How a C3D file's data section was read: where it starts, which source said so, and the frame
/// layout, against what the file holds.
struct C3dLayoutReport
{
  std::size_t dataStartBlock = 0;       ///< 1-based 512-byte block where the data section starts
  std::string dataStartSource;          ///< "POINT:DATA_START" or "header"
  std::size_t frameBytes = 0;           ///< bytes of one frame (points, then analog)
  std::size_t analogValuesPerFrame = 0; ///< analog values in one frame (channels × samples)
  bool isFloat = false;                 ///< float storage (else 16-bit integers)
  std::size_t declaredFrames = 0;       ///< the frame count header and parameters declare
  std::size_t dataBytes = 0;            ///< bytes from the data start to the end of the file
  std::size_t declaredDataBytes = 0;    ///< declaredFrames × frameBytes
};

/// Reads a C3D file: all three processor types (Intel, DEC with VAX floats, MIPS big-endian),
/// integer and float storage, POINT:SCALE, the residual word (a float converted to an integer
/// first, then read as a signed 16-bit word: negative = invalid, so 65535.0 is −1; low byte the
/// residual, bits 8–14 the camera mask), parameters wherever the header points, more than 65535
/// frames (TRIAL:ACTUAL_START_FIELD/END_FIELD) and 255 markers (POINT:LABELS2...), analog data,
/// events, and each point's type (POINT:ANGLES, FORCES, MOMENTS, POWERS, TYPE_GROUPS). The full
/// parameter tree is kept in Take::parameters().
///
/// Header and parameters are not trusted blindly. Where they disagree on the data layout — the
/// data start (header word 9, POINT:DATA_START), integer or float storage (the sign of the header's
/// scale, POINT:SCALE), the point count (header, POINT:USED) or the analog values per frame
/// (header word 3, ANALOG:USED × ANALOG:RATE / POINT:RATE) — the reading whose data section holds
/// the declared frames exactly wins (else one that holds them; ties go to POINT:DATA_START, the
/// header's counts); a data start inside the header or parameter section is never used. Every
/// disagreement, also of scale, rate and frame count, is a warning saying what was used and why.
///
/// What real writers get wrong is tolerated with a warning appended to `warnings`: a missing
/// ANALOG group, DATA_START 0, a missing description-length byte, missing POINT:UNITS, a data
/// section shorter than the frame count (the complete frames are kept) or longer (the rest is not
/// read), residual words that are no 16-bit integer (NaN, infinite, 65536 and more: those
/// samples are invalid, no residual is made up).
/// Throws IoError when the file cannot be read and FormatError (file and byte offset) when it
/// is not a C3D file, its header or parameter section is corrupt or no data start is usable.
/// O(file size): one read, one bulk conversion pass, no per-sample objects.
///
/// Warnings that mean data the file declares is missing from the take (a truncated data
/// section) or that samples are wrong (wrapped integer coordinates) also go to `dataLoss`, so
/// callers can make the user acknowledge them, and are recorded in the take's history with the
/// unacknowledged ones a saved copy's history carried (carryDataLoss, data_loss_record.h). The project's
/// PROCESSING group becomes the take's sample states and history (provenance.h). `layout`, when
/// given, receives how the data section was read.
[[nodiscard]] Take readC3d(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                           std::vector<std::string>* dataLoss = nullptr, C3dLayoutReport* layout = nullptr);

/// The same from bytes in memory; `sourceName` names the data in error messages.
[[nodiscard]] Take parseC3d(const unsigned char* data, std::size_t size, const std::string& sourceName,
                            std::vector<std::string>* warnings = nullptr,
                            std::vector<std::string>* dataLoss = nullptr, C3dLayoutReport* layout = nullptr);

} // namespace mocap
