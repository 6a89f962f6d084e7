#include "mocap/io/c3d_reader.h"

#include "mocap/io/c3d_binary.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/model/provenance.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <cmath>
#include <map>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the C3D reader's Intel fast path assumes a little-endian host"
#endif

namespace mocap {

namespace {

using c3d::Processor;

/// The fixed-position fields of the 512-byte header block.
struct Header
{
  std::size_t parameterBlock = 0;
  std::uint16_t pointCount = 0;
  std::uint16_t analogValuesPerFrame = 0;  // all channels × samples per frame
  std::uint16_t firstFrame = 0;
  std::uint16_t lastFrame = 0;
  float scale = 0.0f;
  std::uint16_t dataBlock = 0;
  std::uint16_t analogSamplesPerFrame = 0;
  float frameRate = 0.0f;
};

/// How the data section is laid out, resolved from header and parameters.
struct DataLayout
{
  std::size_t offset = 0;
  std::size_t pointCount = 0;
  std::size_t analogValuesPerFrame = 0;
  std::size_t channelCount = 0;
  std::size_t samplesPerFrame = 0;
  std::size_t frameCount = 0;
  std::int64_t firstFrame = 1;
  bool isFloat = false;
  bool analogUnsigned = false;
  double scale = 1.0;
  double frameRate = 0.0;

  [[nodiscard]] std::size_t bytesPerValue() const { return isFloat ? 4 : 2; }
  [[nodiscard]] std::size_t frameBytes() const
  {
    return (pointCount * 4 + analogValuesPerFrame) * bytesPerValue();
  }
};

bool isTextName(std::string_view name)
{
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F; });
}

/// Where one marker's samples go: its coordinate columns and per-sample arrays, by frame.
struct MarkerColumns
{
  double* x;
  double* y;
  double* z;
  bool* valid;
  double* residuals;
  std::uint8_t* cameras;
};

/// One stored sample (x, y, z, residual word at `p`, `bpv` bytes each) into frame `f` of `out`.
/// A sample is valid when its word is ≥ 0 and its coordinates are finite; the word's low byte
/// is the residual (× `residualScale`), bits 8–14 the cameras that saw it. O(1).
template <typename Decode>
void decodeSample(const unsigned char* p, std::size_t bpv, double coordinateScale, double residualScale,
                  Decode decode, const MarkerColumns& out, std::size_t f, ResidualCounts& counts)
{
  const double word = decode(p + 3 * bpv);
  const double xv = decode(p) * coordinateScale;
  const double yv = decode(p + bpv) * coordinateScale;
  const double zv = decode(p + 2 * bpv) * coordinateScale;
  const bool ok = word >= 0.0 && std::isfinite(xv + yv + zv);
  out.x[f] = xv;
  out.y[f] = yv;
  out.z[f] = zv;
  out.valid[f] = ok;
  const auto bits = ok ? static_cast<std::uint32_t>(std::min(word, 65535.0)) : 0u;
  const double residual = ok ? static_cast<double>(bits & 0xFFu) * residualScale : -1.0;
  out.residuals[f] = residual;
  counts.valid += ok ? 1 : 0;
  counts.zero += residual == 0.0 ? 1 : 0;  // (an invalid sample's -1 is never 0)
  out.cameras[f] = static_cast<std::uint8_t>((bits >> 8) & 0x7Fu);
}

