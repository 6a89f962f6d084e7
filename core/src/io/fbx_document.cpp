#include "mocap/io/fbx_document.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"

#include <array>
#include <cmath>
#include <cstring>

namespace mocap {

namespace {

constexpr EnumTable<FbxUpAxis, 4> kUpAxes{{{
    {FbxUpAxis::Y, "y"},
    {FbxUpAxis::Z, "z"},
    {FbxUpAxis::Y, "Y"},
    {FbxUpAxis::Z, "Z"},
}}};

constexpr std::string_view kTakeName = "Take 001";
constexpr std::int32_t kCurveKeyVersion = 4008;
// KeyAttrFlags bits of the FBX SDK's key attributes.
constexpr std::int32_t kKeyConstant = 0x00000002;
constexpr std::int32_t kKeyLinear = 0x00000004;
// KeyAttrDataFloat's third value: both tangent weights at their default 1/3 (0x0D05 each) packed
// into one float's bits; readers ignore it for linear and constant keys.
constexpr std::uint32_t kDefaultTangentWeights = 0x0D050D05;

// The FBX SDK checks a file's id against its creation time; this pair is one it accepts, so every
// file carries it (and the same input gives the same bytes).
constexpr unsigned char kFileId[16] = {0x28, 0xb3, 0x2a, 0xeb, 0xb6, 0x24, 0xcc, 0xc2,
                                       0xbf, 0xc8, 0xb0, 0x2a, 0xa9, 0x2b, 0xfc, 0xf1};
constexpr std::string_view kCreationTime = "1970-01-01 10:00:00:000";
constexpr std::string_view kCreator = "Mocap Studio";

// FBX's TimeMode enum for the standard rates; 14 (custom) uses CustomFrameRate.
std::int32_t timeMode(double rate)
{
  constexpr std::array<std::pair<double, std::int32_t>, 13> kModes{{
      {120.0, 1}, {100.0, 2}, {60.0, 3}, {50.0, 4}, {48.0, 5}, {30.0, 6}, {30.0 / 1.001, 9},
      {25.0, 10}, {24.0, 11}, {24.0 / 1.001, 13}, {96.0, 15}, {72.0, 16}, {60.0 / 1.001, 17},
  }};
  for (const auto& [modeRate, mode] : kModes)
    if (std::abs(rate - modeRate) < 1e-9 * modeRate)
      return mode;
  return 14;
}

// UnitScaleFactor: centimetres per unit of the file's coordinates.
double centimetresPer(LengthUnit unit)
{
  return millimetresPer(unit) / 10.0;
}

std::string nameClass(std::string_view name, std::string_view className)
{
  std::string text(name);
  text += std::string_view("\0\1", 2);
  text += className;
  return text;
}

FbxNode headerExtension()
{
  FbxNode header("FBXHeaderExtension");
  header.child("FBXHeaderVersion").addInt32(1003);
  header.child("FBXVersion").addInt32(static_cast<std::int32_t>(kFbxVersion));
  FbxNode& stamp = header.child("CreationTimeStamp");
  stamp.child("Version").addInt32(1000);
  for (const auto& [field, value] : std::array<std::pair<const char*, std::int32_t>, 7>{
           {{"Year", 1970}, {"Month", 1}, {"Day", 1}, {"Hour", 10}, {"Minute", 0}, {"Second", 0}, {"Millisecond", 0}}})
    stamp.child(field).addInt32(value);
  header.child("Creator").addString(kCreator);
  return header;
}

void addIntProperty(FbxNode& properties, std::string_view name, std::int32_t value)
{
  addFbxProperty(properties, name, "int", "Integer", "").addInt32(value);
}

void addTimeProperty(FbxNode& properties, std::string_view name, std::int64_t ticks)
{
  addFbxProperty(properties, name, "KTime", "Time", "").addInt64(ticks);
}

// Up, front and side axes with their signs, right-handed: Y-up faces +Z with +X to the side (as
// Maya writes it), Z-up faces −Y with +X to the side (as Blender and 3ds Max do).
FbxNode globalSettings(const FbxSceneSettings& settings, std::int64_t startTicks, std::int64_t stopTicks)
{
  FbxNode global("GlobalSettings");
  global.child("Version").addInt32(1000);
  FbxNode& p = global.child("Properties70");
  const bool yUp = settings.up == FbxUpAxis::Y;
  addIntProperty(p, "UpAxis", yUp ? 1 : 2);
  addIntProperty(p, "UpAxisSign", 1);
  addIntProperty(p, "FrontAxis", yUp ? 2 : 1);
  addIntProperty(p, "FrontAxisSign", yUp ? 1 : -1);
  addIntProperty(p, "CoordAxis", 0);
  addIntProperty(p, "CoordAxisSign", 1);
  addIntProperty(p, "OriginalUpAxis", yUp ? 1 : 2);
  addIntProperty(p, "OriginalUpAxisSign", 1);
  addFbxProperty(p, "UnitScaleFactor", "double", "Number", "").addDouble(centimetresPer(settings.unit));
  addFbxProperty(p, "OriginalUnitScaleFactor", "double", "Number", "").addDouble(centimetresPer(settings.unit));
  addFbxProperty(p, "DefaultCamera", "KString", "", "").addString("Producer Perspective");
  addFbxProperty(p, "TimeMode", "enum", "", "").addInt32(timeMode(settings.frameRate));
  addFbxProperty(p, "TimeProtocol", "enum", "", "").addInt32(2);
  addFbxProperty(p, "SnapOnFrameMode", "enum", "", "").addInt32(0);
  addTimeProperty(p, "TimeSpanStart", startTicks);
  addTimeProperty(p, "TimeSpanStop", stopTicks);
  addFbxProperty(p, "CustomFrameRate", "double", "Number", "").addDouble(settings.frameRate);
  return global;
}

FbxNode documents()
{
  FbxNode docs("Documents");
  docs.child("Count").addInt32(1);
  FbxNode& doc = docs.child("Document");
  doc.addInt64(1LL << 40).addString(nameClass("Scene", "Document")).addString("Scene");
  FbxNode& p = doc.child("Properties70");
  addFbxProperty(p, "SourceObject", "object", "", "");
  addFbxProperty(p, "ActiveAnimStackName", "KString", "", "").addString(kTakeName);
  doc.child("RootNode").addInt64(0);
  return docs;
}

FbxNode definitions(const std::map<std::string, int, std::less<>>& counts)
{
  FbxNode defs("Definitions");
  defs.child("Version").addInt32(100);
  int total = 1;
  for (const auto& entry : counts)
    total += entry.second;
  defs.child("Count").addInt32(total);
  defs.child("ObjectType").addString("GlobalSettings").child("Count").addInt32(1);
  for (const auto& [kind, count] : counts)
    defs.child("ObjectType").addString(kind).child("Count").addInt32(count);
  return defs;
}

FbxNode takes(std::int64_t startTicks, std::int64_t stopTicks)
{
  FbxNode all("Takes");
  all.child("Current").addString(kTakeName);
  FbxNode& take = all.child("Take");
  take.addString(kTakeName);
  take.child("FileName").addString("Take_001.tak");
  take.child("LocalTime").addInt64(startTicks).addInt64(stopTicks);
  take.child("ReferenceTime").addInt64(startTicks).addInt64(stopTicks);
  return all;
}

void addCurve(FbxNode& curve, const std::vector<std::int64_t>& times, const std::vector<float>& values,
              FbxInterpolation interpolation)
{
  curve.child("Default").addDouble(values.empty() ? 0.0 : static_cast<double>(values.front()));
  curve.child("KeyVer").addInt32(kCurveKeyVersion);
  curve.child("KeyTime").addInt64s(times);
  curve.child("KeyValueFloat").addFloats(values);
  curve.child("KeyAttrFlags").addInt32s({interpolation == FbxInterpolation::Linear ? kKeyLinear : kKeyConstant});
  float weights = 0.0F;
  static_assert(sizeof(weights) == sizeof(kDefaultTangentWeights));
  std::memcpy(&weights, &kDefaultTangentWeights, sizeof(weights));
  curve.child("KeyAttrDataFloat").addFloats({0.0F, 0.0F, weights, 0.0F});
  curve.child("KeyAttrRefCount").addInt32s({static_cast<std::int32_t>(values.size())});
}

} // namespace

std::string_view fbxUpAxisName(FbxUpAxis axis)
{
  return kUpAxes.name(axis, "?");
}

std::optional<FbxUpAxis> parseFbxUpAxis(std::string_view text)
{
  return kUpAxes.parse(text);
}

FbxNode& addFbxProperty(FbxNode& properties, std::string_view name, std::string_view type, std::string_view label,
                        std::string_view flags)
{
  return properties.child("P").addString(name).addString(type).addString(label).addString(flags);
}

FbxDocument::FbxDocument(const FbxSceneSettings& settings) : m_settings(settings)
{
  if (!(settings.frameRate > 0.0) || !std::isfinite(settings.frameRate))
    throw InvalidArgument("FBX: the frame rate must be positive");
  if (settings.frameCount < 0)
    throw InvalidArgument("FBX: a negative frame count");
  if (!(settings.startSeconds >= 0.0) || !(settings.startSeconds < 1e6))
    throw InvalidArgument("FBX: the start time must be within 0 … 10⁶ s");
  const double ticksPerFrame = static_cast<double>(kFbxTicksPerSecond) / settings.frameRate;
  m_startTicks = std::llround(settings.startSeconds * static_cast<double>(kFbxTicksPerSecond));
  m_keyTimes.reserve(static_cast<std::size_t>(settings.frameCount));
  for (Eigen::Index f = 0; f < settings.frameCount; ++f)
    m_keyTimes.push_back(m_startTicks + std::llround(static_cast<double>(f) * ticksPerFrame));

  const Object stack = addObject("AnimationStack", kTakeName, "AnimStack", "");
  FbxNode& p = stack.node->child("Properties70");
  const std::int64_t stop = m_keyTimes.empty() ? m_startTicks : m_keyTimes.back();
  for (const char* name : {"LocalStart", "ReferenceStart"})
    addTimeProperty(p, name, m_startTicks);
  for (const char* name : {"LocalStop", "ReferenceStop"})
    addTimeProperty(p, name, stop);
  // A layer with a (here empty) property table: readers such as assimp need every object to have
  // a scope of children.
  const Object layer = addObject("AnimationLayer", "BaseLayer", "AnimLayer", "");
  layer.node->child("Properties70");
  m_layer = layer.id;
  connect(m_layer, stack.id);
}

FbxDocument::Object FbxDocument::addObject(std::string_view kind, std::string_view name, std::string_view className,
                                           std::string_view subtype)
{
  FbxNode& node = m_objects.child(std::string(kind));
  const std::int64_t id = m_nextId++;
  node.addInt64(id).addString(nameClass(name, className)).addString(subtype);
  const auto count = m_counts.find(kind);
  if (count == m_counts.end())
    m_counts.emplace(std::string(kind), 1);
  else
    ++count->second;
  return {id, &node};
}

void FbxDocument::connect(std::int64_t child, std::int64_t parent)
{
  m_connections.child("C").addString("OO").addInt64(child).addInt64(parent);
}

void FbxDocument::connectProperty(std::int64_t child, std::int64_t parent, std::string_view property)
{
  m_connections.child("C").addString("OP").addInt64(child).addInt64(parent).addString(property);
}

namespace {

/// The keys of one curve: every frame's time and value, or only those of `frames`.
void keysOf(const std::vector<std::int64_t>& frameTimes, const std::vector<float>& frameValues,
            const std::vector<Eigen::Index>* frames, std::vector<std::int64_t>& times, std::vector<float>& values)
{
  if (!frames) {
    times = frameTimes;
    values = frameValues;
    return;
  }
  times.clear();
  values.clear();
  Eigen::Index previous = -1;
  for (const Eigen::Index f : *frames) {
    if (f <= previous || f >= static_cast<Eigen::Index>(frameTimes.size()))
      throw InvalidArgument("FBX: key frame " + std::to_string(f) + " out of order or past the last frame");
    times.push_back(frameTimes[static_cast<std::size_t>(f)]);
    values.push_back(frameValues[static_cast<std::size_t>(f)]);
    previous = f;
  }
}

} // namespace

void FbxDocument::animate(std::int64_t target, std::string_view property, std::string_view nodeName,
                          const std::vector<std::string>& channels, const std::vector<std::vector<float>>& values,
                          FbxInterpolation interpolation, const std::vector<std::vector<Eigen::Index>>* keyFrames)
{
  if (channels.size() != values.size() || (keyFrames && keyFrames->size() != channels.size()))
    throw InvalidArgument("FBX: " + std::to_string(values.size()) + " curves for " + std::to_string(channels.size()) +
                          " channels");
  const Object curveNode = addObject("AnimationCurveNode", nodeName, "AnimCurveNode", "");
  FbxNode& p = curveNode.node->child("Properties70");
  connect(curveNode.id, m_layer);
  connectProperty(curveNode.id, target, property);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    if (values[c].size() != m_keyTimes.size())
      throw InvalidArgument("FBX: " + std::to_string(values[c].size()) + " keys for " +
                            std::to_string(m_keyTimes.size()) + " frames");
    addFbxProperty(p, channels[c], "Number", "", "A")
        .addDouble(values[c].empty() ? 0.0 : static_cast<double>(values[c].front()));
    const Object curve = addObject("AnimationCurve", "", "AnimCurve", "");
    std::vector<std::int64_t> times;
    std::vector<float> keyValues;
    keysOf(m_keyTimes, values[c], keyFrames ? &(*keyFrames)[c] : nullptr, times, keyValues);
    addCurve(*curve.node, times, keyValues, interpolation);
    connectProperty(curve.id, curveNode.id, channels[c]);
  }
}

std::string FbxDocument::bytes() const
{
  const std::int64_t stop = m_keyTimes.empty() ? m_startTicks : m_keyTimes.back();
  const FbxNode header = headerExtension();
  FbxNode fileId("FileId");
  fileId.addRaw(std::string_view(reinterpret_cast<const char*>(kFileId), sizeof(kFileId)));
  FbxNode creationTime("CreationTime");
  creationTime.addString(kCreationTime);
  FbxNode creator("Creator");
  creator.addString(kCreator);
  const FbxNode global = globalSettings(m_settings, m_startTicks, stop);
  const FbxNode docs = documents();
  const FbxNode references("References");
  const FbxNode defs = definitions(m_counts);
  const FbxNode takeList = takes(m_startTicks, stop);
  const std::vector<const FbxNode*> top{&header, &fileId,      &creationTime, &creator,       &global,   &docs,
                                        &references, &defs, &m_objects,    &m_connections, &takeList};
  return fbxBinary(top);
}

} // namespace mocap
