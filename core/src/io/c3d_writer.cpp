#include "mocap/io/c3d_writer.h"

#include "mocap/io/c3d_binary.h"
#include "mocap/io/c3d_point_types.h"
#include "mocap/io/c3d_string_lists.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/model/provenance.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mocap {

namespace {

constexpr std::size_t kMaxArrayEntries = 255;  // a C3D dimension is one byte

/// Residual resolution: the file's own |POINT:SCALE| converted to the take's current units, so
/// residuals from integer files come back exact; 1 mm otherwise.
double residualScale(const Take& take)
{
  const C3dParameterTree& tree = take.parameters();
  double scale = std::abs(tree.number("POINT", "SCALE").value_or(0.0));
  if (!std::isfinite(scale) || scale == 0.0)
    return 1.0 / millimetresPer(take.units());
  const auto fileUnit = parseLengthUnit(tree.string("POINT", "UNITS").value_or("mm"));
  if (fileUnit)
    scale *= millimetresPer(*fileUnit) / millimetresPer(take.units());
  return scale;
}

void setFieldPair(C3dParameterTree& tree, const std::string& name, std::int64_t value)
{
  const auto v = static_cast<std::uint64_t>(std::max<std::int64_t>(value, 0));
  tree.set("TRIAL", C3dParameter::makeInt16(name, {static_cast<int>(v & 0xFFFFu), static_cast<int>((v >> 16) & 0xFFFFu)},
                                            false));
}

class C3dEncoder
{
public:
  explicit C3dEncoder(const Take& take) : m_take(take), m_tree(take.parameters()) {}

  std::string encode()
  {
    if (m_take.markerCount() > 65535)
      throw InvalidArgument("C3D holds at most 65535 markers, the take has " + std::to_string(m_take.markerCount()));
    m_scale = residualScale(m_take);
    updatePointGroup();
    updateAnalogGroup();
    updateTrialGroup();
    updateEventGroup();
    storeProvenance(m_take, m_tree);
    // DATA_START depends on the parameter section's size, which does not depend on its value.
    m_tree.set("POINT", C3dParameter::makeInt16("DATA_START", {0}, true));
    m_dataBlock = 2 + encodeParameters().size() / c3d::kBlockSize;
    m_tree.set("POINT", C3dParameter::makeInt16("DATA_START", {static_cast<int>(m_dataBlock)}, true));

    std::string out = encodeHeader();
    out += encodeParameters();
    encodeData(out);
    return out;
  }

private:
  [[nodiscard]] std::size_t channelCount() const { return static_cast<std::size_t>(m_take.analog().channelCount()); }
  [[nodiscard]] std::size_t samplesPerFrame() const
  {
    const auto frames = static_cast<std::size_t>(m_take.frameCount());
    if (channelCount() == 0 || frames == 0)
      return 0;
    return static_cast<std::size_t>(m_take.analog().sampleCount()) / frames;
  }

  void updatePointGroup()
  {
    writeC3dPointTypes(m_take, m_tree);  // first: the group's own parameters below win any clash
    const auto markers = static_cast<int>(m_take.markerCount());
    const auto frames = static_cast<int>(std::min<Eigen::Index>(m_take.frameCount(), 65535));
    m_tree.set("POINT", C3dParameter::makeInt16("USED", {markers}, true));
    m_tree.set("POINT", C3dParameter::makeInt16("FRAMES", {frames}, true));
    m_tree.set("POINT", C3dParameter::makeFloat("SCALE", {-m_scale}, true));
    m_tree.set("POINT", C3dParameter::makeFloat("RATE", {m_take.frameRate()}, true));
    m_tree.set("POINT", C3dParameter::makeStrings("UNITS", {std::string(unitName(m_take.units()))}));
    setC3dStringsAcrossParts(m_tree, "POINT", "LABELS", m_take.labels());
    std::vector<std::string> descriptions;
    for (int part = 1;; ++part) {
      const C3dParameter* p = m_tree.find("POINT", part == 1 ? "DESCRIPTIONS" : "DESCRIPTIONS" + std::to_string(part));
      if (!p)
        break;
      const auto more = p->strings();
      descriptions.insert(descriptions.end(), more.begin(), more.end());
    }
    descriptions.resize(m_take.labels().size());
    setC3dStringsAcrossParts(m_tree, "POINT", "DESCRIPTIONS", descriptions);
  }

