#include "mocap/model/provenance.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace mocap {

namespace {

constexpr const char* kGroup = "PROCESSING";
constexpr const char* kHeadMarkers = "HEAD_MARKERS";
constexpr const char* kGroupDescription = "Mocap Studio: sample states and processing history";
constexpr const char* kFormat = "mocap-studio provenance";
constexpr int kVersion = 2;
constexpr std::size_t kRunsPerParameter = 255;   // a C3D dimension is one byte
constexpr std::size_t kPieceBytes = 255;
constexpr std::size_t kPiecesPerParameter = 120;  // 30 600 bytes: under a record's 32 KB

/// The state a version-1 file's single state stood for (1 filled, 2 smoothed, 3 edited), or
/// nullopt for another code.
std::optional<SampleState> versionOneState(int code)
{
  switch (code) {
  case 1: return SampleOrigin::Filled;
  case 2: return SampleState().with(SampleOperation::Smoothed);
  case 3: return SampleOrigin::Edited;
  default: return std::nullopt;
  }
}

/// The state a version-2 STATE_RUNS code stands for (its bits), or nullopt for a code that is
/// not one (untouched samples have no runs).
std::optional<SampleState> versionTwoState(double code)
{
  if (!(code >= 1.0 && code <= 255.0) || code != std::floor(code))
    return std::nullopt;
  const auto bits = static_cast<std::uint8_t>(code);
  const SampleState state = SampleState::fromBits(bits);
  return state.bits() == bits ? std::optional<SampleState>(state) : std::nullopt;
}

/// A sidecar run's state: version 1 [first, length, state] or version 2 [first, length, origin,
/// [operation, …]]; nullopt when it names something else.
std::optional<SampleState> sidecarRunState(const std::vector<JsonValue>& run)
{
  if (run.size() == 3 && run[2].isString()) {
    const std::string name = run[2].string("state");
    return name == "filled" ? versionOneState(1) : name == "smoothed" ? versionOneState(2)
                                                 : name == "edited"   ? versionOneState(3)
                                                                      : std::nullopt;
  }
  if (run.size() != 4 || !run[2].isString())
    return std::nullopt;
  const std::optional<SampleOrigin> origin = parseSampleOrigin(run[2].string("origin"));
  if (!origin)
    return std::nullopt;
  SampleState state = *origin;
  for (const JsonValue& name : run[3].array("operations")) {
    const std::optional<SampleOperation> operation =
        name.isString() ? parseSampleOperation(name.string("operation")) : std::nullopt;
    if (!operation)
      return std::nullopt;
    state = state.with(*operation);
  }
  return state;
}

void warn(std::vector<std::string>* warnings, std::string message)
{
  if (warnings)
    warnings->push_back(std::move(message));
}

/// Sets the states of a run, after checking that it lies inside the take.
bool applyRun(Take& take, const StateRun& run)
{
  if (run.marker < 0 || run.marker >= take.markerCount() || run.first < 0 || run.length <= 0 ||
      run.first + run.length > take.frameCount() || run.state.untouched())
    return false;
  for (Eigen::Index f = run.first; f < run.first + run.length; ++f)
    take.setState(f, run.marker, run.state);
  return true;
}

std::string historyText(const std::vector<ProcessingStep>& history)
{
  JsonWriter json(0);
  writeHistoryJson(json, history);
  return json.str();
}

std::vector<ProcessingStep> readHistory(const JsonValue& list)
{
  std::vector<ProcessingStep> history;
  for (const JsonValue& item : list.array("the history")) {
    ProcessingStep step;
    step.operation = item.find("operation", "a history step") ? item.find("operation", "")->string("operation") : "";
    if (const JsonValue* parameters = item.find("parameters", "a history step"))
      for (const auto& [name, value] : parameters->object("parameters"))
        step.parameters.emplace_back(name, value.string("parameter " + name));
    if (const JsonValue* markers = item.find("markers", "a history step"))
      for (const JsonValue& label : markers->array("markers"))
        step.markers.push_back(label.string("a marker label"));
    if (const JsonValue* first = item.find("first_frame", "a history step"))
      step.firstFrame = static_cast<std::int64_t>(first->number("first_frame"));
    if (const JsonValue* last = item.find("last_frame", "a history step"))
      step.lastFrame = static_cast<std::int64_t>(last->number("last_frame"));
    if (const JsonValue* samples = item.find("samples", "a history step"))
      step.samples = static_cast<std::int64_t>(samples->number("samples"));
    if (const JsonValue* time = item.find("time", "a history step"))
      step.time = time->string("time");
    if (const JsonValue* tool = item.find("tool", "a history step"))
      step.tool = tool->string("tool");
    history.push_back(std::move(step));
  }
  return history;
}

/// Parameters `base`, `base2`, `base3`… of `group`, in order.
std::vector<const C3dParameter*> parameterParts(const C3dGroup& group, const std::string& base)
{
  std::vector<const C3dParameter*> parts;
  for (int part = 1;; ++part) {
    const C3dParameter* p = group.find(part == 1 ? base : base + std::to_string(part));
    if (!p)
      return parts;
    parts.push_back(p);
  }
}

/// Marks valid samples with residual exactly 0 as Filled when the file's residuals are real
/// (some above 0 and fewer than half at 0); returns how many were marked.
Eigen::Index markZeroResidualsFilled(Take& take, std::optional<ResidualCounts> counts)
{
  const auto valid = take.valid();
  const auto residuals = take.residuals();
  if (!counts)
    counts = ResidualCounts{(valid.array() && residuals.array() == 0.0).count(), valid.count()};
  const Eigen::Index zero = counts->zero;
  const Eigen::Index positive = counts->valid - zero;
  if (zero == 0 || positive == 0 || zero * 2 >= zero + positive)
    return 0;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f)
      if (valid(f, m) && residuals(f, m) == 0.0)
        take.setState(f, m, SampleOrigin::Filled);
  return zero;
}

