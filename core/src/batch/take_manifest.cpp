#include "mocap/batch/take_manifest.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <map>
#include <set>
#include <system_error>

namespace fs = std::filesystem;

namespace mocap {

namespace {

bool isTakeFile(const fs::path& path)
{
  const std::string extension = lowerExtension(path);
  return extension == "c3d" || extension == "trc";
}

/// Whether `path` is `folder` or lies below it (both absolute and lexically normal).
bool isWithin(const fs::path& path, const fs::path& folder)
{
  if (folder.empty())
    return false;
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

/// The canonical path of a folder, or empty when it cannot be resolved.
fs::path canonicalFolder(const fs::path& folder)
{
  std::error_code error;
  fs::path canonical = fs::canonical(folder, error);
  return error ? fs::path() : canonical;
}

/// Depth-first walk of one folder: take files are added, sub-folders entered once each (by
/// canonical path), so a symbolic link back to an ancestor or to a folder already seen is
/// reported instead of followed. Entries of a folder are visited in sorted order.
void scanFolder(const fs::path& folder, const fs::path& exclude, std::set<fs::path>& visited,
                std::vector<fs::path>& files, std::vector<std::string>& warnings)
{
  std::vector<fs::path> children;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    children.push_back(it->path());
  if (error)
    warnings.push_back(folder.string() + ": cannot be read (" + error.message() + "); skipped");
  std::sort(children.begin(), children.end());
  for (const fs::path& child : children) {
    if (isWithin(child, exclude))
      continue;
    std::error_code statusError;
    const fs::file_status status = fs::status(child, statusError);  // follows links
    if (fs::is_directory(status)) {
      const fs::path canonical = canonicalFolder(child);
      if (canonical.empty())
        continue;
      if (!visited.insert(canonical).second) {
        warnings.push_back(child.string() + ": a link to " + canonical.string() +
                           ", a folder already searched (a folder loop); not followed");
        continue;
      }
      scanFolder(child, exclude, visited, files, warnings);
    } else if (isTakeFile(child) && (fs::is_regular_file(status) || fs::is_symlink(fs::symlink_status(child)))) {
      files.push_back(child);  // a dangling link is kept: the batch reports it as unreadable
    }
  }
}

fs::path absoluteNormal(const fs::path& path)
{
  return fs::absolute(path).lexically_normal();
}

/// The deepest folder that holds every path.
fs::path commonRoot(const std::vector<ManifestEntry>& takes)
{
  fs::path root = takes.front().input.parent_path();
  for (const ManifestEntry& entry : takes) {
    const fs::path folder = entry.input.parent_path();
    fs::path common;
    auto a = root.begin();
    auto b = folder.begin();
    for (; a != root.end() && b != folder.end() && *a == *b; ++a, ++b)
      common /= *a;
    root = common;
  }
  return root;
}

std::vector<ManifestEntry> readTextManifest(const fs::path& source, std::vector<std::string>& warnings)
{
  const std::string text = readFileBytes(source);
  const fs::path base = absoluteNormal(source).parent_path();
  std::vector<ManifestEntry> takes;
  std::map<fs::path, std::size_t> firstLine;
  for (const auto& [lineNumber, line] : contentLines(text)) {
    const fs::path given(std::string{line});
    const fs::path input = (given.is_absolute() ? given : base / given).lexically_normal();
    const auto [it, inserted] = firstLine.emplace(input, lineNumber);
    if (!inserted) {
      warnings.push_back(source.string() + ":" + std::to_string(lineNumber) + ": repeats line " +
                         std::to_string(it->second) + " (" + std::string(line) + "); run once");
      continue;
    }
    ManifestEntry entry;
    entry.input = input;
    entry.line = lineNumber;
    takes.push_back(std::move(entry));
  }
  return takes;
}

} // namespace

TakeManifest readManifest(const fs::path& source, const fs::path& exclude)
{
  TakeManifest manifest;
  manifest.source = source;
  std::error_code error;
  const fs::file_status status = fs::status(source, error);
  if (!fs::exists(status))
    throw IoError(source.string() + ": no such manifest file or folder");
  if (fs::is_directory(status)) {
    const fs::path folder = absoluteNormal(source);
    std::set<fs::path> visited{canonicalFolder(folder)};
    std::vector<fs::path> files;
    scanFolder(folder, exclude.empty() ? fs::path() : absoluteNormal(exclude), visited, files, manifest.warnings);
    for (const fs::path& file : files) {
      ManifestEntry entry;
      entry.input = file.lexically_normal();
      manifest.takes.push_back(std::move(entry));
    }
    if (manifest.takes.empty())
      throw InvalidArgument(source.string() + ": no .c3d or .trc file in this folder or below");
    manifest.root = folder;
  } else {
    manifest.takes = readTextManifest(source, manifest.warnings);
    if (manifest.takes.empty())
      throw InvalidArgument(source.string() + ": the manifest names no take");
    manifest.root = commonRoot(manifest.takes);
  }
  for (ManifestEntry& entry : manifest.takes)
    entry.relative = entry.input.lexically_relative(manifest.root);
  return manifest;
}

const std::string& takeReportSuffix()
{
  static const std::string suffix = ".report.json";
  return suffix;
}

TakeOutputs takeOutputs(const ManifestEntry& entry, const fs::path& outDir)
{
  TakeOutputs outputs;
  outputs.take = outDir / entry.relative;
  outputs.report = outDir / (entry.relative.string() + takeReportSuffix());
  return outputs;
}

} // namespace mocap