#if defined(__SSE2__)
/// decodeSample for two frames of an Intel float file at once (records at `p` and `p` +
/// `frameBytes` into frames `f`, `f` + 1): the two 4-float records are widened and transposed
/// into x, y, z and word pairs, so each column gets one 16-byte store and the tests run on both
/// lanes. The same operations in the same order as decodeSample (the coordinate scale of a float
/// file is 1), so the results are identical. O(1).
void decodeIntelFloatPair(const unsigned char* p, std::size_t frameBytes, double residualScale,
                          const MarkerColumns& out, std::size_t f, ResidualCounts& counts)
{
  const __m128 a = _mm_loadu_ps(reinterpret_cast<const float*>(p));
  const __m128 b = _mm_loadu_ps(reinterpret_cast<const float*>(p + frameBytes));
  const __m128d aXY = _mm_cvtps_pd(a), aZW = _mm_cvtps_pd(_mm_movehl_ps(a, a));
  const __m128d bXY = _mm_cvtps_pd(b), bZW = _mm_cvtps_pd(_mm_movehl_ps(b, b));
  const __m128d x = _mm_unpacklo_pd(aXY, bXY), y = _mm_unpackhi_pd(aXY, bXY);
  const __m128d z = _mm_unpacklo_pd(aZW, bZW), word = _mm_unpackhi_pd(aZW, bZW);
  _mm_storeu_pd(out.x + f, x);
  _mm_storeu_pd(out.y + f, y);
  _mm_storeu_pd(out.z + f, z);
  const __m128d zero = _mm_setzero_pd();
  // x + y + z is finite exactly when (x + y + z) · 0 is 0 (NaN otherwise).
  const __m128d finite = _mm_cmpeq_pd(_mm_mul_pd(_mm_add_pd(_mm_add_pd(x, y), z), zero), zero);
  const __m128d ok = _mm_and_pd(_mm_cmpge_pd(word, zero), finite);
  // The words truncated to integers; the 64-bit lane masks narrowed to the two 32-bit lanes.
  const __m128i okLanes = _mm_shuffle_epi32(_mm_castpd_si128(ok), _MM_SHUFFLE(2, 0, 2, 0));
  const __m128i bits = _mm_and_si128(_mm_cvttpd_epi32(_mm_min_pd(word, _mm_set1_pd(65535.0))), okLanes);
  const __m128d scaled =
      _mm_mul_pd(_mm_cvtepi32_pd(_mm_and_si128(bits, _mm_set1_epi32(0xFF))), _mm_set1_pd(residualScale));
  const __m128d residual = _mm_or_pd(_mm_and_pd(ok, scaled), _mm_andnot_pd(ok, _mm_set1_pd(-1.0)));
  _mm_storeu_pd(out.residuals + f, residual);
  const int okMask = _mm_movemask_pd(ok);
  const int zeroMask = _mm_movemask_pd(_mm_cmpeq_pd(residual, zero));
  out.valid[f] = (okMask & 1) != 0;
  out.valid[f + 1] = (okMask & 2) != 0;
  counts.valid += (okMask & 1) + (okMask >> 1);
  counts.zero += (zeroMask & 1) + (zeroMask >> 1);
  const auto first = static_cast<std::uint32_t>(_mm_cvtsi128_si32(bits));
  const auto second = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(bits, 1)));
  out.cameras[f] = static_cast<std::uint8_t>((first >> 8) & 0x7Fu);
  out.cameras[f + 1] = static_cast<std::uint8_t>((second >> 8) & 0x7Fu);
}
#endif

class C3dParser
{
public:
  C3dParser(const unsigned char* data, std::size_t size, const std::string& name,
            std::vector<std::string>* warnings, std::vector<std::string>* dataLoss)
      : m_data(data), m_size(size), m_name(name), m_warnings(warnings), m_dataLoss(dataLoss)
  {
  }

  Take parse()
  {
    readHeaderBlock();
    readParameters();
    const DataLayout layout = resolveLayout();
    Take take = makeTake(layout);
    decodeData(layout, take);
    readEvents(take);
    take.parameters() = std::move(m_tree);
    loadProvenance(take, m_warnings, m_residualCounts);
    return take;
  }

private:
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const
  {
    throw FormatError(m_name, offset, message);
  }

  void warn(const std::string& message)
  {
    if (m_warnings)
      m_warnings->push_back(message);
  }

  /// A warning that means data the file declares is missing from the take.
  void warnDataLoss(const std::string& message)
  {
    warn(message);
    if (m_dataLoss)
      m_dataLoss->push_back(message);
  }

  /// Throws "<what> truncated" unless bytes [offset, offset + count) are in the file.
  void require(std::size_t offset, std::size_t count, const char* what) const
  {
    if (offset > m_size || count > m_size - offset)
      fail(std::min(offset, m_size), std::string(what) + " truncated");
  }