/// Sets the take's head markers to `labels`, skipping (with a warning) those the take lacks.
void restoreHeadMarkers(Take& take, const std::vector<std::string>& labels, const std::string& sourceName,
                        std::vector<std::string>* warnings)
{
  std::vector<std::string> kept;
  std::string missing;
  for (const std::string& label : labels) {
    if (take.markerIndex(label))
      kept.push_back(label);
    else
      missing += (missing.empty() ? "" : ", ") + label;
  }
  setHeadMarkers(take, kept);
  if (!missing.empty())
    warn(warnings, sourceName + ": head marker(s) " + missing + " not in this take; left out of its head markers");
}

/// The group's VERSION (1 when absent, as the first writers always wrote 1).
int groupVersion(const C3dGroup& group)
{
  const C3dParameter* version = group.find("VERSION");
  return version && version->number() ? static_cast<int>(*version->number()) : 1;
}

void loadProcessingGroup(Take& take, const C3dGroup& group, std::vector<std::string>* warnings)
{
  const int version = groupVersion(group);
  const bool knownVersion = version == 1 || version == kVersion;
  if (!knownVersion)
    warn(warnings, "PROCESSING: VERSION " + std::to_string(version) + " is not one this reader knows (1, " +
                       std::to_string(kVersion) + "); sample states not restored");
  const C3dParameter* labelsParameter = group.find("LABELS");
  const std::vector<std::string> labels = labelsParameter ? labelsParameter->strings() : std::vector<std::string>{};
  std::vector<std::optional<Eigen::Index>> markerOf;
  for (const std::string& label : labels)
    markerOf.push_back(take.markerIndex(label));
  Eigen::Index skipped = 0;
  const auto parts = knownVersion ? parameterParts(group, "STATE_RUNS") : std::vector<const C3dParameter*>{};
  for (const C3dParameter* part : parts) {
    const std::size_t runs = part->numbers.size() / 4;
    for (std::size_t r = 0; r < runs; ++r) {
      const double* v = &part->numbers[4 * r];
      const auto index = static_cast<std::size_t>(std::max(0.0, v[0]));
      const std::optional<SampleState> state =
          version == 1 ? versionOneState(static_cast<int>(v[3])) : versionTwoState(v[3]);
      const bool known = index < markerOf.size() && markerOf[index] && state;
      const bool applied = known && applyRun(take, {*markerOf[index], static_cast<Eigen::Index>(v[1]),
                                                    static_cast<Eigen::Index>(v[2]), *state});
      skipped += applied ? 0 : 1;
    }
  }
  if (skipped > 0)
    warn(warnings, "PROCESSING: " + std::to_string(skipped) +
                       " sample-state run(s) name markers or frames this take does not have, or a state this "
                       "reader does not know; skipped");
  std::string text;
  for (const C3dParameter* part : parameterParts(group, "HISTORY"))
    text += part->chars;
  const C3dParameter* bytes = group.find("HISTORY_BYTES");
  if (bytes && bytes->number() && *bytes->number() >= 0 && *bytes->number() <= static_cast<double>(text.size()))
    text.resize(static_cast<std::size_t>(*bytes->number()));
  if (!text.empty())
    take.history() = readHistory(parseJson(text, "PROCESSING:HISTORY"));
  if (const C3dParameter* head = group.find(kHeadMarkers))
    restoreHeadMarkers(take, head->strings(), "PROCESSING:HEAD_MARKERS", warnings);
}

} // namespace

