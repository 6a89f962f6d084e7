#pragma once

#include "mocap/cleaning/clean_pipeline.h"

#include <string>
#include <string_view>

namespace mocap {

class JsonValue;
class JsonWriter;

/// A cleaning preset: the options of `mocap clean` (CleanOptions) as a JSON file, so a batch, a
/// cluster job and the studio clean every take the same way. The canonical form, which
/// cleanPresetJson writes, names every option of every step that runs:
///
///     {
///       "format": "mocap-clean-preset", "version": 1,
///       "stabilize": {"markers": ["head1", ...], "keep_stabilized": false},
///       "spikes": {"method": "robust", "factor": 1.5, "threshold": 6, "noise_floor": 0.05, "max_passes": 1},
///       "fill": {"method": "auto", "max_gap_frames": 0, "max_gap_seconds": 0.5, "extrapolate": false,
///                "min_valid_fraction": 0.2, "neighbours": 6},
///       "smooth": {"method": "gcvspl", "degree": 3, "knot_spacing": 4, "cutoff_hz": 6, "winter_cutoff": false,
///                  "gcvspl_mode": "gcv", "gcvspl_degree": 3, "error_variance": 0, "savgol_window": 9,
///                  "savgol_degree": 3}
///     }
///
/// A step whose "method" is "off" is skipped (and holds no other key). Keys left out take the
/// defaults of the core's option structs, so {} is `mocap clean`'s default pipeline.
/// FillOptions::fillAnyway (marker indices of one take) has no place in a preset.

/// The canonical JSON of `options` (keys in a fixed order, shortest round-trip numbers), ending
/// in a newline. O(#options).
[[nodiscard]] std::string cleanPresetJson(const CleanOptions& options);

/// The preset as the next value of `json` (a per-take report embeds the preset it was cleaned with).
void writeCleanPreset(JsonWriter& json, const CleanOptions& options);

/// The preset in a parsed JSON object; throws as parseCleanPreset. O(#keys).
[[nodiscard]] CleanOptions cleanPresetFromJson(const JsonValue& value);

/// Reads a preset. Throws FormatError for text that is not JSON, and InvalidArgument naming the
/// key ("preset spikes.factor: must be a number", "preset: unknown key 'smoth'") for an unknown
/// key, a value of the wrong type, an unknown method or a number out of its documented range.
/// `sourceName` names the file in the errors. O(text size).
[[nodiscard]] CleanOptions parseCleanPreset(std::string_view text, const std::string& sourceName);

/// parseCleanPreset of a file's bytes. Throws IoError when it cannot be read.
[[nodiscard]] CleanOptions readCleanPreset(const std::string& path);

/// The hash (contentHash, as hex) of the canonical JSON: equal presets hash equal however their
/// files are written (key order, spacing, defaults left out). O(#options).
[[nodiscard]] std::string cleanPresetHash(const CleanOptions& options);

} // namespace mocap