  [[nodiscard]] std::uint16_t u16(std::size_t offset) const { return c3d::readU16(m_data + offset, m_processor); }
  [[nodiscard]] std::int16_t i16(std::size_t offset) const { return c3d::readI16(m_data + offset, m_processor); }
  [[nodiscard]] float f32(std::size_t offset) const { return c3d::readF32(m_data + offset, m_processor); }

  void readHeaderBlock()
  {
    if (m_size < c3d::kBlockSize)
      fail(m_size, "file too short for a C3D header (" + std::to_string(m_size) + " bytes)");
    if (m_data[1] != c3d::kKeyByte)
      fail(1, "not a C3D file (header key byte is " + std::to_string(m_data[1]) + ", expected 80)");
    m_header.parameterBlock = m_data[0];
    if (m_header.parameterBlock == 0)
      fail(0, "parameter section pointer is 0");
    m_parameterOffset = (m_header.parameterBlock - 1) * c3d::kBlockSize;
    require(m_parameterOffset, 4, "parameter section");
    const unsigned char processorByte = m_data[m_parameterOffset + 3];
    if (processorByte < 84 || processorByte > 86)
      fail(m_parameterOffset + 3, "unknown processor type " + std::to_string(processorByte) +
                                      " (expected 84 Intel, 85 DEC or 86 MIPS)");
    m_processor = static_cast<Processor>(processorByte);

    m_header.pointCount = u16(2);
    m_header.analogValuesPerFrame = u16(4);
    m_header.firstFrame = u16(6);
    m_header.lastFrame = u16(8);
    m_header.scale = f32(12);
    m_header.dataBlock = u16(16);
    m_header.analogSamplesPerFrame = u16(18);
    m_header.frameRate = f32(20);
  }

  void readParameters()
  {
    std::map<int, std::vector<C3dParameter>> parametersByGroup;
    std::size_t pos = m_parameterOffset + 4;
    while (true) {
      require(pos, 2, "parameter section");
      const auto nameLength = static_cast<std::int8_t>(m_data[pos]);
      const auto id = static_cast<std::int8_t>(m_data[pos + 1]);
      if (nameLength == 0 || id == 0)
        break;
      const auto length = static_cast<std::size_t>(std::abs(nameLength));
      require(pos + 2, length + 2, "parameter section");
      const std::string name(reinterpret_cast<const char*>(m_data + pos + 2), length);
      if (!isTextName(name))
        fail(pos + 2, "parameter section corrupt: a record name is binary data");
      const std::size_t offsetPos = pos + 2 + length;
      const std::int16_t link = i16(offsetPos);
      const std::size_t next = link == 0 ? m_size : offsetPos + static_cast<std::size_t>(std::max<int>(link, 0));
      if (link < 0 || (link > 0 && next <= pos))
        fail(offsetPos, "parameter section corrupt: record '" + name + "' links backwards (offset " +
                            std::to_string(link) + ")");
      const bool last = link == 0 || !continuesAt(next);
      require(offsetPos, (last ? std::min(next, m_size) : next) - offsetPos, "parameter section");
      const std::size_t limit = last ? std::min(next, m_size) : next;
      const std::size_t body = offsetPos + 2;
      if (id < 0) {
        C3dGroup group;
        group.id = -id;
        group.name = name;
        group.locked = nameLength < 0;
        group.description = readDescription(body, limit, name);
        m_tree.groups().push_back(std::move(group));
      } else {
        C3dParameter parameter = readParameter(body, limit, name);
        parameter.locked = nameLength < 0;
        parametersByGroup[id].push_back(std::move(parameter));
      }
      if (last)
        break;
      pos = next;
    }
    attachParameters(parametersByGroup);
  }