namespace {

constexpr EnumTable<SampleOrigin, 3> kSampleOrigins{{{
    {SampleOrigin::Measured, "measured"},
    {SampleOrigin::Filled, "filled"},
    {SampleOrigin::Edited, "edited"},
}}};

constexpr EnumTable<SampleOperation, 2> kSampleOperationNames{{{
    {SampleOperation::Smoothed, "smoothed"},
    {SampleOperation::Stabilized, "stabilized"},
}}};

} // namespace

std::string_view sampleOriginName(SampleOrigin origin)
{
  return kSampleOrigins.name(origin, "measured");
}

std::string_view sampleOperationName(SampleOperation operation)
{
  return kSampleOperationNames.name(operation, "");
}

std::optional<SampleOrigin> parseSampleOrigin(std::string_view name)
{
  return kSampleOrigins.parse(name);
}

std::optional<SampleOperation> parseSampleOperation(std::string_view name)
{
  return kSampleOperationNames.parse(name);
}

std::vector<StateRun> stateRuns(const Take& take)
{
  std::vector<StateRun> runs;
  const auto states = take.states();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    for (Eigen::Index f = 0; f < take.frameCount();) {
      const auto state = states(f, m);
      Eigen::Index end = f + 1;
      while (end < take.frameCount() && states(end, m) == state)
        ++end;
      if (state != 0)
        runs.push_back({m, f, end - f, SampleState::fromBits(state)});
      f = end;
    }
  }
  return runs;
}

StateCounts& StateCounts::operator+=(const StateCounts& other)
{
  measured += other.measured;
  filled += other.filled;
  edited += other.edited;
  smoothed += other.smoothed;
  stabilized += other.stabilized;
  smoothedMeasured += other.smoothedMeasured;
  return *this;
}

std::vector<StateCounts> stateCounts(const Take& take)
{
  std::vector<StateCounts> counts(static_cast<std::size_t>(take.markerCount()));
  const auto valid = take.valid();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    counts[static_cast<std::size_t>(m)].measured = valid.col(m).count();
  for (const StateRun& run : stateRuns(take)) {
    StateCounts& c = counts[static_cast<std::size_t>(run.marker)];
    const SampleOrigin origin = run.state.origin();
    if (origin != SampleOrigin::Measured) {
      // Made samples were counted as measured when valid (a deleted one is edited and invalid).
      c.measured -= valid.col(run.marker).segment(run.first, run.length).count();
      (origin == SampleOrigin::Filled ? c.filled : c.edited) += run.length;
    }
    const bool smoothed = run.state.has(SampleOperation::Smoothed);
    c.smoothed += smoothed ? run.length : 0;
    c.smoothedMeasured += smoothed && origin == SampleOrigin::Measured ? run.length : 0;
    c.stabilized += run.state.has(SampleOperation::Stabilized) ? run.length : 0;
  }
  return counts;
}

StateCounts totalCounts(const std::vector<StateCounts>& counts)
{
  StateCounts total;
  for (const StateCounts& c : counts)
    total += c;
  return total;
}

bool hasProvenance(const Take& take)
{
  return !take.history().empty() || !headMarkers(take).empty() || (take.states() != std::uint8_t{0}).any();
}

void writeStateCountsJson(JsonWriter& json, const StateCounts& counts)
{
  const auto number = [](Eigen::Index n) { return static_cast<std::int64_t>(n); };
  json.key("filled").value(number(counts.filled));
  json.key("smoothed").value(number(counts.smoothedMeasured));
  json.key("edited").value(number(counts.edited));
  json.key("origin").beginObject();
  json.key("measured").value(number(counts.measured));
  json.key("filled").value(number(counts.filled));
  json.key("edited").value(number(counts.edited));
  json.endObject();
  json.key("operations").beginObject();
  json.key("smoothed").value(number(counts.smoothed));
  json.key("stabilized").value(number(counts.stabilized));
  json.endObject();
}

