#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace mocap {

/// One take of a manifest.
struct ManifestEntry
{
  std::filesystem::path input;     ///< absolute, lexically normal
  std::filesystem::path relative;  ///< below the manifest's root: where the outputs go under OUTDIR
  std::size_t line = 0;            ///< 1-based line of a text manifest; 0 for a folder's file
};

/// The takes of a batch, in a fixed order (a text manifest's line order; a folder's paths sorted),
/// so take I is the same take for `mocap batch`, `mocap clean --index I` and every cluster task.
struct TakeManifest
{
  std::filesystem::path source;  ///< the manifest file or folder
  /// The deepest folder holding every input: outputs mirror the inputs' tree below it.
  std::filesystem::path root;
  std::vector<ManifestEntry> takes;
  /// What was tolerated and how: "takes.txt:7: repeats line 3 (a.c3d); run once",
  /// "DIR/loop: a symbolic link back to DIR (a folder loop); not followed".
  std::vector<std::string> warnings;
};

/// Reads a manifest: a text file with one input path per line (relative paths are relative to the
/// file's folder; blank lines and lines starting with '#' are ignored; a path given again is
/// reported and run once) or a folder, searched recursively for .c3d and .trc files (any case),
/// following symbolic links but never into a folder already visited (a link loop is reported, not
/// followed), skipping `exclude` and everything below it (the output folder when it lies inside).
/// Inputs that do not exist are kept: the batch records their error. Throws IoError when the
/// manifest cannot be read and InvalidArgument when it names no take. O(#lines) or O(#entries
/// of the folder tree · log).
[[nodiscard]] TakeManifest readManifest(const std::filesystem::path& source, const std::filesystem::path& exclude = {});

/// The output paths of one take under `outDir`: the cleaned take (same name and format as the
/// input) and its report beside it, "<name>.report.json".
struct TakeOutputs
{
  std::filesystem::path take;
  std::filesystem::path report;
};
[[nodiscard]] TakeOutputs takeOutputs(const ManifestEntry& entry, const std::filesystem::path& outDir);

/// The suffix of every per-take report, ".report.json".
[[nodiscard]] const std::string& takeReportSuffix();

} // namespace mocap
