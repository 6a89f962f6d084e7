#include "mocap/io/trc_io.h"
#include "mocap/io/take_plausibility.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"
#include "mocap/model/marker_edits.h"
#include "mocap/model/marker_points.h"
#include "mocap/model/sample_rows.h"
#include "mocap/base/file_io.h"
#include "mocap/base/text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <system_error>

namespace mocap {

namespace {

// Frame numbers are kept well inside int64 so firstFrame + index can never overflow.
constexpr std::int64_t kMaxFrameNumber = std::int64_t{1} << 52;
// A full row spends at least one byte (a tab) per coordinate, so a genuine file holds fewer
// samples than bytes; short rows may need a little more. Anything beyond this is a hostile count.
constexpr std::size_t kSampleAllowance = 65536;

// O(1).
bool inFrameRange(std::int64_t frame)
{
  return frame >= -kMaxFrameNumber && frame <= kMaxFrameNumber;
}

// Cell separators of space-padded lines. O(1).
bool isBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

// Walks text line by line, dropping the CR of CRLF; a final line break ends the last line rather
// than starting an empty one. Each call O(line length).
class LineReader
{
public:
  // O(1).
  explicit LineReader(std::string_view text) : m_text(text) {}

  // The next line, false past the end. O(line length).
  bool next(std::string_view& line)
  {
    if (m_pos >= m_text.size())
      return false;
    const std::size_t end = m_text.find('\n', m_pos);
    const std::size_t stop = end == std::string_view::npos ? m_text.size() : end;
    line = m_text.substr(m_pos, stop - m_pos);
    if (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    m_pos = stop + 1;
    ++m_lineNumber;
    return true;
  }

  // 1-based number of the line last returned. O(1).
  [[nodiscard]] std::size_t lineNumber() const { return m_lineNumber; }

private:
  std::string_view m_text;
  std::size_t m_pos = 0;
  std::size_t m_lineNumber = 0;
};

// Calls f(index, trimmed cell) for each cell: tab-separated when the line has a tab, otherwise
// separated by runs of blanks (some writers pad with spaces). O(line length).
template <typename F>
void forEachCell(std::string_view line, F&& f)
{
  std::size_t index = 0;
  if (line.find('\t') != std::string_view::npos) {
    std::size_t start = 0;
    while (true) {
      const std::size_t end = line.find('\t', start);
      const std::size_t stop = end == std::string_view::npos ? line.size() : end;
      f(index++, trim(line.substr(start, stop - start)));
      if (end == std::string_view::npos)
        return;
      start = end + 1;
    }
  }
  std::size_t pos = 0;
  while (true) {
    while (pos < line.size() && isBlank(line[pos]))
      ++pos;
    if (pos >= line.size())
      return;
    const std::size_t start = pos;
    while (pos < line.size() && !isBlank(line[pos]))
      ++pos;
    f(index++, line.substr(start, pos - start));
  }
}

// All cells of a line, trailing empty ones dropped. O(line length).
std::vector<std::string_view> cellsOf(std::string_view line)
{
  std::vector<std::string_view> cells;
  forEachCell(line, [&](std::size_t, std::string_view cell) { cells.push_back(cell); });
  while (!cells.empty() && cells.back().empty())
    cells.pop_back();
  return cells;
}

// Blank-run tokens of a line. O(line length).
std::vector<std::string_view> blankTokens(std::string_view line)
{
  std::vector<std::string_view> tokens;
  std::size_t pos = 0;
  while (true) {
    while (pos < line.size() && isBlank(line[pos]))
      ++pos;
    if (pos >= line.size())
      return tokens;
    const std::size_t start = pos;
    while (pos < line.size() && !isBlank(line[pos]))
      ++pos;
    tokens.push_back(line.substr(start, pos - start));
  }
}

// A whole cell as an integer; "12.0" is accepted as some writers print counts as reals. O(cell).
bool parseInteger(std::string_view cell, std::int64_t& value)
{
  std::string_view digits = cell;
  if (!digits.empty() && digits.front() == '+')
    digits.remove_prefix(1);
  if (digits.empty())
    return false;
  const char* end = digits.data() + digits.size();
  const auto result = std::from_chars(digits.data(), end, value);
  if (result.ec == std::errc() && result.ptr == end)
    return true;
  double real = 0.0;
  constexpr double kLimit = 9007199254740992.0;  // 2^53: every integer below is exact
  if (!parseNumber(cell, real) || !std::isfinite(real) || std::fabs(real) > kLimit ||
      std::trunc(real) != real)
    return false;
  value = static_cast<std::int64_t>(real);
  return true;
}

// At most 40 characters of untrusted text for an error message. O(1).
std::string excerpt(std::string_view text)
{
  constexpr std::size_t kMax = 40;
  return text.size() <= kMax ? std::string(text) : std::string(text.substr(0, kMax)) + "...";
}

class TrcParser
{
public:
  // O(1).
  TrcParser(std::string_view text, const std::string& sourceName, std::vector<std::string>* warnings,
            std::vector<std::string>* dataLoss)
      : m_text(text), m_source(sourceName), m_warnings(warnings), m_dataLoss(dataLoss)
  {
  }