  void updateAnalogGroup()
  {
    const AnalogData& analog = m_take.analog();
    if (channelCount() == 0 && !m_tree.group("ANALOG"))
      return;
    if (channelCount() > kMaxArrayEntries)
      throw InvalidArgument("writing more than 255 analog channels is not supported");
    std::vector<std::string> labels, descriptions, units;
    std::vector<double> scales;
    std::vector<int> offsets;
    for (const AnalogChannel& c : analog.channels) {
      labels.push_back(c.label);
      descriptions.push_back(c.description);
      units.push_back(c.unit);
      scales.push_back(c.scale);
      offsets.push_back(static_cast<int>(c.offset));
    }
    m_tree.set("ANALOG", C3dParameter::makeInt16("USED", {static_cast<int>(channelCount())}, true));
    if (channelCount() == 0)
      return;
    m_tree.set("ANALOG", C3dParameter::makeFloat("RATE", {analog.rate}, true));
    m_tree.set("ANALOG", C3dParameter::makeFloat("GEN_SCALE", {analog.generalScale}, true));
    m_tree.set("ANALOG", C3dParameter::makeFloat("SCALE", scales, false));
    m_tree.set("ANALOG", C3dParameter::makeInt16("OFFSET", offsets, false));
    setC3dStringsAcrossParts(m_tree, "ANALOG", "LABELS", labels);
    setC3dStringsAcrossParts(m_tree, "ANALOG", "DESCRIPTIONS", descriptions);
    setC3dStringsAcrossParts(m_tree, "ANALOG", "UNITS", units);
  }

  void updateTrialGroup()
  {
    const std::int64_t first = m_take.firstFrame();
    const std::int64_t last = first + std::max<std::int64_t>(m_take.frameCount(), 1) - 1;
    if (last > 65535 || m_tree.find("TRIAL", "ACTUAL_START_FIELD")) {
      setFieldPair(m_tree, "ACTUAL_START_FIELD", first);
      setFieldPair(m_tree, "ACTUAL_END_FIELD", last);
    }
  }

  void updateEventGroup()
  {
    const auto& events = m_take.events();
    if (events.empty() && !m_tree.group("EVENT"))
      return;
    if (events.size() > kMaxArrayEntries)
      throw InvalidArgument("writing more than 255 events is not supported");
    std::vector<double> times;
    std::vector<std::string> labels, contexts, descriptions, subjects;
    for (const Event& e : events) {
      times.push_back(0.0);  // (minutes, seconds) pairs; all time goes into seconds
      times.push_back(e.time);
      labels.push_back(e.label);
      contexts.push_back(e.context);
      descriptions.push_back(e.description);
      subjects.push_back(e.subject);
    }
    m_tree.set("EVENT", C3dParameter::makeInt16("USED", {static_cast<int>(events.size())}, true));
    C3dParameter timesParameter = C3dParameter::makeFloat("TIMES", times, false);
    timesParameter.dimensions = {2, static_cast<int>(events.size())};
    m_tree.set("EVENT", std::move(timesParameter));
    m_tree.set("EVENT", C3dParameter::makeStrings("LABELS", labels));
    m_tree.set("EVENT", C3dParameter::makeStrings("CONTEXTS", contexts));
    m_tree.set("EVENT", C3dParameter::makeStrings("DESCRIPTIONS", descriptions));
    m_tree.set("EVENT", C3dParameter::makeStrings("SUBJECTS", subjects));
    for (const char* perEvent : {"ICON_IDS", "GENERIC_FLAGS"}) {
      const C3dParameter* p = m_tree.find("EVENT", perEvent);
      if (p && p->elementCount() != events.size())
        m_tree.remove("EVENT", perEvent);
    }
  }

  static void appendName(std::string& out, const std::string& name, bool locked, int id)
  {
    const std::string clipped = name.substr(0, 127);
    const auto length = static_cast<int>(clipped.size());
    c3d::appendU8(out, static_cast<std::uint8_t>(static_cast<std::int8_t>(locked ? -length : length)));
    c3d::appendU8(out, static_cast<std::uint8_t>(static_cast<std::int8_t>(id)));
    out += clipped;
  }

