#pragma once

#include "mocap/model/marker_set.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace mocap {

/// The marker-set file, JSON:
///   { "format": "mocap-marker-set", "version": 1, "units": "mm",
///     "markers": [ { "label": "Nose", "position": [x, y, z], "vertex": 812 }, ... ],
///     "pairs": [ ["Leye", "Reye"], ... ], "links": [ ["Nose", "Chin"], ... ],
///     "mesh": "face.obj" }
/// `pairs`, `links`, `mesh` and each marker's `vertex` are optional. Pairs and links name labels.
[[nodiscard]] std::string markerSetJson(const MarkerSet& set);

/// Parses the text above and validates it (validateMarkerSet). Throws FormatError(sourceName,
/// ...) for malformed JSON, a missing or wrongly typed member, an unknown label in a pair or link,
/// unknown units, another format name or a version other than 1. O(text size + #labels log #labels).
[[nodiscard]] MarkerSet parseMarkerSet(std::string_view text, const std::string& sourceName);

/// parseMarkerSet on a file's content; throws IoError when it cannot be read.
[[nodiscard]] MarkerSet readMarkerSet(const std::filesystem::path& path);

/// Writes markerSetJson(set) atomically after validateMarkerSet.
void writeMarkerSet(const MarkerSet& set, const std::filesystem::path& path);

/// parseMarkerPairs on a file's content, or, for a .json marker-set file (readMarkerSet), its
/// pairs by label (FormatError for a label not in `labels`). Throws IoError when it cannot be
/// read. O(file size + #labels).
[[nodiscard]] MarkerSymmetry readMarkerPairs(const std::filesystem::path& path,
                                             const std::vector<std::string>& labels);

} // namespace mocap