void writeHistoryJson(JsonWriter& json, const std::vector<ProcessingStep>& history)
{
  json.beginArray();
  for (const ProcessingStep& step : history) {
    json.beginObject();
    json.key("operation").value(step.operation);
    json.key("parameters").beginObject();
    auto parameters = step.parameters;  // sorted, as a JSON reader gives them back
    std::sort(parameters.begin(), parameters.end());
    for (const auto& [name, value] : parameters)
      json.key(name).value(value);
    json.endObject();
    json.key("markers").beginArray();
    for (const std::string& label : step.markers)
      json.value(label);
    json.endArray();
    json.key("first_frame").value(step.firstFrame);
    json.key("last_frame").value(step.lastFrame);
    json.key("samples").value(step.samples);
    json.key("time").value(step.time);
    json.key("tool").value(step.tool);
    json.endObject();
  }
  json.endArray();
}

std::string provenanceJson(const Take& take)
{
  const std::vector<StateRun> runs = stateRuns(take);
  const std::vector<StateCounts> counts = stateCounts(take);
  JsonWriter json;
  json.beginObject();
  json.key("format").value(kFormat);
  json.key("version").value(kVersion);
  json.key("frames").value(static_cast<std::int64_t>(take.frameCount()));
  json.key("first_frame").value(take.firstFrame());
  json.key("markers").beginArray();
  auto run = runs.begin();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    json.beginObject().key("label").value(take.label(m));
    writeStateCountsJson(json, counts[static_cast<std::size_t>(m)]);
    json.key("runs").beginArray();
    for (; run != runs.end() && run->marker == m; ++run) {
      json.beginArray()
          .value(take.firstFrame() + run->first)
          .value(static_cast<std::int64_t>(run->length))
          .value(sampleOriginName(run->state.origin()))
          .beginArray();
      for (const SampleOperation operation : kSampleOperations)
        if (run->state.has(operation))
          json.value(sampleOperationName(operation));
      json.endArray().endArray();
    }
    json.endArray().endObject();
  }
  json.endArray();
  json.key("history");
  writeHistoryJson(json, take.history());
  if (const std::vector<std::string> head = headMarkers(take); !head.empty()) {
    json.key("head_markers").beginArray();
    for (const std::string& label : head)
      json.value(label);
    json.endArray();
  }
  json.endObject();
  return json.str() + "\n";
}

void applyProvenanceJson(Take& take, std::string_view text, const std::string& sourceName,
                         std::vector<std::string>* warnings)
{
  const JsonValue root = parseJson(text, sourceName);
  const JsonValue* format = root.find("format", sourceName);
  if (!format || !format->isString() || format->string("format") != kFormat)
    throw FormatError(sourceName, 0, "not a provenance file (no \"format\": \"" + std::string(kFormat) + "\")");
  const JsonValue* frames = root.find("frames", sourceName);
  if (frames && frames->number("frames") != static_cast<double>(take.frameCount())) {
    warn(warnings, sourceName + ": written for " + std::to_string(static_cast<long long>(frames->number("frames"))) +
                       " frames, the take has " + std::to_string(take.frameCount()) + "; sample states ignored");
  } else if (const JsonValue* markers = root.find("markers", sourceName)) {
    Eigen::Index skipped = 0;
    for (const JsonValue& marker : markers->array("markers")) {
      const auto index = take.markerIndex(marker.find("label", "a marker")->string("label"));
      const JsonValue* runs = marker.find("runs", "a marker");
      for (const JsonValue& item : runs ? runs->array("runs") : std::vector<JsonValue>{}) {
        const auto& v = item.array("a run");
        const std::optional<SampleState> state = sidecarRunState(v);
        const bool ok = index && state && v[0].isNumber() && v[1].isNumber() &&
                        applyRun(take, {*index, static_cast<Eigen::Index>(v[0].number("first") -
                                                                           static_cast<double>(take.firstFrame())),
                                        static_cast<Eigen::Index>(v[1].number("length")), *state});
        skipped += ok ? 0 : 1;
      }
    }
    if (skipped > 0)
      warn(warnings, sourceName + ": " + std::to_string(skipped) +
                         " sample-state run(s) name markers or frames this take does not have, or a state this "
                         "reader does not know; skipped");
  }
  if (const JsonValue* history = root.find("history", sourceName))
    take.history() = readHistory(*history);
  if (const JsonValue* head = root.find("head_markers", sourceName)) {
    std::vector<std::string> labels;
    for (const JsonValue& label : head->array("head_markers"))
      labels.push_back(label.string("a head marker label"));
    restoreHeadMarkers(take, labels, sourceName, warnings);
  }
}