  static void appendDescription(std::string& out, const std::string& description)
  {
    const std::string clipped = description.substr(0, 255);
    c3d::appendU8(out, static_cast<std::uint8_t>(clipped.size()));
    out += clipped;
  }

  static void appendParameterBody(std::string& out, const C3dParameter& p)
  {
    if (p.dimensions.size() > 7)
      throw InvalidArgument("parameter " + p.name + " has more than 7 dimensions");
    c3d::appendU8(out, static_cast<std::uint8_t>(static_cast<std::int8_t>(p.type)));
    c3d::appendU8(out, static_cast<std::uint8_t>(p.dimensions.size()));
    for (int d : p.dimensions) {
      if (d < 0 || d > 255)
        throw InvalidArgument("parameter " + p.name + " has a dimension of " + std::to_string(d) + " (max 255)");
      c3d::appendU8(out, static_cast<std::uint8_t>(d));
    }
    const std::size_t count = p.elementCount();
    switch (p.type) {
    case C3dType::Char: {
      std::string chars = p.chars;
      chars.resize(count, ' ');
      out += chars;
      break;
    }
    case C3dType::Byte:
      for (std::size_t i = 0; i < count; ++i)
        c3d::appendU8(out, static_cast<std::uint8_t>(i < p.numbers.size() ? p.numbers[i] : 0.0));
      break;
    case C3dType::Int16:
      for (std::size_t i = 0; i < count; ++i)
        c3d::appendI16(out, static_cast<std::int16_t>(i < p.numbers.size() ? p.numbers[i] : 0.0));
      break;
    case C3dType::Float:
      for (std::size_t i = 0; i < count; ++i)
        c3d::appendF32(out, static_cast<float>(i < p.numbers.size() ? p.numbers[i] : 0.0));
      break;
    }
    appendDescription(out, p.description);
  }

  /// Appends one record; its link word points just past it (patched to 0 for the last record).
  static std::size_t appendRecord(std::string& out, const std::string& name, bool locked, int id,
                                  const std::string& body)
  {
    appendName(out, name, locked, id);
    const std::size_t linkAt = out.size();
    const std::size_t link = body.size() + 2;
    if (link > 32767)
      throw InvalidArgument("C3D parameter " + name + " is too large (" + std::to_string(body.size()) + " bytes)");
    c3d::appendI16(out, static_cast<std::int16_t>(link));
    out += body;
    return linkAt;
  }

  std::string encodeParameters() const
  {
    std::string out;
    out.push_back(1);
    out.push_back(static_cast<char>(c3d::kKeyByte));
    out.push_back(0);  // block count, patched below
    out.push_back(static_cast<char>(c3d::Processor::Intel));
    std::size_t lastLink = 0;
    for (const C3dGroup& group : m_tree.groups()) {
      if (group.id < 1 || group.id > 127)
        throw InvalidArgument("C3D group " + group.name + " has id " + std::to_string(group.id));
      std::string body;
      appendDescription(body, group.description);
      lastLink = appendRecord(out, group.name, group.locked, -group.id, body);
      for (const C3dParameter& p : group.parameters) {
        body.clear();
        appendParameterBody(body, p);
        lastLink = appendRecord(out, p.name, p.locked, group.id, body);
      }
    }
    if (lastLink != 0)
      c3d::putI16(out, lastLink, 0);
    out.resize(((out.size() + 1 + c3d::kBlockSize - 1) / c3d::kBlockSize) * c3d::kBlockSize, '\0');
    const std::size_t blocks = out.size() / c3d::kBlockSize;
    if (blocks > 255)
      throw InvalidArgument("C3D parameter section exceeds 255 blocks");
    out[2] = static_cast<char>(blocks);
    return out;
  }