  /// Whether a link to `next` continues the section. Some writers (the SGI sample02 files) give
  /// the last record a link far past the section's declared end, into the data: a link beyond
  /// that end continues only when a plausible record (text name) sits there.
  bool continuesAt(std::size_t next)
  {
    const std::size_t declaredEnd = m_parameterOffset + std::size_t{m_data[m_parameterOffset + 2]} * c3d::kBlockSize;
    if (next < declaredEnd)
      return true;  // inside the section: follow it (require() reports a truncated file)
    if (next + 2 <= m_size && m_data[next] == 0)
      return true;  // a proper terminator: only the declared block count was too small
    const auto length = next + 2 <= m_size ? static_cast<std::size_t>(std::abs(static_cast<std::int8_t>(m_data[next]))) : 0;
    const bool plausible = length > 0 && m_data[next + 1] != 0 && next + 2 + length <= m_size &&
                           isTextName(std::string_view(reinterpret_cast<const char*>(m_data + next + 2), length));
    if (!plausible)
      warn("the last parameter links past the parameter section's end; the section ends there");
    return plausible;
  }

  /// A description: length byte then text, clipped to the record's end `limit`.
  std::string readDescription(std::size_t at, std::size_t limit, const std::string& owner)
  {
    if (at >= limit) {
      warn("parameter '" + owner + "' has no description-length byte; read as empty");
      return {};
    }
    std::size_t length = m_data[at];
    if (at + 1 + length > limit) {
      warn("description of '" + owner + "' runs past its record; clipped");
      length = limit - at - 1;
    }
    return std::string(trim(std::string_view(reinterpret_cast<const char*>(m_data + at + 1), length)));
  }

  C3dParameter readParameter(std::size_t body, std::size_t limit, const std::string& name)
  {
    C3dParameter p;
    p.name = name;
    if (body + 2 > limit)
      fail(body, "parameter '" + name + "' record too short");
    const auto type = static_cast<std::int8_t>(m_data[body]);
    if (type != -1 && type != 1 && type != 2 && type != 4)
      fail(body, "parameter '" + name + "' has unknown type " + std::to_string(type));
    p.type = static_cast<C3dType>(type);
    const std::size_t dimensionCount = m_data[body + 1];
    if (body + 2 + dimensionCount > limit)
      fail(body + 1, "parameter '" + name + "' dimensions run past its record");
    for (std::size_t d = 0; d < dimensionCount; ++d)
      p.dimensions.push_back(m_data[body + 2 + d]);
    const std::size_t dataAt = body + 2 + dimensionCount;
    const std::size_t elementSize = static_cast<std::size_t>(std::abs(type));
    const std::size_t count = p.elementCount();
    if (count * elementSize > limit - dataAt)
      fail(dataAt, "parameter '" + name + "' data run past its record (" + std::to_string(count * elementSize) +
                       " bytes)");
    const unsigned char* data = m_data + dataAt;
    switch (p.type) {
    case C3dType::Char: p.chars.assign(reinterpret_cast<const char*>(data), count); break;
    case C3dType::Byte: p.numbers.assign(data, data + count); break;
    case C3dType::Int16:
      p.numbers.resize(count);
      for (std::size_t i = 0; i < count; ++i)
        p.numbers[i] = c3d::readI16(data + 2 * i, m_processor);
      break;
    case C3dType::Float:
      p.numbers.resize(count);
      for (std::size_t i = 0; i < count; ++i)
        p.numbers[i] = static_cast<double>(c3d::readF32(data + 4 * i, m_processor));
      break;
    }
    p.description = readDescription(dataAt + count * elementSize, limit, name);
    return p;
  }

  void attachParameters(std::map<int, std::vector<C3dParameter>>& parametersByGroup)
  {
    for (auto& [id, parameters] : parametersByGroup) {
      auto it = std::find_if(m_tree.groups().begin(), m_tree.groups().end(),
                             [id = id](const C3dGroup& g) { return g.id == id; });
      if (it == m_tree.groups().end()) {
        warn("parameters of group " + std::to_string(id) + " have no group record; kept in GROUP" +
             std::to_string(id));
        C3dGroup group;
        group.id = id;
        group.name = "GROUP" + std::to_string(id);
        m_tree.groups().push_back(std::move(group));
        it = std::prev(m_tree.groups().end());
      }
      for (auto& p : parameters)
        it->parameters.push_back(std::move(p));
    }
  }

