#include "mocap/batch/archive_summary.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"
#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/batch/clean_preset.h"
#include "mocap/batch/take_manifest.h"
#include "mocap/model/data_loss_record.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <system_error>

namespace fs = std::filesystem;

namespace mocap {

namespace {

// Gap lengths are binned by powers of two: 1, 2–3, 4–7, …, 512–1023, 1024 and longer.
constexpr std::size_t kGapBins = 11;
constexpr std::size_t kMostSpikedMarkers = 30;
constexpr std::size_t kHeatMarkers = 40;
constexpr std::size_t kHeatTakes = 400;
constexpr std::size_t kNamedFailures = 10;  // takes named per failure reason; the rest are counted

std::size_t gapBin(std::int64_t length)
{
  std::size_t bin = 0;
  for (std::int64_t l = std::max<std::int64_t>(length, 1); l > 1 && bin + 1 < kGapBins; l >>= 1)
    ++bin;
  return bin;
}

std::string gapBinLabel(std::size_t bin)
{
  const std::int64_t low = std::int64_t{1} << bin;
  if (bin + 1 == kGapBins)
    return "≥" + std::to_string(low);
  return low == 1 ? std::string("1") : std::to_string(low) + "–" + std::to_string(2 * low - 1);
}

/// What the plots show, gathered once. A marker's missing share sums over the takes that have it
/// (a take of another marker set does not make it "missing"). O(#takes · #markers).
struct Figures
{
  std::size_t cleaned = 0, failed = 0;
  std::array<std::int64_t, kGapBins> gapHistogram{};
  std::vector<std::pair<std::string, std::int64_t>> spikesPerMarker;  ///< most first
  std::vector<std::string> heatMarkers;                              ///< most often missing first
  std::vector<std::size_t> heatTakes;                                ///< cleaned takes, report order
  std::map<std::string, std::size_t> presetUse;                      ///< hash → takes
};

Figures gather(const ArchiveSummary& summary)
{
  Figures figures;
  std::map<std::string, std::int64_t> spikes;
  std::map<std::string, double> missing;
  for (std::size_t t = 0; t < summary.reports.size(); ++t) {
    const TakeReport& report = summary.reports[t];
    ++figures.presetUse[report.presetHash];
    if (report.failed()) {
      ++figures.failed;
      continue;
    }
    ++figures.cleaned;
    if (figures.heatTakes.size() < kHeatTakes)
      figures.heatTakes.push_back(t);
    for (const MarkerQuality& marker : report.markers) {
      for (const std::int64_t length : marker.gapLengths)
        ++figures.gapHistogram[gapBin(length)];
      spikes[marker.label] += marker.spikes;
      missing[marker.label] += 1.0 - marker.validBefore;
    }
  }
  figures.spikesPerMarker.assign(spikes.begin(), spikes.end());
  std::stable_sort(figures.spikesPerMarker.begin(), figures.spikesPerMarker.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  if (figures.spikesPerMarker.size() > kMostSpikedMarkers)
    figures.spikesPerMarker.resize(kMostSpikedMarkers);
  std::vector<std::pair<std::string, double>> byMissing(missing.begin(), missing.end());
  std::stable_sort(byMissing.begin(), byMissing.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  for (std::size_t i = 0; i < byMissing.size() && i < kHeatMarkers; ++i)
    figures.heatMarkers.push_back(byMissing[i].first);
  return figures;
}

std::string escape(std::string_view text)
{
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&#39;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string fixed(double value, int decimals)
{
  return fixedText(value, decimals, "0");  // coordinates: a number even when the value is not
}

std::string percent(double fraction)
{
  return fixed(100.0 * fraction, 1) + " %";
}

/// The take's name in the plots: its output path below OUTDIR.
std::string takeName(const TakeReport& report)
{
  return report.output.empty() ? report.input : report.output;
}

/// White to red by `fraction` (0…1).
std::string heatColour(double fraction)
{
  const double f = std::clamp(fraction, 0.0, 1.0);
  const auto channel = [f](int from, int to) { return static_cast<int>(std::lround(from + (to - from) * f)); };
  char text[16];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel(255, 214), channel(255, 39), channel(255, 40));
  return text;
}

// Each plot is an <svg class="plot" id="…"> whose marks carry their values in data-* attributes
// and a <title> (the browser's tooltip).

void validFractionPlot(std::string& html, const ArchiveSummary& summary)
{
  const std::size_t n = summary.reports.size();
  const double left = 50, top = 20, width = 860, height = 220;
  const double step = n > 0 ? width / static_cast<double>(n) : width;
  html += "<svg class=\"plot\" id=\"valid-fraction\" xmlns=\"http://www.w3.org/2000/svg\" width=\"940\" height=\"340\">\n";
  html += "<rect x=\"" + fixed(left, 0) + "\" y=\"" + fixed(top, 0) + "\" width=\"" + fixed(width, 0) + "\" height=\"" +
          fixed(height, 0) + "\" fill=\"#f7f7f7\" stroke=\"#999\"/>\n";
  for (int tick = 0; tick <= 4; ++tick) {
    const double y = top + height * (1.0 - tick / 4.0);
    html += "<line x1=\"" + fixed(left, 0) + "\" x2=\"" + fixed(left + width, 0) + "\" y1=\"" + fixed(y, 1) + "\" y2=\"" +
            fixed(y, 1) + "\" stroke=\"#ddd\"/><text x=\"" + fixed(left - 6, 0) + "\" y=\"" + fixed(y + 4, 1) +
            "\" text-anchor=\"end\" font-size=\"11\">" + std::to_string(tick * 25) + " %</text>\n";
  }
  const auto yOf = [&](double fraction) { return top + height * (1.0 - std::clamp(fraction, 0.0, 1.0)); };
  const double barWidth = std::clamp(step * 0.4, 0.5, 18.0);
  const auto bar = [&](double x, double fraction, const char* colour) {
    return "<rect x=\"" + fixed(x, 2) + "\" y=\"" + fixed(yOf(fraction), 1) + "\" width=\"" + fixed(barWidth, 2) +
           "\" height=\"" + fixed(top + height - yOf(fraction), 1) + "\" fill=\"" + colour + "\"/>";
  };
  for (std::size_t t = 0; t < n; ++t) {
    const TakeReport& report = summary.reports[t];
    const double x = left + step * (static_cast<double>(t) + 0.5);
    const std::string name = escape(takeName(report));
    if (n <= 40) {  // few enough takes to name each under its bars
      const double y = top + height + 10;
      html += "<text x=\"" + fixed(x - 4, 1) + "\" y=\"" + fixed(y, 1) + "\" font-size=\"10\" transform=\"rotate(30 " +
              fixed(x - 4, 1) + " " + fixed(y, 1) + ")\">" + name + "</text>\n";
    }
    if (report.failed()) {
      // A cross on the axis, not a bar: a failed take has no valid fraction to draw, and a
      // full-height bar would read as 100 %.
      const double r = std::clamp(barWidth, 3.0, 6.0), y = top + height - r - 2;
      html += "<g class=\"failed\" data-take=\"" + name + "\" stroke=\"#d62728\" stroke-width=\"2\"><title>" + name +
              ": failed: " + escape(report.error) + "</title><line x1=\"" + fixed(x - r, 2) + "\" y1=\"" +
              fixed(y - r, 1) + "\" x2=\"" + fixed(x + r, 2) + "\" y2=\"" + fixed(y + r, 1) + "\"/><line x1=\"" +
              fixed(x - r, 2) + "\" y1=\"" + fixed(y + r, 1) + "\" x2=\"" + fixed(x + r, 2) + "\" y2=\"" +
              fixed(y - r, 1) + "\"/></g>\n";
      continue;
    }
    html += "<g class=\"take\" data-take=\"" + name + "\" data-before=\"" + fixed(report.validBefore, 4) +
            "\" data-after=\"" + fixed(report.validAfter, 4) + "\"><title>" + name + ": " +
            percent(report.validBefore) + " → " + percent(report.validAfter) + "</title>" +
            bar(x - barWidth, report.validBefore, "#ff7f0e") + bar(x, report.validAfter, "#1f77b4") + "</g>\n";
  }
  html += "<text x=\"" + fixed(left, 0) +
          "\" y=\"16\" font-size=\"12\" dy=\"-4\"><tspan fill=\"#ff7f0e\">▮ before</tspan>  <tspan fill=\"#1f77b4\">▮ after "
          "cleaning</tspan>  <tspan fill=\"#d62728\">✕ failed</tspan>  (takes in path order)</text>\n";
  html += "</svg>\n";
}

void barPlot(std::string& html, const std::string& id, const std::vector<std::pair<std::string, std::int64_t>>& bars,
             const std::string& colour, const std::string& valueName)
{
  const double left = 50, top = 10, width = 860, height = 200;
  std::int64_t highest = 1;
  for (const auto& bar : bars)
    highest = std::max(highest, bar.second);
  const double step = bars.empty() ? width : width / static_cast<double>(bars.size());
  html += "<svg class=\"plot\" id=\"" + id + "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"940\" height=\"300\">\n";
  html += "<line x1=\"" + fixed(left, 0) + "\" x2=\"" + fixed(left + width, 0) + "\" y1=\"" + fixed(top + height, 0) +
          "\" y2=\"" + fixed(top + height, 0) + "\" stroke=\"#999\"/>\n";
  html += "<text x=\"" + fixed(left - 6, 0) + "\" y=\"" + fixed(top + 10, 0) + "\" text-anchor=\"end\" font-size=\"11\">" +
          std::to_string(highest) + "</text>\n";
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const double h = height * static_cast<double>(bars[i].second) / static_cast<double>(highest);
    const double x = left + step * static_cast<double>(i);
    const std::string label = escape(bars[i].first);
    html += "<rect class=\"bar\" data-label=\"" + label + "\" data-" + valueName + "=\"" +
            std::to_string(bars[i].second) + "\" x=\"" + fixed(x + step * 0.1, 1) + "\" y=\"" +
            fixed(top + height - h, 1) + "\" width=\"" + fixed(step * 0.8, 1) + "\" height=\"" + fixed(h, 1) +
            "\" fill=\"" + colour + "\"><title>" + label + ": " + std::to_string(bars[i].second) + "</title></rect>\n";
    const double cx = x + step * 0.5, cy = top + height + 8;
    html += "<text x=\"" + fixed(cx, 1) + "\" y=\"" + fixed(cy, 1) + "\" font-size=\"10\" transform=\"rotate(45 " +
            fixed(cx, 1) + " " + fixed(cy, 1) + ")\">" + label + "</text>\n";
  }
  html += "</svg>\n";
}

void missingHeatMap(std::string& html, const ArchiveSummary& summary, const Figures& figures)
{
  const double left = 140, top = 10;
  const double cellW = figures.heatTakes.empty() ? 10 : std::clamp(760.0 / static_cast<double>(figures.heatTakes.size()), 1.5, 24.0);
  const double cellH = 14;
  const double width = left + cellW * static_cast<double>(figures.heatTakes.size()) + 20;
  const double height = top + cellH * static_cast<double>(figures.heatMarkers.size()) + 30;
  html += "<svg class=\"plot\" id=\"missing-heat-map\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
          fixed(std::max(width, 640.0), 0) + "\" height=\"" + fixed(height, 0) + "\">\n";
  for (std::size_t m = 0; m < figures.heatMarkers.size(); ++m) {
    const std::string& label = figures.heatMarkers[m];
    const double y = top + cellH * static_cast<double>(m);
    html += "<text x=\"" + fixed(left - 6, 0) + "\" y=\"" + fixed(y + cellH - 3, 1) +
            "\" text-anchor=\"end\" font-size=\"11\">" + escape(label) + "</text>\n";
    for (std::size_t c = 0; c < figures.heatTakes.size(); ++c) {
      const TakeReport& report = summary.reports[figures.heatTakes[c]];
      const auto marker = std::find_if(report.markers.begin(), report.markers.end(),
                                       [&label](const MarkerQuality& q) { return q.label == label; });
      const bool present = marker != report.markers.end();  // another marker set: grey, not "missing"
      const double fraction = present ? 1.0 - marker->validBefore : 0.0;
      html += "<rect class=\"cell\" data-marker=\"" + escape(label) + "\" data-take=\"" + escape(takeName(report)) +
              "\" data-missing=\"" + (present ? fixed(fraction, 4) : std::string("absent")) + "\" x=\"" +
              fixed(left + cellW * static_cast<double>(c), 2) + "\" y=\"" + fixed(y, 1) + "\" width=\"" +
              fixed(cellW, 2) + "\" height=\"" + fixed(cellH, 1) + "\" fill=\"" +
              (present ? heatColour(fraction) : std::string("#c8c8c8")) + "\"><title>" + escape(label) + " in " +
              escape(takeName(report)) + ": " + (present ? percent(fraction) + " missing" : std::string("not in this take")) +
              "</title></rect>\n";
    }
  }
  html += "<text x=\"" + fixed(left, 0) + "\" y=\"" + fixed(height - 8, 0) +
          "\" font-size=\"12\">takes (columns, path order) · white: never missing, red: always missing, grey: not in the take</text>\n";
  html += "</svg>\n";
}

/// "the data section is shorter than declared …; 2 more warnings" for a reason column.
std::string firstOf(const std::vector<std::string>& warnings, const char* more)
{
  std::string text = warnings.front();
  if (warnings.size() > 1)
    text += " (and " + std::to_string(warnings.size() - 1) + " " + more + ")";
  return text;
}

/// Why a take needs a person, worst reasons first, and how badly (`severity`): a failure, then data
/// the file declares but the take lacks, then a file whose header and parameters disagreed (the
/// reader chose, and may have chosen wrong), then a low valid fraction, markers never seen, and
/// last gaps left open, which most takes have. So a take that lost data is never buried under
/// takes that only have their usual open gaps.
std::string reviewReason(const TakeReport& report, double minValid, double& severity)
{
  if (report.failed()) {
    severity = 10.0;
    return "failed: " + report.error;
  }
  std::vector<std::string> reasons;
  severity = 0.0;
  if (!report.dataLoss.empty()) {
    const DataLossKinds kinds = dataLossKinds(report.dataLoss);
    const char* what = !kinds.wrong ? "data lost on reading: "
                       : kinds.missing ? "data lost and wrong on reading: "
                                       : "wrong data on reading: ";
    reasons.push_back(what + firstOf(report.dataLoss, "more"));
    severity += 6.0;
  }
  if (report.warnings.size() > report.dataLoss.size()) {
    std::vector<std::string> others;
    for (const std::string& warning : report.warnings)
      if (std::find(report.dataLoss.begin(), report.dataLoss.end(), warning) == report.dataLoss.end())
        others.push_back(warning);
    reasons.push_back("read with warnings: " + firstOf(others, "more warnings"));
    severity += 4.0;
  }
  if (report.validAfter < minValid) {
    reasons.push_back("valid " + percent(report.validAfter) + " after cleaning (below " + percent(minValid) + ")");
    severity += 2.0 + (minValid - report.validAfter);
  }
  if (!report.missingMarkers.empty()) {
    std::string names;
    for (std::size_t i = 0; i < report.missingMarkers.size() && i < 5; ++i)
      names += (i ? ", " : "") + report.missingMarkers[i];
    if (report.missingMarkers.size() > 5)
      names += ", …";
    reasons.push_back(std::to_string(report.missingMarkers.size()) + " markers never seen (" + names + ")");
    severity += 1.0 + 0.01 * static_cast<double>(report.missingMarkers.size());
  }
  if (report.unfilledGaps > 0) {
    reasons.push_back(std::to_string(report.unfilledGaps) + " gaps left open");
    severity += 1.0 - report.validAfter;
  }
  std::string text;
  for (const std::string& reason : reasons)
    text += (text.empty() ? "" : "; ") + reason;
  return text;
}

std::vector<std::pair<std::string, std::int64_t>> histogramBars(const Figures& figures)
{
  std::vector<std::pair<std::string, std::int64_t>> bars;
  for (std::size_t bin = 0; bin < kGapBins; ++bin)
    bars.emplace_back(gapBinLabel(bin), figures.gapHistogram[bin]);
  return bars;
}

} // namespace

ArchiveSummary summarizeArchive(const fs::path& outDir, double minValid)
{
  std::error_code error;
  if (!fs::is_directory(outDir, error))
    throw IoError(outDir.string() + ": not a folder (give the OUTDIR of mocap batch)");
  ArchiveSummary summary;
  summary.outDir = outDir;
  summary.minValid = minValid;
  std::vector<fs::path> files;
  const std::string& suffix = takeReportSuffix();
  for (fs::recursive_directory_iterator it(outDir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (it->is_regular_file(error) && name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      files.push_back(it->path());
  }
  if (error)
    throw IoError(outDir.string() + ": cannot be read (" + error.message() + ")");
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    try {
      summary.reports.push_back(parseTakeReport(readFileBytes(file), file.string()));
    } catch (const Error& e) {
      summary.unreadable.push_back(e.what());
    }
  }
  for (std::size_t t = 0; t < summary.reports.size(); ++t) {
    TakeToReview review;
    review.take = t;
    review.reason = reviewReason(summary.reports[t], minValid, review.severity);
    if (!review.reason.empty())
      summary.review.push_back(std::move(review));
  }
  std::stable_sort(summary.review.begin(), summary.review.end(),
                   [](const TakeToReview& a, const TakeToReview& b) { return a.severity > b.severity; });
  return summary;
}

namespace {

/// A report's error less a leading "INPUT: " or "NAME: " naming the take (readers prefix their
/// errors with the file), so takes failing for one cause share one reason.
std::string failureReason(const TakeReport& report)
{
  const std::string name = std::filesystem::path(report.input).filename().string();
  for (const std::string& prefix : {report.input + ": ", name + ": "})
    if (!name.empty() && report.error.rfind(prefix, 0) == 0)
      return report.error.substr(prefix.size());
  return report.error;
}

void failureTable(std::string& html, const ArchiveSummary& summary)
{
  const std::vector<FailureGroup> groups = failuresByReason(summary);
  if (groups.empty())
    return;
  html += "<h2>Failures by reason</h2>\n<table id=\"failures\"><tr><th>reason</th><th>takes</th><th>which</th></tr>\n";
  for (const FailureGroup& group : groups) {
    std::string names;
    for (std::size_t i = 0; i < group.takes.size() && i < kNamedFailures; ++i)
      names += (i > 0 ? ", " : "") + takeName(summary.reports[group.takes[i]]);
    if (group.takes.size() > kNamedFailures)
      names += " and " + std::to_string(group.takes.size() - kNamedFailures) + " more";
    html += "<tr><td>" + escape(group.reason) + "</td><td>" + std::to_string(group.takes.size()) + "</td><td>" +
            escape(names) + "</td></tr>\n";
  }
  html += "</table>\n";
}

} // namespace

std::vector<FailureGroup> failuresByReason(const ArchiveSummary& summary)
{
  std::map<std::string, std::vector<std::size_t>> byReason;
  for (std::size_t t = 0; t < summary.reports.size(); ++t)
    if (summary.reports[t].failed())
      byReason[failureReason(summary.reports[t])].push_back(t);
  std::vector<FailureGroup> groups;
  for (auto& [reason, takes] : byReason)
    groups.push_back({reason, std::move(takes)});
  std::stable_sort(groups.begin(), groups.end(),
                   [](const FailureGroup& a, const FailureGroup& b) { return a.takes.size() > b.takes.size(); });
  return groups;
}

std::string archiveSummaryHtml(const ArchiveSummary& summary)
{
  const Figures figures = gather(summary);
  std::string html;
  html += "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n";
  html += "<title>Archive report: " + escape(summary.outDir.string()) + "</title>\n";
  html += "<style>body{font-family:sans-serif;margin:24px;color:#222}h2{margin-top:32px}"
          "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 8px;text-align:left}"
          ".bad{color:#b00}pre{background:#f4f4f4;padding:8px}</style>\n</head>\n<body>\n";
  html += "<h1>Archive report</h1>\n<p>" + escape(summary.outDir.string()) + "</p>\n";
  html += "<table id=\"counts\"><tr><th>takes</th><th>cleaned</th><th>failed</th><th>to review</th><th>unreadable "
          "reports</th></tr><tr><td>" +
          std::to_string(summary.reports.size()) + "</td><td>" + std::to_string(figures.cleaned) + "</td><td>" +
          std::to_string(figures.failed) + "</td><td>" + std::to_string(summary.review.size()) + "</td><td>" +
          std::to_string(summary.unreadable.size()) + "</td></tr></table>\n";
  for (const std::string& problem : summary.unreadable)
    html += "<p class=\"bad\">" + escape(problem) + "</p>\n";
  html += "<h2>Valid fraction before and after cleaning, per take</h2>\n";
  validFractionPlot(html, summary);
  html += "<h2>Gap lengths (frames, as read; all takes)</h2>\n";
  barPlot(html, "gap-lengths", histogramBars(figures), "#2ca02c", "count");
  html += "<h2>Spikes per marker (the " + std::to_string(kMostSpikedMarkers) + " most spiked markers)</h2>\n";
  barPlot(html, "spikes-per-marker", figures.spikesPerMarker, "#9467bd", "spikes");
  html += "<h2>Missing samples: markers × takes (the " + std::to_string(kHeatMarkers) +
          " markers most often missing";
  if (figures.cleaned > figures.heatTakes.size())
    html += "; the first " + std::to_string(figures.heatTakes.size()) + " of " + std::to_string(figures.cleaned) +
            " takes";
  html += ")</h2>\n";
  missingHeatMap(html, summary, figures);
  failureTable(html, summary);
  html += "<h2>Takes that need a person (worst first)</h2>\n<table id=\"review\"><tr><th>take</th><th>valid "
          "after</th><th>reader warnings</th><th>reason</th></tr>\n";
  for (const TakeToReview& review : summary.review) {
    const TakeReport& report = summary.reports[review.take];
    std::string warnings;  // every warning in the cell's tooltip, one per line; the count in the cell
    for (const std::string& warning : report.warnings)
      warnings += (warnings.empty() ? "" : "&#10;") + escape(warning);
    html += std::string("<tr") + (report.failed() || !report.dataLoss.empty() ? " class=\"bad\"" : "") + "><td>" +
            escape(takeName(report)) + "</td><td>" +
            (report.failed() ? std::string("–") : percent(report.validAfter)) + "</td><td class=\"warnings\" title=\"" +
            warnings + "\">" + std::to_string(report.warnings.size()) + "</td><td>" + escape(review.reason) +
            "</td></tr>\n";
  }
  html += "</table>\n<h2>Processing settings</h2>\n";
  for (const auto& [hash, count] : figures.presetUse) {
    const auto it = std::find_if(summary.reports.begin(), summary.reports.end(),
                                 [&hash = hash](const TakeReport& r) { return r.presetHash == hash; });
    html += "<p>Preset " + escape(hash) + " (" + std::to_string(count) + " takes):</p>\n<pre>" +
            escape(cleanPresetJson(it->preset)) + "</pre>\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

std::string archiveSummaryJson(const ArchiveSummary& summary)
{
  const Figures figures = gather(summary);
  JsonWriter json;
  json.beginObject();
  json.key("out_dir").value(summary.outDir.string());
  json.key("takes").value(static_cast<std::int64_t>(summary.reports.size()));
  json.key("cleaned").value(static_cast<std::int64_t>(figures.cleaned));
  json.key("failed").value(static_cast<std::int64_t>(figures.failed));
  json.key("unreadable_reports").beginArray();
  for (const std::string& problem : summary.unreadable)
    json.value(problem);
  json.endArray();
  json.key("min_valid").value(summary.minValid);
  json.key("per_take").beginArray();
  for (const TakeReport& report : summary.reports) {
    json.beginObject().key("take").value(takeName(report));
    if (report.failed())
      json.key("error").value(report.error);
    else
      json.key("valid_fraction_before").value(report.validBefore).key("valid_fraction_after").value(report.validAfter);
    json.endObject();
  }
  json.endArray();
  json.key("gap_length_histogram").beginArray();
  for (const auto& [label, count] : histogramBars(figures))
    json.beginObject().key("frames").value(label).key("gaps").value(count).endObject();
  json.endArray();
  json.key("spikes_per_marker").beginArray();
  for (const auto& [label, count] : figures.spikesPerMarker)
    json.beginObject().key("marker").value(label).key("spikes").value(count).endObject();
  json.endArray();
  json.key("failures_by_reason").beginArray();
  for (const FailureGroup& group : failuresByReason(summary)) {
    json.beginObject().key("reason").value(group.reason).key("takes").beginArray();
    for (const std::size_t t : group.takes)
      json.value(takeName(summary.reports[t]));
    json.endArray().endObject();
  }
  json.endArray();
  json.key("review").beginArray();
  for (const TakeToReview& review : summary.review)
    json.beginObject()
        .key("take")
        .value(takeName(summary.reports[review.take]))
        .key("reason")
        .value(review.reason)
        .key("warnings")
        .value(static_cast<std::int64_t>(summary.reports[review.take].warnings.size()))
        .key("data_loss")
        .value(!summary.reports[review.take].dataLoss.empty())
        .endObject();
  json.endArray();
  json.key("presets").beginObject();
  for (const auto& [hash, count] : figures.presetUse)
    json.key(hash).value(static_cast<std::int64_t>(count));
  json.endObject();
  json.endObject();
  return json.str() + "\n";
}

} // namespace mocap