  std::string encodeHeader() const
  {
    std::string header(c3d::kBlockSize, '\0');
    header[0] = 2;
    header[1] = static_cast<char>(c3d::kKeyByte);
    const std::int64_t first = std::clamp<std::int64_t>(m_take.firstFrame(), 1, 65535);
    const std::int64_t last = std::min<std::int64_t>(first + std::max<Eigen::Index>(m_take.frameCount(), 1) - 1, 65535);
    c3d::putI16(header, 2, static_cast<std::int16_t>(m_take.markerCount()));
    c3d::putI16(header, 4, static_cast<std::int16_t>(channelCount() * samplesPerFrame()));
    c3d::putI16(header, 6, static_cast<std::int16_t>(first));
    c3d::putI16(header, 8, static_cast<std::int16_t>(last));
    c3d::putF32(header, 12, static_cast<float>(-m_scale));
    c3d::putI16(header, 16, static_cast<std::int16_t>(m_dataBlock));
    c3d::putI16(header, 18, static_cast<std::int16_t>(samplesPerFrame()));
    c3d::putF32(header, 20, static_cast<float>(m_take.frameRate()));
    encodeHeaderEvents(header);
    return header;
  }

  void encodeHeaderEvents(std::string& header) const
  {
    const auto& events = m_take.events();
    const std::size_t count = std::min<std::size_t>(events.size(), 18);
    c3d::putI16(header, 298, static_cast<std::int16_t>(c3d::kEventKey));
    c3d::putI16(header, 300, static_cast<std::int16_t>(count));
    for (std::size_t i = 0; i < count; ++i) {
      c3d::putF32(header, 304 + 4 * i, static_cast<float>(events[i].time));
      header[376 + i] = 1;  // display flag
      std::string label = events[i].label.substr(0, 4);
      label.resize(4, ' ');
      header.replace(396 + 4 * i, 4, label);
    }
  }

  void encodeData(std::string& out) const
  {
    const auto frames = m_take.frameCount();
    const auto markers = m_take.markerCount();
    const std::size_t analogPerFrame = channelCount() * samplesPerFrame();
    const std::size_t frameBytes = (static_cast<std::size_t>(markers) * 4 + analogPerFrame) * 4;
    const std::size_t start = (m_dataBlock - 1) * c3d::kBlockSize;
    out.resize(start + static_cast<std::size_t>(frames) * frameBytes);
    const double* positions = m_take.positionData();
    const auto& valid = m_take.valid();
    const auto& residuals = m_take.residuals();
    const auto& cameras = m_take.cameraMasks();
    const auto& states = m_take.states();
    std::vector<float> frame(frameBytes / 4);
    for (Eigen::Index f = 0; f < frames; ++f) {
      float* p = frame.data();
      for (Eigen::Index m = 0; m < markers; ++m, p += 4) {
        if (!valid(f, m)) {
          p[0] = p[1] = p[2] = 0.0f;
          p[3] = -1.0f;
          continue;
        }
        const double* block = positions + m * frames * 3;
        p[0] = static_cast<float>(block[f]);
        p[1] = static_cast<float>(block[f + frames]);
        p[2] = static_cast<float>(block[f + 2 * frames]);
        // C3D convention: residual 0 marks a computed point, so a filled sample is written with 0
        // and a measured one never rounds down to 0. Camera bits are kept as read.
        const double measured = residuals(f, m) / m_scale;
        const double residual = SampleState::fromBits(states(f, m)).origin() == SampleOrigin::Filled ? 0.0
                                : measured > 0.0 ? std::clamp(std::round(measured), 1.0, 255.0)
                                                 : 0.0;
        p[3] = static_cast<float>((static_cast<unsigned>(cameras(f, m) & 0x7Fu) << 8) | static_cast<unsigned>(residual));
      }
      encodeAnalogFrame(f, p);
      std::memcpy(&out[start + static_cast<std::size_t>(f) * frameBytes], frame.data(), frameBytes);
    }
  }

  void encodeAnalogFrame(Eigen::Index frame, float* p) const
  {
    const auto& stored = m_take.analog().stored;
    const auto samples = static_cast<Eigen::Index>(samplesPerFrame());
    for (Eigen::Index s = 0; s < samples; ++s)
      for (Eigen::Index c = 0; c < stored.cols(); ++c)
        *p++ = static_cast<float>(stored(frame * samples + s, c));
  }

  const Take& m_take;
  C3dParameterTree m_tree;
  double m_scale = 1.0;
  std::size_t m_dataBlock = 2;
};

} // namespace

std::string encodeC3d(const Take& take)
{
  return C3dEncoder(take).encode();
}

void writeC3d(const Take& take, const std::filesystem::path& path)
{
  writeFileAtomically(path, encodeC3d(take));
}

} // namespace mocap
