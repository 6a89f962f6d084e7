#include "mocap/video/reference_video_sidecar.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <cmath>

namespace mocap {

namespace {

constexpr const char* kFormat = "mocap reference videos";
constexpr int kVersion = 1;

std::filesystem::path absoluteOf(const std::filesystem::path& path)
{
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return (error ? path : absolute).lexically_normal();
}

bool isFile(const std::filesystem::path& path)
{
  std::error_code error;
  return !path.empty() && std::filesystem::is_regular_file(path, error);
}

/// One entry of "videos"; `sidecar` names the file in errors.
ReferenceVideoLink readLink(const JsonValue& entry, const std::filesystem::path& folder, const std::string& sidecar)
{
  ReferenceVideoLink link;
  if (const JsonValue* relative = entry.find("path", sidecar); relative && !relative->isNull())
    link.relative = std::filesystem::path(relative->string(sidecar + ": path")).lexically_normal();
  if (const JsonValue* absolute = entry.find("absolute_path", sidecar); absolute && !absolute->isNull())
    link.path = std::filesystem::path(absolute->string(sidecar + ": absolute_path")).lexically_normal();
  if (link.relative.empty() && link.path.empty())
    throw FormatError(sidecar, "a video without a path");
  if (const JsonValue* offset = entry.find("offset", sidecar)) {
    link.offset = offset->number(sidecar + ": offset");
    if (!std::isfinite(link.offset))
      throw FormatError(sidecar, "a video's offset is not a finite number");
  }
  // The relative path first: a folder moved with its take and videos keeps them.
  const std::filesystem::path besideTake = link.relative.empty() ? std::filesystem::path() : (folder / link.relative).lexically_normal();
  if (isFile(besideTake)) {
    link.path = besideTake;
  } else if (!isFile(link.path)) {
    link.found = false;
    if (link.path.empty())
      link.path = besideTake;
  }
  return link;
}

} // namespace

std::filesystem::path referenceVideoSidecarPath(const std::filesystem::path& take)
{
  std::filesystem::path sidecar = take;
  sidecar += ".video.json";
  return sidecar;
}

ReferenceVideoLink linkReferenceVideo(const std::filesystem::path& video, const std::filesystem::path& take, double offset)
{
  ReferenceVideoLink link;
  link.path = absoluteOf(video);
  link.relative = link.path.lexically_relative(absoluteOf(take).parent_path());
  link.offset = offset;
  link.found = isFile(link.path);
  return link;
}

std::vector<ReferenceVideoLink> readReferenceVideoSidecar(const std::filesystem::path& take)
{
  const std::filesystem::path path = referenceVideoSidecarPath(take);
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    return {};
  const std::string name = path.string();
  const std::filesystem::path folder = absoluteOf(take).parent_path();
  std::vector<ReferenceVideoLink> links;
  try {
    const JsonValue root = parseJson(readFileBytes(path), name);
    const JsonValue* format = root.find("format", name);
    if (!format || format->string(name + ": format") != kFormat)
      throw FormatError(name, std::string("not a reference video sidecar (\"format\" is not \"") + kFormat + "\")");
    const JsonValue* version = root.find("version", name);
    if (!version || version->number(name + ": version") != kVersion)
      throw FormatError(name, "a sidecar version this build does not read (it reads version 1)");
    const JsonValue* videos = root.find("videos", name);
    if (!videos)
      throw FormatError(name, "no \"videos\" list");
    for (const JsonValue& entry : videos->array(name + ": videos"))
      links.push_back(readLink(entry, folder, name));
  } catch (const InvalidArgument& e) {  // a value of the wrong type
    throw FormatError(name, e.what());
  }
  return links;
}

void writeReferenceVideoSidecar(const std::filesystem::path& take, const std::vector<ReferenceVideoLink>& links)
{
  const std::filesystem::path path = referenceVideoSidecarPath(take);
  if (links.empty()) {
    std::error_code error;
    std::filesystem::remove(path, error);
    if (error)
      throw IoError(path.string() + ": cannot remove: " + error.message());
    return;
  }
  JsonWriter json;
  json.beginObject().key("format").value(kFormat).key("version").value(kVersion).key("videos").beginArray();
  for (const ReferenceVideoLink& link : links) {
    json.beginObject().key("path");
    if (link.relative.empty())
      json.null();
    else
      json.value(link.relative.generic_string());
    json.key("absolute_path").value(link.path.generic_string()).key("offset").value(link.offset).endObject();
  }
  json.endArray().endObject();
  writeFileAtomically(path, json.str() + "\n");
}

} // namespace mocap