void storeProvenance(const Take& take, C3dParameterTree& tree)
{
  const std::vector<std::string> head = headMarkers(take);  // before the group goes: `tree` may hold them
  tree.removeGroup(kGroup);
  if (!hasProvenance(take))
    return;
  tree.ensureGroup(kGroup, kGroupDescription);
  tree.set(kGroup, C3dParameter::makeInt16("VERSION", {kVersion}, true));
  tree.set(kGroup, C3dParameter::makeStrings("LABELS", take.labels()));
  const std::vector<StateRun> runs = stateRuns(take);
  for (std::size_t start = 0, part = 1; start < runs.size(); start += kRunsPerParameter, ++part) {
    const std::size_t end = std::min(runs.size(), start + kRunsPerParameter);
    std::vector<double> values;
    for (std::size_t r = start; r < end; ++r)
      values.insert(values.end(), {static_cast<double>(runs[r].marker), static_cast<double>(runs[r].first),
                                   static_cast<double>(runs[r].length), static_cast<double>(runs[r].state.bits())});
    C3dParameter p = C3dParameter::makeFloat(part == 1 ? "STATE_RUNS" : "STATE_RUNS" + std::to_string(part), values,
                                             false);
    p.dimensions = {4, static_cast<int>(end - start)};
    tree.set(kGroup, std::move(p));
  }
  const std::string text = historyText(take.history());
  tree.set(kGroup, C3dParameter::makeFloat("HISTORY_BYTES", {static_cast<double>(text.size())}, true));
  const std::size_t pieces = (text.size() + kPieceBytes - 1) / kPieceBytes;
  for (std::size_t start = 0, part = 1; start < pieces; start += kPiecesPerParameter, ++part) {
    const std::size_t count = std::min(pieces - start, kPiecesPerParameter);
    C3dParameter p;
    p.name = part == 1 ? "HISTORY" : "HISTORY" + std::to_string(part);
    p.type = C3dType::Char;
    p.dimensions = {static_cast<int>(kPieceBytes), static_cast<int>(count)};
    p.chars = text.substr(start * kPieceBytes, count * kPieceBytes);
    p.chars.resize(count * kPieceBytes, ' ');
    tree.set(kGroup, std::move(p));
  }
  if (!head.empty())
    tree.set(kGroup, C3dParameter::makeStrings(kHeadMarkers, head));
}

void loadProvenance(Take& take, std::vector<std::string>* warnings, std::optional<ResidualCounts> counts)
{
  const C3dGroup* group = take.parameters().group(kGroup);
  if (!group) {
    if (const Eigen::Index marked = markZeroResidualsFilled(take, counts); marked > 0)
      warn(warnings, std::to_string(marked) +
                         " sample(s) have residual 0, which C3D writers use for computed (gap-filled) points; "
                         "shown as filled");
    return;
  }
  const C3dGroup copy = *group;
  take.parameters().removeGroup(kGroup);
  try {
    loadProcessingGroup(take, copy, warnings);
  } catch (const Error& e) {
    warn(warnings, std::string("PROCESSING group unreadable, sample states and history not restored: ") + e.what());
  }
}

std::vector<std::string> headMarkers(const Take& take)
{
  return take.parameters().strings(kGroup, kHeadMarkers);
}

void setHeadMarkers(Take& take, const std::vector<std::string>& labels)
{
  C3dParameterTree& tree = take.parameters();
  if (labels.empty()) {
    tree.remove(kGroup, kHeadMarkers);
    if (const C3dGroup* group = tree.group(kGroup); group && group->parameters.empty())
      tree.removeGroup(kGroup);
    return;
  }
  tree.ensureGroup(kGroup, kGroupDescription);
  tree.set(kGroup, C3dParameter::makeStrings(kHeadMarkers, labels));
}

std::filesystem::path provenanceSidecarPath(const std::filesystem::path& takePath)
{
  std::filesystem::path sidecar = takePath;
  sidecar.replace_extension(".provenance.json");
  return sidecar;
}

} // namespace mocap