  // O(text size + #frames · #markers).
  Take parse()
  {
    constexpr std::string_view kBom = "\xEF\xBB\xBF";
    if (m_text.substr(0, kBom.size()) == kBom)
      m_text.remove_prefix(kBom.size());
    LineReader reader(m_text);
    std::string_view line;

    std::vector<std::string_view> magic;
    if (reader.next(line))
      magic = blankTokens(line);
    if (magic.empty() || !equalsIgnoreCase(magic.front(), "PathFileType"))
      fail(1, "not a TRC file (expected PathFileType)");
    std::string_view namesLine;
    std::string_view valuesLine;
    if (!reader.next(namesLine) || !reader.next(valuesLine))
      fail(reader.lineNumber() + 1, "file ends inside the header");
    readHeaderValues(namesLine, valuesLine);

    std::string_view labelLine;
    if (!reader.next(labelLine))
      fail(4, "file ends before the marker labels");
    std::vector<std::string> labels = readLabels(labelLine);

    // Line 5 names the coordinates; a file without it starts its rows here.
    LineReader data = reader;
    if (reader.next(line) && !isDataRow(line))
      data = reader;

    // First pass counts rows so the take is allocated once, after checking the size is sane.
    std::size_t rows = 0;
    LineReader counter = data;
    while (counter.next(line))
      if (!trim(line).empty())
        ++rows;
    const std::size_t markers = labels.size();
    if (markers > 0 && rows > (m_text.size() + kSampleAllowance) / markers)
      fail(3, std::to_string(rows) + " rows of " + std::to_string(markers) +
                  " markers are too many for a file of " + std::to_string(m_text.size()) + " bytes");
    if (m_numFrames && static_cast<std::size_t>(*m_numFrames) > rows && m_dataLoss)
      m_dataLoss->push_back("NumFrames is " + std::to_string(*m_numFrames) + " but the file has only " +
                            std::to_string(rows) + " data rows: the file is truncated");
    if (m_numFrames && static_cast<std::size_t>(*m_numFrames) != rows)
      warn("NumFrames is " + std::to_string(*m_numFrames) + " but the file has " + std::to_string(rows) +
           " data rows; read " + std::to_string(rows) + " frames");

    for (std::string& warning : makeLabelsUnique(labels))
      warn(std::move(warning));
    Take take(std::move(labels), static_cast<Eigen::Index>(rows), m_rate);
    take.setUnits(m_units);
    if (m_origStartFrame)
      take.setFirstFrame(*m_origStartFrame);

    Eigen::Index row = 0;
    while (data.next(line)) {
      if (trim(line).empty())
        continue;
      readRow(line, data.lineNumber(), row, take);
      ++row;
    }
    for (std::string& warning : takePlausibilityWarnings(take, m_unitDeclared))
      warn(std::move(warning));
    return take;
  }

private:
  // O(message length).
  [[noreturn]] void fail(std::size_t line, const std::string& message) const
  {
    throw FormatError(m_source, "line " + std::to_string(line) + ": " + message);
  }

  // O(1) amortized.
  void warn(std::string message)
  {
    if (m_warnings)
      m_warnings->push_back(std::move(message));
  }

