#include "mocap/batch/clean_preset.h"

#include "mocap/base/content_hash.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"
#include "mocap/base/number_text.h"

#include <cmath>
#include <algorithm>
#include <map>
#include <set>

namespace mocap {

namespace {

constexpr const char* kFormat = "mocap-clean-preset";
constexpr int kVersion = 1;

void writeSpikes(JsonWriter& json, const std::optional<SpikeOptions>& spikes)
{
  json.key("spikes").beginObject();
  json.key("method").value(spikes ? spikeMethodName(spikes->method) : "off");
  if (spikes) {
    json.key("factor").value(spikes->factor);
    json.key("threshold").value(spikes->threshold);
    json.key("noise_floor").value(spikes->noiseFloor);
    json.key("max_passes").value(spikes->maxPasses);
  }
  json.endObject();
}

void writeFill(JsonWriter& json, const std::optional<FillOptions>& fill)
{
  json.key("fill").beginObject();
  json.key("method").value(fill ? fillMethodName(fill->method) : "off");
  if (fill) {
    json.key("max_gap_frames").value(static_cast<std::int64_t>(fill->maxGap));
    json.key("max_gap_seconds").value(fill->maxGapSeconds);
    json.key("extrapolate").value(fill->extrapolate);
    json.key("min_valid_fraction").value(fill->minValidFraction);
    json.key("neighbours").value(fill->neighbours);
  }
  json.endObject();
}

void writeSmooth(JsonWriter& json, const std::optional<SmoothOptions>& smooth)
{
  json.key("smooth").beginObject();
  json.key("method").value(smooth ? smoothMethodName(smooth->method) : "off");
  if (smooth) {
    json.key("degree").value(smooth->degree);
    json.key("knot_spacing").value(smooth->knotSpacing);
    json.key("cutoff_hz").value(smooth->cutoffHz);
    json.key("winter_cutoff").value(smooth->winterCutoff);
    json.key("gcvspl_mode").value(smoothingSplineModeName(smooth->gcvsplMode));
    json.key("gcvspl_degree").value(smooth->gcvsplDegree);
    json.key("error_variance").value(smooth->errorVariance);
    json.key("savgol_window").value(smooth->savgolWindow);
    json.key("savgol_degree").value(smooth->savgolDegree);
  }
  json.endObject();
}

/// Reads the members of one preset object: each key is handed to its reader, and a key without
/// one is refused, so a misspelt option never passes silently.
class ObjectReader
{
public:
  ObjectReader(const JsonValue& value, std::string path) : m_path(std::move(path))
  {
    m_members = &value.object(where());
  }

  [[nodiscard]] std::string where(const std::string& key = {}) const
  {
    const std::string name = m_path.empty() ? key : (key.empty() ? m_path : m_path + "." + key);
    return name.empty() ? std::string("preset") : "preset " + name;
  }

  [[nodiscard]] const JsonValue* take(const std::string& key)
  {
    m_known.insert(key);
    const auto it = m_members->find(key);
    return it == m_members->end() ? nullptr : &it->second;
  }

  void number(const std::string& key, double& out, double min, double max)
  {
    if (const JsonValue* value = take(key)) {
      const double v = value->number(where(key));
      if (!std::isfinite(v) || v < min || v > max)
        throw InvalidArgument(where(key) + ": " + numberText(v) + " not in [" + numberText(min) + ", " +
                              numberText(max) + "]");
      out = v;
    }
  }

  template <typename Integer>
  void whole(const std::string& key, Integer& out, long long min, long long max)
  {
    double v = static_cast<double>(out);
    number(key, v, static_cast<double>(min), static_cast<double>(max));
    if (v != std::floor(v))
      throw InvalidArgument(where(key) + ": " + numberText(v) + " is not a whole number");
    out = static_cast<Integer>(v);
  }

  void flag(const std::string& key, bool& out)
  {
    if (const JsonValue* value = take(key))
      out = value->boolean(where(key));
  }

  /// The member's text parsed by `parse`, or an error listing `choices`.
  template <typename Parse>
  auto choice(const std::string& key, Parse parse, const std::string& choices) -> decltype(parse(""))
  {
    const JsonValue* value = take(key);
    if (value == nullptr)
      return std::nullopt;
    const std::string& text = value->string(where(key));
    auto parsed = parse(text);
    if (!parsed)
      throw InvalidArgument(where(key) + ": unknown value '" + text + "' (expected " + choices + ")");
    return parsed;
  }

  /// Refuses every key no reader asked for.
  void finish() const
  {
    for (const auto& [key, value] : *m_members)
      if (m_known.count(key) == 0)
        throw InvalidArgument(where() + ": unknown key '" + key + "'");
  }