  /// Strings of `base`, `base2`, `base3`... concatenated (C3D splits arrays over 255 entries).
  std::vector<std::string> stringsAcrossParts(std::string_view group, const std::string& base) const
  {
    std::vector<std::string> all = m_tree.strings(group, base);
    for (int part = 2;; ++part) {
      const C3dParameter* p = m_tree.find(group, base + std::to_string(part));
      if (!p)
        return all;
      const auto more = p->strings();
      all.insert(all.end(), more.begin(), more.end());
    }
  }

  DataLayout resolveLayout()
  {
    DataLayout layout;
    layout.pointCount = m_header.pointCount;
    const auto used = m_tree.find("POINT", "USED");
    if (used && used->unsignedInt16() && *used->unsignedInt16() != m_header.pointCount)
      warn("POINT:USED (" + std::to_string(*used->unsignedInt16()) + ") differs from the header's point count (" +
           std::to_string(m_header.pointCount) + "); the header's count lays out the data");

    double scale = m_tree.number("POINT", "SCALE").value_or(static_cast<double>(m_header.scale));
    if (!std::isfinite(scale) || scale == 0.0) {
      warn("POINT:SCALE is " + std::to_string(scale) + "; using the header's scale");
      scale = static_cast<double>(m_header.scale);
      if (!std::isfinite(scale) || scale == 0.0)
        scale = -1.0;
    }
    layout.isFloat = scale < 0.0;
    layout.scale = std::abs(scale);

    layout.frameRate = resolveFrameRate();
    resolveAnalogLayout(layout);
    layout.offset = resolveDataOffset();
    resolveFrames(layout);
    return layout;
  }

  double resolveFrameRate()
  {
    const double header = static_cast<double>(m_header.frameRate);
    const auto parameter = m_tree.number("POINT", "RATE");
    if (parameter && std::isfinite(*parameter) && *parameter > 0.0)
      return *parameter;
    if (std::isfinite(header) && header > 0.0) {
      if (parameter)
        warn("POINT:RATE is not a positive number; using the header's rate");
      return header;
    }
    fail(20, "frame rate is not a positive number in the header or POINT:RATE");
  }

  void resolveAnalogLayout(DataLayout& layout)
  {
    layout.analogValuesPerFrame = m_header.analogValuesPerFrame;
    if (layout.analogValuesPerFrame == 0)
      return;
    const C3dParameter* used = m_tree.find("ANALOG", "USED");
    std::size_t channels = used && used->unsignedInt16() ? *used->unsignedInt16() : 0;
    if (!m_tree.group("ANALOG"))
      warn("the header declares " + std::to_string(layout.analogValuesPerFrame) +
           " analog values per frame but there is no ANALOG group; channels named A1...");
    if (channels == 0 || layout.analogValuesPerFrame % channels != 0) {
      const std::size_t samples = m_header.analogSamplesPerFrame;
      channels = (samples > 0 && layout.analogValuesPerFrame % samples == 0)
                     ? layout.analogValuesPerFrame / samples
                     : layout.analogValuesPerFrame;
      if (used)
        warn("ANALOG:USED does not divide the header's analog values per frame; using " +
             std::to_string(channels) + " channels");
    }
    layout.channelCount = channels;
    layout.samplesPerFrame = layout.analogValuesPerFrame / channels;
    const auto format = m_tree.string("ANALOG", "FORMAT");
    layout.analogUnsigned = format && equalsIgnoreCase(*format, "UNSIGNED");
  }

  std::size_t resolveDataOffset()
  {
    std::size_t block = m_header.dataBlock;
    const C3dParameter* start = m_tree.find("POINT", "DATA_START");
    if (start && start->unsignedInt16()) {
      const std::size_t parameterBlock = *start->unsignedInt16();
      if (parameterBlock == 0)
        warn("POINT:DATA_START is 0; using the header's data block " + std::to_string(block));
      else if (parameterBlock != block && block != 0)
        warn("POINT:DATA_START (" + std::to_string(parameterBlock) + ") differs from the header (" +
             std::to_string(block) + "); using POINT:DATA_START");
      if (parameterBlock != 0)
        block = parameterBlock;
    }
    if (block == 0)
      fail(16, "data section pointer is 0");
    const std::size_t offset = (block - 1) * c3d::kBlockSize;
    if (offset > m_size)
      fail(16, "data section pointer (block " + std::to_string(block) + ") is beyond the end of the file");
    return offset;
  }

