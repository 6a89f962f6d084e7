#include "mocap/io/weights_csv_reader.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/base/number_text.h"
#include "mocap/base/text.h"

#include <cmath>

namespace mocap {

namespace {

/// A header's fields per RFC 4180: a quoted field may hold commas, its quotes doubled.
std::vector<std::string> headerFields(std::string_view line, const std::string& sourceName)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted)
    throw FormatError(sourceName, "line 1: a quoted name is not closed");
  return fields;
}

double number(std::string_view cell, const TextLine& line, const std::string& sourceName, const char* what)
{
  double value = 0.0;
  if (!parseNumber(trim(cell), value) || !std::isfinite(value))
    throw FormatError(sourceName, "line " + std::to_string(line.number) + ": " + what + " '" + std::string(cell) +
                                      "' is not a finite number");
  return value;
}

} // namespace

WeightCurves parseWeightsCsv(std::string_view text, const std::string& sourceName)
{
  const std::vector<TextLine> lines = contentLines(text);
  if (lines.empty())
    throw FormatError(sourceName, "the file is empty");
  std::vector<std::string> header = headerFields(lines[0].text, sourceName);
  if (header.size() < 3 || header[0] != "Frame" || header[1] != "Time")
    throw FormatError(sourceName, "line " + std::to_string(lines[0].number) +
                                      ": weight curves start with Frame,Time and a column per shape");
  WeightCurves curves;
  curves.names.assign(header.begin() + 2, header.end());
  const auto shapes = static_cast<Eigen::Index>(curves.names.size());
  curves.weights.resize(static_cast<Eigen::Index>(lines.size()) - 1, shapes);
  double firstTime = 0.0, lastTime = 0.0;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const TextLine& line = lines[r];
    const std::vector<std::string_view> cells = split(line.text, ',');
    if (static_cast<Eigen::Index>(cells.size()) != shapes + 2)
      throw FormatError(sourceName, "line " + std::to_string(line.number) + ": " + std::to_string(cells.size()) +
                                        " cells, not " + std::to_string(shapes + 2));
    const double frame = number(cells[0], line, sourceName, "the frame");
    const double time = number(cells[1], line, sourceName, "the time");
    if (r == 1) {
      curves.firstFrame = std::llround(frame);
      firstTime = time;
    } else if (!(time > lastTime)) {
      throw FormatError(sourceName, "line " + std::to_string(line.number) + ": the time does not increase");
    }
    lastTime = time;
    for (Eigen::Index s = 0; s < shapes; ++s)
      curves.weights(static_cast<Eigen::Index>(r) - 1, s) =
          number(cells[static_cast<std::size_t>(s) + 2], line, sourceName, "the weight");
  }
  const Eigen::Index rows = curves.weights.rows();
  if (rows > 1) {
    // Times were written as i / rate, so the quotient is the rate up to rounding: snap it.
    const double rate = static_cast<double>(rows - 1) / (lastTime - firstTime);
    curves.frameRate = std::abs(rate - std::round(rate)) < 1e-6 * rate ? std::round(rate) : rate;
  }
  return curves;
}

WeightCurves readWeightsCsv(const std::filesystem::path& path)
{
  return parseWeightsCsv(readFileBytes(path), path.string());
}

} // namespace mocap