  static std::string numberText(double v)
  {
    std::string text;
    appendNumber(text, v);
    return text;
  }

private:
  std::string m_path;
  const std::map<std::string, JsonValue>* m_members = nullptr;
  std::set<std::string> m_known;
};

/// "off", or the step's method; `method` is set from the "method" key when it names one.
template <typename Options, typename Parse>
bool stepIsOn(ObjectReader& step, Options& options, Parse parse, const std::string& choices)
{
  const JsonValue* method = step.take("method");
  if (method != nullptr && method->string(step.where("method")) == "off") {
    step.finish();  // nothing else belongs to a step that does not run
    return false;
  }
  if (const auto parsed = step.choice("method", parse, choices + "|off"))
    options.method = *parsed;
  return true;
}

std::optional<SpikeOptions> readSpikes(const JsonValue& value)
{
  ObjectReader step(value, "spikes");
  SpikeOptions options;
  if (!stepIsOn(step, options, parseSpikeMethod, spikeMethodNames()))
    return std::nullopt;
  step.number("factor", options.factor, 1e-6, 1e6);
  step.number("threshold", options.threshold, 1e-6, 1e6);
  step.number("noise_floor", options.noiseFloor, 0.0, 1e6);
  step.whole("max_passes", options.maxPasses, 1, 100);
  step.finish();
  return options;
}

std::string fillMethodChoices()
{
  std::string names;
  for (const FillMethod method : allFillMethods())
    names += (names.empty() ? "" : "|") + std::string(fillMethodName(method));
  return names;
}

std::optional<FillOptions> readFill(const JsonValue& value)
{
  ObjectReader step(value, "fill");
  FillOptions options;
  if (!stepIsOn(step, options, parseFillMethod, fillMethodChoices()))
    return std::nullopt;
  step.whole("max_gap_frames", options.maxGap, 0, 1LL << 40);
  step.number("max_gap_seconds", options.maxGapSeconds, 0.0, 1e9);
  step.flag("extrapolate", options.extrapolate);
  step.number("min_valid_fraction", options.minValidFraction, 0.0, 1.0);
  step.whole("neighbours", options.neighbours, 1, 1000);
  step.finish();
  return options;
}

std::optional<SmoothOptions> readSmooth(const JsonValue& value)
{
  ObjectReader step(value, "smooth");
  SmoothOptions options;
  if (!stepIsOn(step, options, parseSmoothMethod, smoothMethodNames()))
    return std::nullopt;
  step.whole("degree", options.degree, 2, 7);
  step.number("knot_spacing", options.knotSpacing, 1.0, 1e6);
  step.number("cutoff_hz", options.cutoffHz, 1e-6, 1e6);
  step.flag("winter_cutoff", options.winterCutoff);
  if (const auto mode = step.choice("gcvspl_mode", parseSmoothingSplineMode, "gcv|variance|cutoff"))
    options.gcvsplMode = *mode;
  step.whole("gcvspl_degree", options.gcvsplDegree, 3, 5);
  if (options.gcvsplDegree == 4)
    throw InvalidArgument(step.where("gcvspl_degree") + ": 4 is not 3 or 5");
  step.number("error_variance", options.errorVariance, 0.0, 1e12);
  step.whole("savgol_window", options.savgolWindow, 3, 1001);
  if (options.savgolWindow % 2 == 0)
    throw InvalidArgument(step.where("savgol_window") + ": " + std::to_string(options.savgolWindow) +
                          " is not odd");
  step.whole("savgol_degree", options.savgolDegree, 0, std::min(options.savgolWindow - 1, 10));
  step.finish();
  return options;
}

} // namespace

std::string cleanPresetJson(const CleanOptions& options)
{
  JsonWriter json;
  writeCleanPreset(json, options);
  return json.str() + "\n";
}

void writeCleanPreset(JsonWriter& json, const CleanOptions& options)
{
  json.beginObject();
  json.key("format").value(kFormat);
  json.key("version").value(kVersion);
  json.key("stabilize").beginObject();
  json.key("markers").beginArray();
  for (const std::string& label : options.stabilizeLabels)
    json.value(label);
  json.endArray();
  json.key("keep_stabilized").value(options.keepStabilized);
  json.endObject();
  writeSpikes(json, options.spikes);
  writeFill(json, options.fill);
  writeSmooth(json, options.smooth);
  json.endObject();
}

CleanOptions parseCleanPreset(std::string_view text, const std::string& sourceName)
{
  return cleanPresetFromJson(parseJson(text, sourceName));
}

CleanOptions cleanPresetFromJson(const JsonValue& document)
{
  ObjectReader top(document, "");
  if (const JsonValue* format = top.take("format"); format && format->string(top.where("format")) != kFormat)
    throw InvalidArgument(top.where("format") + ": '" + format->string("") + "' is not " + kFormat);
  int version = kVersion;
  top.whole("version", version, 1, 1000);
  if (version != kVersion)
    throw InvalidArgument(top.where("version") + ": " + std::to_string(version) + " is newer than this program (" +
                          std::to_string(kVersion) + ")");
  CleanOptions options;
  if (const JsonValue* stabilize = top.take("stabilize")) {
    ObjectReader step(*stabilize, "stabilize");
    if (const JsonValue* markers = step.take("markers"))
      for (const JsonValue& label : markers->array(step.where("markers"))) {
        const std::string& name = label.string(step.where("markers") + " entry");
        if (name.empty())
          throw InvalidArgument(step.where("markers") + ": an empty label");
        options.stabilizeLabels.push_back(name);
      }
    step.flag("keep_stabilized", options.keepStabilized);
    step.finish();
  }
  if (const JsonValue* spikes = top.take("spikes"))
    options.spikes = readSpikes(*spikes);
  if (const JsonValue* fill = top.take("fill"))
    options.fill = readFill(*fill);
  if (const JsonValue* smooth = top.take("smooth"))
    options.smooth = readSmooth(*smooth);
  top.finish();
  return options;
}

CleanOptions readCleanPreset(const std::string& path)
{
  const std::string text = readFileBytes(path);
  try {
    return parseCleanPreset(text, path);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(path + ": " + e.what());
  }
}

std::string cleanPresetHash(const CleanOptions& options)
{
  return hashText(contentHash(cleanPresetJson(options)));
}

} // namespace mocap
