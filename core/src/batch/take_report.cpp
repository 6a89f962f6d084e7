#include "mocap/batch/take_report.h"

#include "mocap/base/error.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"
#include "mocap/batch/clean_preset.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_points.h"

#include <cmath>

namespace mocap {

namespace {

double markerValidFraction(const Take& take, Eigen::Index marker)
{
  if (take.frameCount() == 0)
    return 0.0;
  return static_cast<double>(take.valid().col(marker).count()) / static_cast<double>(take.frameCount());
}

void writeStrings(JsonWriter& json, const std::string& key, const std::vector<std::string>& texts)
{
  json.key(key).beginArray();
  for (const std::string& text : texts)
    json.value(text);
  json.endArray();
}

// Readers of the keys of a report; each names the key it failed on.

std::string text(const JsonValue& object, const std::string& key, const std::string& where)
{
  const JsonValue* value = object.find(key, where);
  return value ? value->string(where + "." + key) : std::string();
}

double number(const JsonValue& object, const std::string& key, const std::string& where)
{
  const JsonValue* value = object.find(key, where);
  return value && !value->isNull() ? value->number(where + "." + key) : 0.0;
}

std::int64_t whole(const JsonValue& object, const std::string& key, const std::string& where)
{
  const double v = number(object, key, where);
  if (!std::isfinite(v) || v != std::floor(v) || std::fabs(v) > 9e15)
    throw InvalidArgument(where + "." + key + " must be a whole number");
  return static_cast<std::int64_t>(v);
}

std::vector<std::string> strings(const JsonValue& object, const std::string& key, const std::string& where)
{
  std::vector<std::string> texts;
  if (const JsonValue* value = object.find(key, where))
    for (const JsonValue& item : value->array(where + "." + key))
      texts.push_back(item.string(where + "." + key));
  return texts;
}

} // namespace

std::vector<MarkerQuality> qualityBefore(const Take& take)
{
  std::vector<MarkerQuality> markers;
  for (const Eigen::Index m : markerPoints(take)) {
    MarkerQuality& marker = markers.emplace_back();
    marker.label = take.label(m);
    marker.validBefore = markerValidFraction(take, m);
    for (const Gap& gap : findGaps(take.valid().col(m), m))
      marker.gapLengths.push_back(static_cast<std::int64_t>(gap.length));
  }
  return markers;
}

void recordCleaning(TakeReport& report, std::vector<MarkerQuality> before, const Take& cleaned,
                    const CleanReport& cleaning)
{
  report.markers = std::move(before);
  report.frames = static_cast<std::int64_t>(cleaned.frameCount());
  report.frameRate = cleaned.frameRate();
  report.validAfter = markerValidFraction(cleaned);
  // report.markers follows the marker points (model outputs have no entry); cleaning names points.
  const std::vector<Eigen::Index> points = markerPoints(cleaned);
  std::vector<MarkerQuality*> entry(static_cast<std::size_t>(cleaned.markerCount()), nullptr);
  for (std::size_t j = 0; j < points.size() && j < report.markers.size(); ++j) {
    const Eigen::Index m = points[j];
    MarkerQuality& marker = report.markers[j];
    entry[static_cast<std::size_t>(m)] = &marker;
    marker.validAfter = markerValidFraction(cleaned, m);
    if (cleaned.valid().col(m).count() == 0)
      report.missingMarkers.push_back(marker.label);
  }
  auto markerOf = [&entry](Eigen::Index m) -> MarkerQuality* {
    return m >= 0 && m < static_cast<Eigen::Index>(entry.size()) ? entry[static_cast<std::size_t>(m)] : nullptr;
  };
  for (const SpikeFlag& flag : cleaning.spikes)
    if (MarkerQuality* marker = markerOf(flag.marker))
      ++marker->spikes;
  for (const GapFillReport& gap : cleaning.gaps)
    if (MarkerQuality* marker = markerOf(gap.gap.marker))
      ++(gap.filled ? marker->filledGaps : marker->unfilledGaps);
  report.spikes = static_cast<std::int64_t>(cleaning.spikes.size());
  for (const MarkerQuality& marker : report.markers) {
    report.filledGaps += marker.filledGaps;
    report.unfilledGaps += marker.unfilledGaps;
  }
  report.filledSamples = static_cast<std::int64_t>(cleaning.filledSamples);
  report.smoothedSamples = static_cast<std::int64_t>(cleaning.smoothedSamples);
  report.modelOutputs = static_cast<std::int64_t>(cleaning.modelOutputs.size());
}

std::string takeReportJson(const TakeReport& report)
{
  JsonWriter json;
  json.beginObject();
  json.key("format").value("mocap-take-report");
  json.key("version").value(1);
  json.key("input").value(report.input);
  json.key("input_hash").value(report.inputHash);
  json.key("input_bytes").value(report.inputBytes);
  json.key("output").value(report.output);
  json.key("status").value(report.failed() ? "failed" : "cleaned");
  if (report.failed())
    json.key("error").value(report.error);
  writeStrings(json, "warnings", report.warnings);
  writeStrings(json, "data_loss", report.dataLoss);
  json.key("preset_hash").value(report.presetHash);
  json.key("preset");
  writeCleanPreset(json, report.preset);
  if (!report.failed()) {
    json.key("frames").value(report.frames);
    json.key("frame_rate").value(report.frameRate);
    json.key("valid_fraction_before").value(report.validBefore);
    json.key("valid_fraction_after").value(report.validAfter);
    json.key("spikes_flagged").value(report.spikes);
    json.key("filled_gaps").value(report.filledGaps);
    json.key("unfilled_gaps").value(report.unfilledGaps);
    json.key("filled_samples").value(report.filledSamples);
    json.key("smoothed_samples").value(report.smoothedSamples);
    writeStrings(json, "markers_missing", report.missingMarkers);
    json.key("model_outputs_untouched").value(report.modelOutputs);
    json.key("markers").beginArray();
    for (const MarkerQuality& marker : report.markers) {
      json.beginObject();
      json.key("label").value(marker.label);
      json.key("valid_fraction_before").value(marker.validBefore);
      json.key("valid_fraction_after").value(marker.validAfter);
      json.key("gap_lengths").beginArray();
      for (const std::int64_t length : marker.gapLengths)
        json.value(length);
      json.endArray();
      json.key("spikes").value(marker.spikes);
      json.key("filled_gaps").value(marker.filledGaps);
      json.key("unfilled_gaps").value(marker.unfilledGaps);
      json.endObject();
    }
    json.endArray();
  }
  json.key("timings").beginObject();
  json.key("read_s").value(report.timings.read);
  json.key("clean_s").value(report.timings.clean);
  json.key("write_s").value(report.timings.write);
  json.key("total_s").value(report.timings.total);
  json.endObject();
  json.endObject();
  return json.str() + "\n";
}

TakeReport parseTakeReport(std::string_view bytes, const std::string& sourceName)
{
  const JsonValue document = parseJson(bytes, sourceName);
  const std::string where = sourceName;
  if (text(document, "format", where) != "mocap-take-report")
    throw InvalidArgument(where + ": not a mocap take report (format must be \"mocap-take-report\")");
  TakeReport report;
  report.input = text(document, "input", where);
  report.inputHash = text(document, "input_hash", where);
  report.inputBytes = whole(document, "input_bytes", where);
  report.output = text(document, "output", where);
  report.error = text(document, "error", where);
  if (text(document, "status", where) == "failed" && report.error.empty())
    report.error = "failed";
  report.warnings = strings(document, "warnings", where);
  report.dataLoss = strings(document, "data_loss", where);  // absent from reports before it existed
  report.presetHash = text(document, "preset_hash", where);
  if (const JsonValue* preset = document.find("preset", where))
    report.preset = cleanPresetFromJson(*preset);
  report.frames = whole(document, "frames", where);
  report.frameRate = number(document, "frame_rate", where);
  report.validBefore = number(document, "valid_fraction_before", where);
  report.validAfter = number(document, "valid_fraction_after", where);
  report.spikes = whole(document, "spikes_flagged", where);
  report.filledGaps = whole(document, "filled_gaps", where);
  report.unfilledGaps = whole(document, "unfilled_gaps", where);
  report.filledSamples = whole(document, "filled_samples", where);
  report.smoothedSamples = whole(document, "smoothed_samples", where);
  report.missingMarkers = strings(document, "markers_missing", where);
  report.modelOutputs = whole(document, "model_outputs_untouched", where);
  if (const JsonValue* markers = document.find("markers", where))
    for (const JsonValue& item : markers->array(where + ".markers")) {
      const std::string at = where + ".markers[" + std::to_string(report.markers.size()) + "]";
      MarkerQuality marker;
      marker.label = text(item, "label", at);
      marker.validBefore = number(item, "valid_fraction_before", at);
      marker.validAfter = number(item, "valid_fraction_after", at);
      if (const JsonValue* gaps = item.find("gap_lengths", at))
        for (const JsonValue& length : gaps->array(at + ".gap_lengths"))
          marker.gapLengths.push_back(static_cast<std::int64_t>(length.number(at + ".gap_lengths")));
      marker.spikes = whole(item, "spikes", at);
      marker.filledGaps = whole(item, "filled_gaps", at);
      marker.unfilledGaps = whole(item, "unfilled_gaps", at);
      report.markers.push_back(std::move(marker));
    }
  if (const JsonValue* timings = document.find("timings", where)) {
    report.timings.read = number(*timings, "read_s", where + ".timings");
    report.timings.clean = number(*timings, "clean_s", where + ".timings");
    report.timings.write = number(*timings, "write_s", where + ".timings");
    report.timings.total = number(*timings, "total_s", where + ".timings");
  }
  return report;
}

} // namespace mocap