  // Lines 2 and 3. Tab cells keep empty values aligned; blank tokens cope with space padding.
  // O(line lengths · #header fields).
  void readHeaderValues(std::string_view namesLine, std::string_view valuesLine)
  {
    std::vector<std::string_view> names = cellsOf(namesLine);
    std::vector<std::string_view> values = cellsOf(valuesLine);
    bool aligned = names.size() == values.size();
    for (std::string_view name : names)
      aligned = aligned && name.find(' ') == std::string_view::npos;
    if (!aligned) {
      names = blankTokens(namesLine);
      values = blankTokens(valuesLine);
    }
    if (names.size() != values.size())
      warn("line 3: " + std::to_string(values.size()) + " values for " + std::to_string(names.size()) +
           " header names");
    const auto value = [&](std::string_view key) -> std::optional<std::string_view> {
      for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
        if (equalsIgnoreCase(names[i], key))
          return values[i];
      return std::nullopt;
    };

    double rate = 0.0;
    const auto dataRate = value("DataRate");
    if (dataRate && parseNumber(*dataRate, rate) && std::isfinite(rate) && rate > 0.0) {
      m_rate = rate;
    } else {
      const auto cameraRate = value("CameraRate");
      if (!cameraRate || !parseNumber(*cameraRate, rate) || !std::isfinite(rate) || rate <= 0.0)
        fail(3, "no valid DataRate or CameraRate");
      warn("line 3: no valid DataRate; using CameraRate " + std::string(*cameraRate));
      m_rate = rate;
    }

    std::int64_t count = 0;
    const auto numMarkers = value("NumMarkers");
    if (!numMarkers || !parseInteger(*numMarkers, count) || count < 0)
      fail(3, "no valid NumMarkers");
    // Each marker needs at least a label and a separator somewhere in the text.
    if (static_cast<std::uint64_t>(count) > m_text.size() / 2)
      fail(3, "NumMarkers " + std::to_string(count) + " is too large for a file of " +
                  std::to_string(m_text.size()) + " bytes");
    m_numMarkers = static_cast<std::size_t>(count);

    const auto numFrames = value("NumFrames");
    if (numFrames && parseInteger(*numFrames, count) && count >= 0)
      m_numFrames = count;
    else
      warn("line 3: no valid NumFrames; counting the data rows");

    const auto units = value("Units");
    const auto unit = units ? parseLengthUnit(*units) : std::nullopt;
    m_unitDeclared = unit.has_value();
    if (unit)
      m_units = *unit;
    else if (units)
      warn("line 3: unknown Units '" + excerpt(*units) + "'; assuming mm");
    else
      warn("line 3: no Units; assuming mm");

    const auto startFrame = value("OrigDataStartFrame");
    if (startFrame && parseInteger(*startFrame, count) && inFrameRange(count))
      m_origStartFrame = count;
  }

  // Line 4: `Frame# Time L1 <tab> <tab> L2 ...`. Labels sit every third cell; when the padding
  // cells are not empty (sloppy writers) the non-empty cells are taken in order. O(line length).
  std::vector<std::string> readLabels(std::string_view line)
  {
    std::vector<std::string_view> cells;
    forEachCell(line, [&](std::size_t, std::string_view cell) { cells.push_back(cell); });
    bool positional = true;
    std::size_t found = 0;
    for (std::size_t i = 2; i < cells.size(); ++i) {
      if (cells[i].empty())
        continue;
      ++found;
      positional = positional && (i - 2) % 3 == 0;
    }
    std::vector<std::string> labels(m_numMarkers);
    if (positional) {
      for (std::size_t m = 0; m < m_numMarkers && 2 + 3 * m < cells.size(); ++m)
        labels[m] = std::string(cells[2 + 3 * m]);
    } else {
      std::size_t m = 0;
      for (std::size_t i = 2; i < cells.size() && m < m_numMarkers; ++i)
        if (!cells[i].empty())
          labels[m++] = std::string(cells[i]);
    }
    if (found != m_numMarkers)
      warn("line 4: " + std::to_string(found) + " labels for NumMarkers " + std::to_string(m_numMarkers));
    return labels;
  }

  // A row starts with an integer frame number; the coordinate-name line starts with an empty cell.
  // O(line length).
  static bool isDataRow(std::string_view line)
  {
    std::string_view first;
    bool any = false;
    forEachCell(line, [&](std::size_t index, std::string_view cell) {
      if (index == 0) {
        first = cell;
        any = true;
      }
    });
    std::int64_t frame = 0;
    return any && parseInteger(first, frame);
  }

