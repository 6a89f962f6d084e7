#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// One reference video linked to a take, as its sidecar remembers it.
struct ReferenceVideoLink
{
  /// The video file: where it was found, or (when missing) where the sidecar last saw it.
  std::filesystem::path path;
  /// `path` relative to the take's folder, as stored ("" when none was): tried first on reading,
  /// so a folder moved with its take and videos still finds them.
  std::filesystem::path relative;
  double offset = 0.0;  ///< seconds: video time at the take's first frame
  bool found = true;    ///< whether `path` exists (reading sets it)
};

/// The sidecar beside a take that remembers its reference videos: "TAKE.c3d" → "TAKE.c3d.video.json"
/// (the take's full file name plus ".video.json", so takes differing only by extension keep theirs apart).
[[nodiscard]] std::filesystem::path referenceVideoSidecarPath(const std::filesystem::path& take);

/// A link to `video` from the take at `take`: its absolute path and the path relative to the take's folder.
[[nodiscard]] ReferenceVideoLink linkReferenceVideo(const std::filesystem::path& video,
                                                    const std::filesystem::path& take, double offset);

/// The videos the sidecar of `take` remembers, in order; none when it has no sidecar. Each is
/// looked for at its relative path (from the take's folder) first, then at its absolute path;
/// one found at neither comes back with found = false and both paths as stored, so writing the
/// links back loses nothing. Throws FormatError (naming the sidecar) for a malformed sidecar and
/// IoError when it cannot be read. O(sidecar size).
[[nodiscard]] std::vector<ReferenceVideoLink> readReferenceVideoSidecar(const std::filesystem::path& take);

/// Writes `links` to the sidecar of `take` atomically (a temporary file renamed over it); with no
/// links the sidecar is removed. JSON: {"format": "mocap reference videos", "version": 1,
/// "videos": [{"path": RELATIVE, "absolute_path": ABSOLUTE, "offset": SECONDS}, …]}, paths with
/// forward slashes. Throws IoError when it cannot be written.
void writeReferenceVideoSidecar(const std::filesystem::path& take, const std::vector<ReferenceVideoLink>& links);

} // namespace mocap