  void resolveFrames(DataLayout& layout)
  {
    layout.firstFrame = m_header.firstFrame;
    std::size_t frames =
        m_header.lastFrame >= m_header.firstFrame ? std::size_t{m_header.lastFrame} - m_header.firstFrame + 1 : 0;
    const C3dParameter* start = m_tree.find("TRIAL", "ACTUAL_START_FIELD");
    const C3dParameter* end = m_tree.find("TRIAL", "ACTUAL_END_FIELD");
    if (start && end && start->numbers.size() >= 2 && end->numbers.size() >= 2) {
      const auto first = std::size_t{*start->unsignedInt16(0)} + (std::size_t{*start->unsignedInt16(1)} << 16);
      const auto last = std::size_t{*end->unsignedInt16(0)} + (std::size_t{*end->unsignedInt16(1)} << 16);
      if (last >= first) {
        frames = last - first + 1;
        layout.firstFrame = static_cast<std::int64_t>(first);
      }
    } else if (const C3dParameter* count = m_tree.find("POINT", "FRAMES");
               count && count->unsignedInt16() && *count->unsignedInt16() > frames &&
               (m_header.lastFrame == 65535 || m_header.lastFrame < m_header.firstFrame)) {
      frames = *count->unsignedInt16();  // the header's 16-bit last frame wrapped
    }
    const std::size_t frameBytes = layout.frameBytes();
    if (frameBytes > 0) {
      const std::size_t available = (m_size - layout.offset) / frameBytes;
      if (available < frames) {
        warnDataLoss("data section holds " + std::to_string(available) + " of " + std::to_string(frames) +
             " frames; the file is truncated");
        frames = available;
      }
    } else if (frames > 0) {
      frames = 0;  // no points and no analog: nothing to keep per frame
    }
    layout.frameCount = frames;
  }

  std::vector<std::string> pointLabels(std::size_t count)
  {
    std::vector<std::string> labels = stringsAcrossParts("POINT", "LABELS");
    if (labels.size() < count && count > 0)
      warn("POINT:LABELS names " + std::to_string(labels.size()) + " of " + std::to_string(count) +
           " points; the rest are named M<n>");
    labels.resize(count);
    for (auto& w : makeLabelsUnique(labels))
      warn(w);
    return labels;
  }

  Take makeTake(const DataLayout& layout)
  {
    // decodeFrames() writes every sample of every marker.
    Take take(pointLabels(layout.pointCount), static_cast<Eigen::Index>(layout.frameCount), layout.frameRate,
              Take::Uninitialized{});
    take.setFirstFrame(layout.firstFrame);
    const auto unitText = m_tree.string("POINT", "UNITS");
    const auto unit = unitText ? parseLengthUnit(*unitText) : std::nullopt;
    if (!unitText)
      warn("POINT:UNITS is missing; assuming mm");
    else if (!unit)
      warn("POINT:UNITS '" + *unitText + "' is not a length unit; assuming mm");
    take.setUnits(unit.value_or(LengthUnit::Millimetre));
    makeAnalog(layout, take.analog());
    return take;
  }