  // One data row into frame `row` of `take`. O(line length).
  void readRow(std::string_view line, std::size_t lineNumber, Eigen::Index row, Take& take)
  {
    const std::size_t markers = static_cast<std::size_t>(take.markerCount());
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    bool extra = false;
    forEachCell(line, [&](std::size_t index, std::string_view cell) {
      if (index == 0) {
        readFrameNumber(cell, lineNumber, row, take);
        return;
      }
      double value = std::numeric_limits<double>::quiet_NaN();
      if (!cell.empty() && !parseNumber(cell, value))
        fail(lineNumber, "bad number '" + excerpt(cell) + "' in column " + std::to_string(index + 1));
      if (index == 1)
        return;  // time is implied by the frame rate
      const std::size_t marker = (index - 2) / 3;
      const std::size_t axis = (index - 2) % 3;
      if (marker >= markers) {
        extra = extra || !cell.empty();
        return;
      }
      xyz[static_cast<Eigen::Index>(axis)] = value;
      if (axis == 2 && xyz.allFinite()) {
        const auto m = static_cast<Eigen::Index>(marker);
        take.setPosition(row, m, xyz);
        take.valid()(row, m) = true;
        take.residuals()(row, m) = 0.0;
      }
    });
    if (extra && !m_warnedExtraCells) {
      m_warnedExtraCells = true;
      warn("line " + std::to_string(lineNumber) + ": cells beyond NumMarkers ignored");
    }
  }

  // O(cell length).
  void readFrameNumber(std::string_view cell, std::size_t lineNumber, Eigen::Index row, Take& take)
  {
    std::int64_t frame = 0;
    if (!parseInteger(cell, frame))
      fail(lineNumber, "bad frame number '" + excerpt(cell) + "'");
    if (!inFrameRange(frame))
      fail(lineNumber, "frame number " + std::to_string(frame) + " out of range");
    if (row == 0) {
      take.setFirstFrame(frame);
    } else if (frame != m_previousFrame + 1 && !m_warnedFrameNumbers) {
      m_warnedFrameNumbers = true;
      warn("line " + std::to_string(lineNumber) + ": frame " + std::to_string(frame) + " does not follow " +
           std::to_string(m_previousFrame) + "; rows are read in file order");
    }
    m_previousFrame = frame;
  }

  std::string_view m_text;
  const std::string& m_source;
  std::vector<std::string>* m_warnings;
  std::vector<std::string>* m_dataLoss;
  double m_rate = 0.0;
  std::size_t m_numMarkers = 0;
  std::optional<std::int64_t> m_numFrames;
  std::optional<std::int64_t> m_origStartFrame;
  LengthUnit m_units = LengthUnit::Millimetre;
  bool m_unitDeclared = false;  // line 3's Units names a length unit
  std::int64_t m_previousFrame = 0;
  bool m_warnedExtraCells = false;
  bool m_warnedFrameNumbers = false;
};


// Tabs and line breaks would split the cell; blanks around it would be trimmed on reading. O(n).
std::string cellText(std::string_view text)
{
  std::string out(text);
  for (char& c : out)
    if (c == '\t' || c == '\r' || c == '\n')
      c = ' ';
  return std::string(trim(out));
}

} // namespace

Take readTrc(const std::filesystem::path& path, std::vector<std::string>* warnings, std::vector<std::string>* dataLoss)
{
  return parseTrc(readFileBytes(path), path.string(), warnings, dataLoss);
}

Take parseTrc(std::string_view text, const std::string& sourceName, std::vector<std::string>* warnings,
              std::vector<std::string>* dataLoss)
{
  return TrcParser(text, sourceName, warnings, dataLoss).parse();
}

std::string formatTrc(const Take& take, std::string_view fileName)
{
  if (const std::optional<Take> markers = withoutModelOutputs(take, "a TRC file"))
    return formatTrc(*markers, fileName);
  const Eigen::Index frames = take.frameCount();
  const Eigen::Index markers = take.markerCount();
  std::string out;
  out += "PathFileType\t4\t(X/Y/Z)\t";
  out += cellText(fileName);
  out += "\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\t"
         "OrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  appendNumber(out, take.frameRate());
  out += '\t';
  appendNumber(out, take.frameRate());
  out += '\t' + std::to_string(frames) + '\t' + std::to_string(markers) + '\t';
  out += unitName(take.units());
  out += '\t';
  appendNumber(out, take.frameRate());
  out += '\t' + std::to_string(take.firstFrame()) + '\t' + std::to_string(frames) + '\n';

  out += "Frame#\tTime";
  for (const std::string& label : take.labels())
    out += '\t' + cellText(label) + "\t\t";
  out += "\n\t";
  for (Eigen::Index m = 1; m <= markers; ++m) {
    const std::string n = std::to_string(m);
    out += "\tX" + n + "\tY" + n + "\tZ" + n;
  }
  out += "\n\n";

  appendSampleRows(out, take, '\t');
  return out;
}

void writeTrc(const Take& take, const std::filesystem::path& path)
{
  writeFileAtomically(path, formatTrc(take, path.filename().string()));
}

} // namespace mocap