  void makeAnalog(const DataLayout& layout, AnalogData& analog)
  {
    if (layout.channelCount == 0)
      return;
    analog.rate = m_tree.number("ANALOG", "RATE").value_or(0.0);
    const double expectedRate = layout.frameRate * static_cast<double>(layout.samplesPerFrame);
    if (!std::isfinite(analog.rate) || analog.rate <= 0.0)
      analog.rate = expectedRate;
    analog.generalScale = m_tree.number("ANALOG", "GEN_SCALE").value_or(1.0);
    const auto labels = stringsAcrossParts("ANALOG", "LABELS");
    const auto descriptions = stringsAcrossParts("ANALOG", "DESCRIPTIONS");
    const auto units = stringsAcrossParts("ANALOG", "UNITS");
    const auto scales = m_tree.numbers("ANALOG", "SCALE");
    const C3dParameter* offsets = m_tree.find("ANALOG", "OFFSET");
    analog.channels.resize(layout.channelCount);
    for (std::size_t c = 0; c < layout.channelCount; ++c) {
      AnalogChannel& channel = analog.channels[c];
      channel.label = c < labels.size() && !labels[c].empty() ? labels[c] : "A" + std::to_string(c + 1);
      channel.description = c < descriptions.size() ? descriptions[c] : std::string();
      channel.unit = c < units.size() ? units[c] : std::string();
      channel.scale = c < scales.size() ? scales[c] : 1.0;
      if (offsets && c < offsets->numbers.size())
        channel.offset = layout.analogUnsigned ? static_cast<double>(*offsets->unsignedInt16(c)) : offsets->numbers[c];
    }
    analog.stored.resize(static_cast<Eigen::Index>(layout.frameCount * layout.samplesPerFrame),
                         static_cast<Eigen::Index>(layout.channelCount));
  }

  void decodeData(const DataLayout& layout, Take& take)
  {
    if (layout.frameCount == 0)
      return;
    const bool intel = m_processor == Processor::Intel;
    if (layout.isFloat) {
      if (intel)
        decodeFrames<true>(layout, take, [](const unsigned char* p) {
          float v;
          std::memcpy(&v, p, 4);
          return static_cast<double>(v);
        });
      else
        decodeFrames<false>(layout, take, [proc = m_processor](const unsigned char* p) {
          return static_cast<double>(c3d::readF32(p, proc));
        });
    } else {
      decodeFrames<false>(layout, take, [proc = m_processor](const unsigned char* p) {
        return static_cast<double>(c3d::readI16(p, proc));
      });
    }
  }

  /// One pass over the data section. `decode` turns one stored value into a double; an Intel
  /// float file (`IntelFloat`) goes two frames at a time where the CPU has SSE2.
  /// Frames go in chunks that fit the L2 cache: within a chunk each marker's samples are read
  /// with the frame stride and written to its contiguous columns, so both sides stream.
  template <bool IntelFloat, typename Decode>
  void decodeFrames(const DataLayout& layout, Take& take, Decode decode)
  {
    constexpr std::size_t kChunkFrames = 1024;
    const std::size_t frames = layout.frameCount;
    const std::size_t bpv = layout.bytesPerValue();
    const std::size_t frameBytes = layout.frameBytes();
    const double coordinateScale = layout.isFloat ? 1.0 : layout.scale;
    const double residualScale = layout.scale;
    const unsigned char* data = m_data + layout.offset;
    ResidualCounts counts;  // counted here, so loadProvenance need not read the residuals again
    for (std::size_t first = 0; first < frames; first += kChunkFrames) {
      const std::size_t last = std::min(frames, first + kChunkFrames);
      for (std::size_t m = 0; m < layout.pointCount; ++m) {
        const MarkerColumns out = markerColumns(take, m);
        const unsigned char* p = data + first * frameBytes + m * 4 * bpv;
        std::size_t f = first;
#if defined(__SSE2__)
        if constexpr (IntelFloat)
          for (; f + 1 < last; f += 2, p += 2 * frameBytes)
            decodeIntelFloatPair(p, frameBytes, residualScale, out, f, counts);
#endif
        for (; f < last; ++f, p += frameBytes)
          decodeSample(p, bpv, coordinateScale, residualScale, decode, out, f, counts);
      }
    }
    m_residualCounts = counts;
    decodeAnalog(layout, take.analog(), decode);
  }

  static MarkerColumns markerColumns(Take& take, std::size_t marker)
  {
    const auto frames = static_cast<std::size_t>(take.frameCount());
    double* x = take.positionData() + marker * frames * 3;
    const std::size_t base = marker * frames;
    return {x,
            x + frames,
            x + 2 * frames,
            take.valid().data() + base,
            take.residuals().data() + base,
            take.cameraMasks().data() + base};
  }

  template <typename Decode>
  void decodeAnalog(const DataLayout& layout, AnalogData& analog, Decode decode)
  {
    if (layout.channelCount == 0)
      return;
    const std::size_t bpv = layout.bytesPerValue();
    const std::size_t frameBytes = layout.frameBytes();
    const std::size_t channels = layout.channelCount;
    const std::size_t samples = layout.samplesPerFrame;
    const auto rows = static_cast<std::size_t>(analog.stored.rows());
    double* out = analog.stored.data();
    for (std::size_t f = 0; f < layout.frameCount; ++f) {
      const unsigned char* p = m_data + layout.offset + f * frameBytes + layout.pointCount * 4 * bpv;
      for (std::size_t s = 0; s < samples; ++s)
        for (std::size_t c = 0; c < channels; ++c, p += bpv) {
          double v = decode(p);
          if (layout.analogUnsigned && !layout.isFloat)
            v = static_cast<double>(c3d::readU16(p, m_processor));
          out[c * rows + f * samples + s] = v;
        }
    }
  }

  void readEvents(Take& take)
  {
    const C3dGroup* group = m_tree.group("EVENT");
    if (group && group->find("TIMES")) {
      readEventGroup(take.events());
      return;
    }
    readHeaderEvents(take.events());
  }

  void readEventGroup(std::vector<Event>& events) const
  {
    const auto times = m_tree.numbers("EVENT", "TIMES");
    const auto labels = stringsAcrossParts("EVENT", "LABELS");
    const auto contexts = stringsAcrossParts("EVENT", "CONTEXTS");
    const auto descriptions = stringsAcrossParts("EVENT", "DESCRIPTIONS");
    const auto subjects = stringsAcrossParts("EVENT", "SUBJECTS");
    std::size_t count = times.size() / 2;
    if (const auto used = m_tree.find("EVENT", "USED"); used && used->unsignedInt16())
      count = std::min<std::size_t>(count, *used->unsignedInt16());
    auto at = [](const std::vector<std::string>& v, std::size_t i) { return i < v.size() ? v[i] : std::string(); };
    for (std::size_t i = 0; i < count; ++i) {
      Event e;
      e.time = times[2 * i] * 60.0 + times[2 * i + 1];  // TIMES holds (minutes, seconds) pairs
      e.label = at(labels, i);
      e.context = at(contexts, i);
      e.description = at(descriptions, i);
      e.subject = at(subjects, i);
      events.push_back(std::move(e));
    }
  }

  void readHeaderEvents(std::vector<Event>& events) const
  {
    if (u16(298) != c3d::kEventKey)
      return;
    const std::size_t count = std::min<std::size_t>(u16(300), 18);
    for (std::size_t i = 0; i < count; ++i) {
      Event e;
      e.time = static_cast<double>(f32(304 + 4 * i));
      e.label = std::string(trim(std::string_view(reinterpret_cast<const char*>(m_data + 396 + 4 * i), 4)));
      if (std::isfinite(e.time))
        events.push_back(std::move(e));
    }
  }

  const unsigned char* m_data;
  std::size_t m_size;
  const std::string& m_name;
  std::vector<std::string>* m_warnings;
  std::vector<std::string>* m_dataLoss;
  std::optional<ResidualCounts> m_residualCounts;  // set by decodeFrames
  Processor m_processor = Processor::Intel;
  Header m_header;
  std::size_t m_parameterOffset = 0;
  C3dParameterTree m_tree;
};

} // namespace

Take parseC3d(const unsigned char* data, std::size_t size, const std::string& sourceName,
              std::vector<std::string>* warnings, std::vector<std::string>* dataLoss)
{
  return C3dParser(data, size, sourceName, warnings, dataLoss).parse();
}

Take readC3d(const std::filesystem::path& path, std::vector<std::string>* warnings, std::vector<std::string>* dataLoss)
{
  const MappedFile file(path);
  return parseC3d(file.data(), file.size(), path.string(), warnings, dataLoss);
}

} // namespace mocap
