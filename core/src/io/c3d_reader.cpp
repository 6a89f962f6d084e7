#include "mocap/io/c3d_reader.h"

#include "mocap/model/data_loss_record.h"

#include "mocap/io/c3d_binary.h"
#include "mocap/io/c3d_point_types.h"
#include "mocap/io/c3d_string_lists.h"
#include "mocap/io/take_plausibility.h"
#include "mocap/io/vicon_virtual_points.h"
#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/model/provenance.h"
#include "mocap/base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>

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

/// How analog values are laid out in a frame: `samples` samples of `channels` channels each.
struct AnalogShape
{
  std::size_t values = 0;  // channels × samples
  std::size_t channels = 0;
  std::size_t samples = 0;
  bool fromHeader = false;  // the header's word 3 (else ANALOG:USED × ANALOG:RATE / POINT:RATE)
};

/// How the data section is laid out, resolved from header and parameters.
struct DataLayout
{
  std::size_t offset = 0;
  std::size_t dataBlock = 0;  // 1-based block at `offset`
  bool dataStartFromHeader = false;
  std::size_t pointCount = 0;
  AnalogShape analog;
  std::size_t declaredFrames = 0;
  std::size_t frameCount = 0;  // the declared count until fitFramesToData keeps what the data hold
  std::int64_t firstFrame = 1;
  bool isFloat = false;
  bool analogUnsigned = false;
  double scale = 1.0;
  double frameRate = 0.0;

  [[nodiscard]] std::size_t bytesPerValue() const { return isFloat ? 4 : 2; }
  [[nodiscard]] std::size_t frameBytes() const
  {
    return (pointCount * 4 + analog.values) * bytesPerValue();
  }
};

/// One source's reading of one part of the layout: what it says (for warnings) and how it sets it.
struct LayoutOption
{
  std::string source;
  std::function<void(DataLayout&)> apply;
};
/// The readings of one part of the layout (data start, storage, point count, analog), default first.
using LayoutOptions = std::vector<LayoutOption>;

/// How the declared frames fit a data section, best last: not all of them; all, with bytes to
/// spare; all, with nothing after them but the padding of the last block.
enum class Fit
{
  Short,
  Holds,
  Exact,
};

/// A scale a file can be read with: finite and not 0.
bool usableScale(double scale)
{
  return std::isfinite(scale) && scale != 0.0;
}

/// Whether two values a header and a parameter give differ beyond float rounding.
bool differ(double a, double b)
{
  return !(std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)));
}

/// A number for a warning: 6 significant digits.
std::string numberText(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// What the decoding pass counts: the residuals loadProvenance needs, and the samples whose
/// residual word is no 16-bit integer.
struct SampleCounts
{
  ResidualCounts residuals;
  std::size_t outOfRange = 0;
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

/// The residual word is two bytes read as a signed 16-bit integer; a float file stores it as a
/// float that converts to an integer of those two bytes. From kSignBit up the word's sign bit is
/// set (65535 is −1: invalid); from kWordEnd up, and NaN or infinite, it is no 16-bit word at all.
constexpr double kSignBit = 32768.0;
constexpr double kWordEnd = 65536.0;

/// One stored sample (x, y, z, residual word at `p`, `bpv` bytes each) into frame `f` of `out`.
/// The word is converted to an integer (toward zero) before its sign is tested, as the format
/// says. A sample is valid when that integer is a non-negative 16-bit word and the coordinates
/// are finite; its low byte is the residual (× `residualScale`), bits 8–14 the cameras that saw
/// it. A word that is no 16-bit integer is counted, not clamped into a residual. O(1).
template <typename Decode>
void decodeSample(const unsigned char* p, std::size_t bpv, double coordinateScale, double residualScale,
                  Decode decode, const MarkerColumns& out, std::size_t f, SampleCounts& counts)
{
  const double word = decode(p + 3 * bpv);
  const double xv = decode(p) * coordinateScale;
  const double yv = decode(p + bpv) * coordinateScale;
  const double zv = decode(p + 2 * bpv) * coordinateScale;
  const bool ok = word > -1.0 && word < kSignBit && std::isfinite(xv + yv + zv);
  out.x[f] = xv;
  out.y[f] = yv;
  out.z[f] = zv;
  out.valid[f] = ok;
  const auto bits = ok ? static_cast<std::uint32_t>(word) : 0u;
  const double residual = ok ? static_cast<double>(bits & 0xFFu) * residualScale : -1.0;
  out.residuals[f] = residual;
  counts.residuals.valid += ok ? 1 : 0;
  counts.residuals.zero += residual == 0.0 ? 1 : 0;  // (an invalid sample's -1 is never 0)
  counts.outOfRange += word < kWordEnd ? 0 : 1;
  out.cameras[f] = static_cast<std::uint8_t>((bits >> 8) & 0x7Fu);
}

#if defined(__SSE2__)
/// decodeSample for two frames of an Intel float file at once (records at `p` and `p` +
/// `frameBytes` into frames `f`, `f` + 1): the two 4-float records are widened and transposed
/// into x, y, z and word pairs, so each column gets one 16-byte store and the tests run on both
/// lanes. The same operations in the same order as decodeSample (the coordinate scale of a float
/// file is 1), so the results are identical. O(1).
void decodeIntelFloatPair(const unsigned char* p, std::size_t frameBytes, double residualScale,
                          const MarkerColumns& out, std::size_t f, SampleCounts& counts)
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
  // The word's integer is ≥ 0 with the sign bit clear: −1 < word < 32768.
  const __m128d nonNegative =
      _mm_and_pd(_mm_cmpgt_pd(word, _mm_set1_pd(-1.0)), _mm_cmplt_pd(word, _mm_set1_pd(kSignBit)));
  const __m128d ok = _mm_and_pd(nonNegative, finite);
  // The words truncated to integers (exact for the words in range); the 64-bit lane masks
  // narrowed to the two 32-bit lanes.
  const __m128i okLanes = _mm_shuffle_epi32(_mm_castpd_si128(ok), _MM_SHUFFLE(2, 0, 2, 0));
  const __m128i bits = _mm_and_si128(_mm_cvttpd_epi32(word), okLanes);
  const __m128d scaled =
      _mm_mul_pd(_mm_cvtepi32_pd(_mm_and_si128(bits, _mm_set1_epi32(0xFF))), _mm_set1_pd(residualScale));
  const __m128d residual = _mm_or_pd(_mm_and_pd(ok, scaled), _mm_andnot_pd(ok, _mm_set1_pd(-1.0)));
  _mm_storeu_pd(out.residuals + f, residual);
  const int okMask = _mm_movemask_pd(ok);
  const int zeroMask = _mm_movemask_pd(_mm_cmpeq_pd(residual, zero));
  out.valid[f] = (okMask & 1) != 0;
  out.valid[f + 1] = (okMask & 2) != 0;
  const int outMask = _mm_movemask_pd(_mm_cmpnlt_pd(word, _mm_set1_pd(kWordEnd)));  // NaN too, as in decodeSample
  counts.residuals.valid += (okMask & 1) + (okMask >> 1);
  counts.residuals.zero += (zeroMask & 1) + (zeroMask >> 1);
  counts.outOfRange += static_cast<std::size_t>((outMask & 1) + (outMask >> 1));
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
            std::vector<std::string>* warnings, std::vector<std::string>* dataLoss, C3dLayoutReport* layout)
      : m_data(data), m_size(size), m_name(name), m_warnings(warnings), m_dataLoss(dataLoss), m_layoutReport(layout)
  {
  }

  Take parse()
  {
    readHeaderBlock();
    readParameters();
    const DataLayout layout = resolveLayout();
    reportLayout(layout);
    Take take = makeTake(layout);
    readC3dPointTypes(m_tree, take);
    decodeData(layout, take);
    reportVirtualPoints(typeViconVirtualPoints(take));  // decoded first: the axes are checked
    if (!layout.isFloat)
      warnAboutWrappedIntegers(layout, take);
    for (const std::string& warning : takePlausibilityWarnings(take, m_unitDeclared))
      warn(warning);
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

  /// Plug-in Gait's virtual points are typed by their names and axes, not by a list of the file: the
  /// reader's judgement, so it is said.
  void reportVirtualPoints(const std::vector<std::string>& labels)
  {
    if (labels.empty())
      return;
    std::string named;
    for (std::size_t i = 0; i < std::min<std::size_t>(labels.size(), 4); ++i)
      named += (i == 0 ? "" : ", ") + labels[i];
    warn(std::to_string(labels.size()) +
         (labels.size() == 1 ? " point is a Vicon Plug-in Gait virtual point" : " points are Vicon Plug-in Gait virtual points") +
         " (segment axes, centre of mass: " + named + (labels.size() > 4 ? ", …" : "") +
         "), not markers: kept as model outputs");
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
    m_parameterEnd = pos;
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
      std::size_t limit = last ? std::min(next, m_size) : next;
      // The last record ends with the section: what runs past it is the data's bytes.
      const bool clipped = last && limit > parameterSectionEnd() && offsetPos < parameterSectionEnd();
      if (clipped)
        limit = parameterSectionEnd();
      const std::size_t body = offsetPos + 2;
      if (id < 0) {
        C3dGroup group;
        group.id = -id;
        group.name = name;
        group.locked = nameLength < 0;
        group.description = readDescription(body, limit, name);
        m_tree.groups().push_back(std::move(group));
      } else if (std::optional<C3dParameter> parameter = readLastParameter(body, limit, name, id, clipped)) {
        parameter->locked = nameLength < 0;
        parametersByGroup[id].push_back(std::move(*parameter));
      }
      if (last)
        break;
      pos = next;
    }
    attachParameters(parametersByGroup);
  }

  /// Past the parameter section: its declared block count, or where the header's data section
  /// starts when that comes first. O(1).
  std::size_t parameterSectionEnd() const
  {
    std::size_t end = m_parameterOffset + std::size_t{m_data[m_parameterOffset + 2]} * c3d::kBlockSize;
    if (const std::size_t dataStart = (std::size_t{m_header.dataBlock} - 1) * c3d::kBlockSize;
        m_header.dataBlock > 0 && dataStart > m_parameterOffset)
      end = std::min(end, dataStart);
    return end;
  }

  /// Whether a link to `next` continues the section. Some writers (the SGI sample02 files) give
  /// the last record a link far past the section's declared end, into the data: a link beyond
  /// that end continues only when a plausible record (text name) sits there. The section ends at
  /// its declared block count or where the header's data section starts, whichever comes first
  /// (sample18's file declares 12 parameter blocks where its data starts after 10).
  bool continuesAt(std::size_t next)
  {
    if (next < parameterSectionEnd())
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
    m_parameterEnd = std::max(m_parameterEnd, std::min(at, limit));
    if (at >= limit) {
      warn("parameter '" + owner + "' has no description-length byte; read as empty");
      return {};
    }
    std::size_t length = m_data[at];
    if (at + 1 + length > limit) {
      warn("description of '" + owner + "' runs past its record; clipped");
      length = limit - at - 1;
    }
    m_parameterEnd = std::max(m_parameterEnd, at + 1 + length);
    return std::string(trim(std::string_view(reinterpret_cast<const char*>(m_data + at + 1), length)));
  }

  /// readParameter, except that a record `clipped` at the section's end whose values run past it is
  /// left out with a warning (sample18's EVENT:LABELS runs into the data section) rather than
  /// failing the read: no value of it is made up from the data's bytes.
  std::optional<C3dParameter> readLastParameter(std::size_t body, std::size_t limit, const std::string& name,
                                                int group, bool clipped)
  {
    if (!clipped)
      return readParameter(body, limit, name);
    try {
      return readParameter(body, limit, name);
    } catch (const FormatError&) {
      warn("parameter '" + groupName(group) + name + "' runs past the parameter section into the data section (byte " +
           std::to_string(limit) + "); left out");
      return std::nullopt;
    }
  }

  /// "GROUP:" for a parameter of group `id` read so far, or "" (a message's prefix).
  std::string groupName(int id) const
  {
    for (const C3dGroup& group : m_tree.groups())
      if (group.id == id)
        return group.name + ":";
    return {};
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
    return c3dStringsAcrossParts(m_tree, group, base);
  }

  DataLayout resolveLayout()
  {
    DataLayout layout;
    layout.frameRate = resolveFrameRate();
    resolveDeclaredFrames(layout);
    const double scale = resolveScale();
    layout.scale = std::abs(scale);
    chooseLayout(layout, scale);
    fitFramesToData(layout);
    const auto format = m_tree.string("ANALOG", "FORMAT");
    layout.analogUnsigned = format && equalsIgnoreCase(*format, "UNSIGNED");
    return layout;
  }

  double resolveFrameRate()
  {
    const double header = static_cast<double>(m_header.frameRate);
    const auto parameter = m_tree.number("POINT", "RATE");
    const bool headerUsable = std::isfinite(header) && header > 0.0;
    if (parameter && std::isfinite(*parameter) && *parameter > 0.0) {
      if (headerUsable && differ(header, *parameter))
        warn("POINT:RATE (" + numberText(*parameter) + ") differs from the header's frame rate (" +
             numberText(header) + "); using POINT:RATE");
      return *parameter;
    }
    if (headerUsable) {
      if (parameter)
        warn("POINT:RATE is not a positive number; using the header's rate");
      return header;
    }
    fail(20, "frame rate is not a positive number in the header or POINT:RATE");
  }

  /// POINT:SCALE, else the header's scale (−1, float storage, when neither is usable). Its sign
  /// says float (negative) or integer storage, which chooseLayout checks against the header's;
  /// magnitudes that differ are a warning here.
  double resolveScale()
  {
    const auto header = static_cast<double>(m_header.scale);
    const auto parameter = m_tree.number("POINT", "SCALE");
    if (parameter && usableScale(*parameter)) {
      if (usableScale(header) && differ(std::abs(header), std::abs(*parameter)))
        warn("POINT:SCALE (" + numberText(*parameter) + ") differs from the header's scale (" + numberText(header) +
             "); using POINT:SCALE");
      return *parameter;
    }
    if (parameter)
      warn("POINT:SCALE is " + numberText(*parameter) + "; using the header's scale");
    if (usableScale(header))
      return header;
    warn("neither POINT:SCALE nor the header gives a usable scale; reading float storage");
    return -1.0;
  }

  /// The frame count and first frame the file declares: the header's, TRIAL:ACTUAL_START_FIELD
  /// and END_FIELD when present (they count past 65535), or POINT:FRAMES when the header's 16-bit
  /// last frame wrapped. A count elsewhere that differs is a warning.
  void resolveDeclaredFrames(DataLayout& layout)
  {
    layout.firstFrame = m_header.firstFrame;
    const bool headerWrapped = m_header.lastFrame == 65535 || m_header.lastFrame < m_header.firstFrame;
    const std::size_t headerFrames =
        m_header.lastFrame >= m_header.firstFrame ? std::size_t{m_header.lastFrame} - m_header.firstFrame + 1 : 0;
    std::size_t frames = headerFrames;
    std::string source = "the header's frame count";
    const C3dParameter* start = m_tree.find("TRIAL", "ACTUAL_START_FIELD");
    const C3dParameter* end = m_tree.find("TRIAL", "ACTUAL_END_FIELD");
    const C3dParameter* count = m_tree.find("POINT", "FRAMES");
    if (start && end && start->numbers.size() >= 2 && end->numbers.size() >= 2) {
      const auto first = std::size_t{*start->unsignedInt16(0)} + (std::size_t{*start->unsignedInt16(1)} << 16);
      const auto last = std::size_t{*end->unsignedInt16(0)} + (std::size_t{*end->unsignedInt16(1)} << 16);
      if (last >= first) {
        frames = last - first + 1;
        layout.firstFrame = static_cast<std::int64_t>(first);
        source = "TRIAL:ACTUAL_START_FIELD/END_FIELD";
        if (!headerWrapped && frames != headerFrames)
          warnFrameConflict("the header's frame count", headerFrames, source, frames);
      }
    } else if (count && count->unsignedInt16() && *count->unsignedInt16() > frames && headerWrapped) {
      frames = *count->unsignedInt16();  // the header's 16-bit last frame wrapped
      source = "POINT:FRAMES";
    }
    // POINT:FRAMES is a 16-bit count: it can only be compared below 65536 frames.
    if (count && count->unsignedInt16() && frames <= 65535 && *count->unsignedInt16() != frames)
      warnFrameConflict("POINT:FRAMES", *count->unsignedInt16(), source, frames);
    layout.frameCount = frames;
    layout.declaredFrames = frames;
  }

  void warnFrameConflict(const std::string& other, std::size_t otherFrames, const std::string& used,
                         std::size_t usedFrames)
  {
    warn(other + " (" + std::to_string(otherFrames) + ") differs from " + used + " (" + std::to_string(usedFrames) +
         "); using " + used);
  }

  /// Settles the data start, the storage, the point count and the analog layout together: of
  /// every combination the sources offer (at most two options each), the one whose data section
  /// fits the declared frames best (Fit); a tie goes to the first options (POINT:DATA_START, the
  /// sign of POINT:SCALE, the header's counts). Each part with two options is a warning naming
  /// the one used and why. O(1): at most 16 combinations.
  void chooseLayout(DataLayout& layout, double scale)
  {
    const std::vector<LayoutOptions> parts = {dataStartPart(), storagePart(scale), pointCountPart(),
                                              analogPart(layout.frameRate)};
    std::vector<std::size_t> pick(parts.size(), 0), best = pick;
    Fit bestFit = fitOf(applied(layout, parts, pick));
    while (nextCombination(parts, pick)) {
      const Fit fit = fitOf(applied(layout, parts, pick));
      if (fit > bestFit) {
        bestFit = fit;
        best = pick;
      }
    }
    layout = applied(layout, parts, best);
    for (std::size_t k = 0; k < parts.size(); ++k)
      if (parts[k].size() > 1)
        explainChoice(layout, parts, best, k);
    warnAboutHeaderAnalog(layout);
  }

  /// `layout` with option pick[k] of each part applied.
  static DataLayout applied(DataLayout layout, const std::vector<LayoutOptions>& parts,
                            const std::vector<std::size_t>& pick)
  {
    for (std::size_t k = 0; k < parts.size(); ++k)
      parts[k][pick[k]].apply(layout);
    return layout;
  }

  /// Advances `pick` like an odometer over the parts' options; false after the last combination.
  static bool nextCombination(const std::vector<LayoutOptions>& parts, std::vector<std::size_t>& pick)
  {
    for (std::size_t k = 0; k < parts.size(); ++k) {
      if (++pick[k] < parts[k].size())
        return true;
      pick[k] = 0;
    }
    return false;
  }

  /// Warns that part `k`'s two sources disagree (a part has at most two options), which was used
  /// (in `layout`) and why.
  void explainChoice(const DataLayout& layout, const std::vector<LayoutOptions>& parts,
                     const std::vector<std::size_t>& best, std::size_t k)
  {
    std::vector<std::size_t> other = best;
    other[k] = 1 - best[k];
    const DataLayout alternative = applied(layout, parts, other);
    const std::string& used = parts[k][best[k]].source;
    const std::string& notUsed = parts[k][other[k]].source;
    std::string message = used + " and " + notUsed + " disagree; using " + used;
    if (fitOf(layout) != fitOf(alternative))
      message += ": with it the data section " + fitText(layout) + ", with " + notUsed + " it " + fitText(alternative);
    else
      message += " by default, as the file's size fits both alike (the data section " + fitText(layout) + ")";
    warn(message);
  }

  /// The usable data starts: POINT:DATA_START, then the header's word 9 when it differs. One that
  /// is 0, points into the header or parameter section or past the end of the file is a warning
  /// naming the one used instead; when neither is usable the file cannot be read.
  LayoutOptions dataStartPart()
  {
    struct Given
    {
      std::size_t block;
      bool fromHeader;
    };
    std::vector<Given> given;
    if (const C3dParameter* start = m_tree.find("POINT", "DATA_START"); start && start->unsignedInt16())
      given.push_back({*start->unsignedInt16(), false});
    given.push_back({m_header.dataBlock, true});
    LayoutOptions options;
    std::vector<std::string> rejections;
    std::size_t firstBlock = 0;  // of the first usable start
    for (const Given& g : given) {
      const std::string name = g.fromHeader ? "the header's data start" : "POINT:DATA_START";
      const std::string where = name + " (block " + std::to_string(g.block) + ")";
      if (const std::string problem = dataStartProblem(g.block); !problem.empty()) {
        rejections.push_back(g.block == 0 ? name + " is 0" : where + " " + problem);
      } else if (options.empty() || g.block != firstBlock) {
        firstBlock = options.empty() ? g.block : firstBlock;
        options.push_back({where, [g](DataLayout& l) {
                             l.dataBlock = g.block;
                             l.offset = (g.block - 1) * c3d::kBlockSize;
                             l.dataStartFromHeader = g.fromHeader;
                           }});
      }
    }
    if (options.empty())
      fail(16, "no usable data section start: " + rejections.front() +
                   (rejections.size() > 1 ? " and " + rejections.back() : std::string()));
    for (const std::string& r : rejections)
      warn(r + "; using " + options.front().source);
    return options;
  }

  /// Why data cannot start at 1-based block `block`, or empty when it can.
  std::string dataStartProblem(std::size_t block) const
  {
    if (block == 0)
      return "is 0";
    const std::size_t offset = (block - 1) * c3d::kBlockSize;
    if (offset < c3d::kBlockSize)
      return "points into the header";
    if (offset >= m_parameterOffset && offset < m_parameterEnd)
      return "points into the parameter section";
    if (offset > m_size)
      return "is beyond the end of the file";
    return {};
  }

  /// Float or integer storage: the sign of the scale used, and the header's when it differs.
  LayoutOptions storagePart(double scale) const
  {
    auto option = [](const std::string& name, double value) {
      const bool isFloat = value < 0.0;
      return LayoutOption{name + " (" + numberText(value) + (isFloat ? ", float storage)" : ", integer storage)"),
                          [isFloat](DataLayout& l) { l.isFloat = isFloat; }};
    };
    LayoutOptions options{option("POINT:SCALE", scale)};
    const auto header = static_cast<double>(m_header.scale);
    if (usableScale(header) && (header < 0.0) != (scale < 0.0))
      options.push_back(option("the header's scale", header));
    return options;
  }

  /// The header's point count, and POINT:USED when it differs.
  LayoutOptions pointCountPart() const
  {
    auto option = [](const std::string& name, std::size_t count) {
      return LayoutOption{name + " (" + std::to_string(count) + ")", [count](DataLayout& l) { l.pointCount = count; }};
    };
    LayoutOptions options{option("the header's point count", m_header.pointCount)};
    const C3dParameter* used = m_tree.find("POINT", "USED");
    if (used && used->unsignedInt16() && *used->unsignedInt16() != m_header.pointCount)
      options.push_back(option("POINT:USED", *used->unsignedInt16()));
    return options;
  }

  /// The header's analog values per frame (word 3), and ANALOG:USED × the analog samples per
  /// point frame (ANALOG:RATE / POINT:RATE, when a whole number) when that differs.
  LayoutOptions analogPart(double frameRate) const
  {
    const AnalogShape header = headerAnalogShape();
    LayoutOptions options{{"the header's analog values per frame (" + std::to_string(header.values) + ")",
                           [header](DataLayout& l) { l.analog = header; }}};
    const C3dParameter* used = m_tree.find("ANALOG", "USED");
    if (!used || !used->unsignedInt16())
      return options;
    AnalogShape shape;
    shape.channels = *used->unsignedInt16();
    std::string source = "ANALOG:USED (0)";
    if (shape.channels > 0) {
      const double ratio = m_tree.number("ANALOG", "RATE").value_or(0.0) / frameRate;
      const double samples = std::round(ratio);
      if (!(samples >= 1.0 && samples <= 65535.0 && std::abs(ratio - samples) <= 1e-3))
        return options;  // no whole number of samples per frame: makeAnalog warns about the rate
      shape.samples = static_cast<std::size_t>(samples);
      shape.values = shape.channels * shape.samples;
      source = "ANALOG:USED × ANALOG:RATE / POINT:RATE (" + std::to_string(shape.channels) + " × " +
               std::to_string(shape.samples) + " = " + std::to_string(shape.values) + ")";
    }
    if (shape.values != header.values)
      options.push_back({source, [shape](DataLayout& l) { l.analog = shape; }});
    return options;
  }

  /// The header's analog values per frame split into channels × samples: ANALOG:USED channels
  /// when they divide it, else by the header's samples per frame (word 10), else one sample each.
  AnalogShape headerAnalogShape() const
  {
    AnalogShape shape;
    shape.values = m_header.analogValuesPerFrame;
    shape.fromHeader = true;
    if (shape.values == 0)
      return shape;
    const C3dParameter* used = m_tree.find("ANALOG", "USED");
    std::size_t channels = used && used->unsignedInt16() ? *used->unsignedInt16() : 0;
    if (channels == 0 || shape.values % channels != 0) {
      const std::size_t samples = m_header.analogSamplesPerFrame;
      channels = samples > 0 && shape.values % samples == 0 ? shape.values / samples : shape.values;
    }
    shape.channels = channels;
    shape.samples = shape.values / channels;
    return shape;
  }

  /// The warnings the header's analog layout needs when it is the one used.
  void warnAboutHeaderAnalog(const DataLayout& layout)
  {
    if (!layout.analog.fromHeader || layout.analog.values == 0)
      return;
    if (!m_tree.group("ANALOG")) {
      warn("the header declares " + std::to_string(layout.analog.values) +
           " analog values per frame but there is no ANALOG group; channels named A1...");
      return;
    }
    const C3dParameter* used = m_tree.find("ANALOG", "USED");
    if (used && used->unsignedInt16() && *used->unsignedInt16() > 0 && layout.analog.values % *used->unsignedInt16() != 0)
      warn("ANALOG:USED does not divide the header's analog values per frame; using " +
           std::to_string(layout.analog.channels) + " channels");
  }

  /// How the declared frames fit the data section `layout` describes: exactly when the last
  /// frame ends where the file does, or in the file's last block when the file is whole blocks
  /// (the format pads the data section to a block). O(1).
  Fit fitOf(const DataLayout& layout) const
  {
    const std::size_t available = m_size - layout.offset;
    const std::size_t frameBytes = layout.frameBytes();
    if (frameBytes > 0 && layout.frameCount > available / frameBytes)
      return Fit::Short;
    const std::size_t end = layout.offset + layout.frameCount * frameBytes;
    const bool padded = m_size % c3d::kBlockSize == 0 && m_size - end < c3d::kBlockSize;
    return end == m_size || padded ? Fit::Exact : Fit::Holds;
  }

  /// fitOf in words, after "the data section": "holds the 450 declared frames exactly".
  std::string fitText(const DataLayout& layout) const
  {
    const std::size_t available = m_size - layout.offset;
    const std::size_t frameBytes = layout.frameBytes();
    const std::string declared = "the " + std::to_string(layout.frameCount) + " declared frames";
    switch (fitOf(layout)) {
    case Fit::Exact: return "holds " + declared + " exactly";
    case Fit::Holds:
      return "holds " + declared + " and " + std::to_string(available - layout.frameCount * frameBytes) + " bytes more";
    case Fit::Short: break;
    }
    return "holds only " + std::to_string(available / frameBytes) + " of " + declared;
  }

  /// Keeps the complete frames the data section holds. A section shorter than declared is data
  /// loss; one longer than the declared frames and the last block's padding is a warning (the
  /// rest is not read).
  void fitFramesToData(DataLayout& layout)
  {
    const std::size_t frameBytes = layout.frameBytes();
    if (frameBytes == 0) {
      layout.frameCount = 0;  // no points and no analog: nothing to keep per frame
      return;
    }
    const std::size_t frames = layout.frameCount;
    const std::size_t available = m_size - layout.offset;
    const Fit fit = fitOf(layout);
    if (fit == Fit::Short) {
      layout.frameCount = available / frameBytes;
      warnDataLoss("the data section is shorter than declared: it holds " + std::to_string(layout.frameCount) +
                   " of the " + std::to_string(frames) +
                   " frames (the file is truncated or declares too many); the complete frames are kept");
    } else if (fit == Fit::Holds) {
      const std::size_t extra = available - frames * frameBytes;
      warn("the data section is longer than declared: " + std::to_string(extra) + " bytes (" +
           std::to_string(extra / frameBytes) + " whole frames) follow the " + std::to_string(frames) +
           " declared frames; they are not read");
    }
  }

  void reportLayout(const DataLayout& layout) const
  {
    if (!m_layoutReport)
      return;
    C3dLayoutReport& r = *m_layoutReport;
    const std::size_t frameBytes = layout.frameBytes();
    r.dataStartBlock = layout.dataBlock;
    r.dataStartSource = layout.dataStartFromHeader ? "header" : "POINT:DATA_START";
    r.frameBytes = frameBytes;
    r.analogValuesPerFrame = layout.analog.values;
    r.isFloat = layout.isFloat;
    r.declaredFrames = layout.declaredFrames;
    r.dataBytes = m_size - layout.offset;
    // A corrupt frame count can declare more bytes than a size_t holds.
    const bool overflows = frameBytes > 0 && layout.declaredFrames > std::numeric_limits<std::size_t>::max() / frameBytes;
    r.declaredDataBytes = overflows ? std::numeric_limits<std::size_t>::max() : layout.declaredFrames * frameBytes;
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
    m_unitDeclared = unit.has_value();
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
    if (layout.analog.channels == 0)
      return;
    analog.rate = analogRate(layout);
    analog.generalScale = m_tree.number("ANALOG", "GEN_SCALE").value_or(1.0);
    const auto labels = stringsAcrossParts("ANALOG", "LABELS");
    const auto descriptions = stringsAcrossParts("ANALOG", "DESCRIPTIONS");
    const auto units = stringsAcrossParts("ANALOG", "UNITS");
    const auto scales = m_tree.numbers("ANALOG", "SCALE");
    const C3dParameter* offsets = m_tree.find("ANALOG", "OFFSET");
    analog.channels.resize(layout.analog.channels);
    for (std::size_t c = 0; c < layout.analog.channels; ++c) {
      AnalogChannel& channel = analog.channels[c];
      channel.label = c < labels.size() && !labels[c].empty() ? labels[c] : "A" + std::to_string(c + 1);
      channel.description = c < descriptions.size() ? descriptions[c] : std::string();
      channel.unit = c < units.size() ? units[c] : std::string();
      channel.scale = c < scales.size() ? scales[c] : 1.0;
      if (offsets && c < offsets->numbers.size())
        channel.offset = layout.analogUnsigned ? static_cast<double>(*offsets->unsignedInt16(c)) : offsets->numbers[c];
    }
    analog.stored.resize(static_cast<Eigen::Index>(layout.frameCount * layout.analog.samples),
                         static_cast<Eigen::Index>(layout.analog.channels));
  }

  /// ANALOG:RATE, unless it is not the point rate × the layout's samples per frame: then that
  /// product (the data's own rate) with a warning.
  double analogRate(const DataLayout& layout)
  {
    const double rate = layout.frameRate * static_cast<double>(layout.analog.samples);
    const double parameter = m_tree.number("ANALOG", "RATE").value_or(0.0);
    if (!(std::isfinite(parameter) && parameter > 0.0))
      return rate;
    if (!differ(parameter, rate))
      return parameter;
    warn("ANALOG:RATE (" + numberText(parameter) + ") is not the frame rate × the " +
         std::to_string(layout.analog.samples) + " analog samples per frame; using " + numberText(rate));
    return rate;
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
    SampleCounts counts;  // residuals counted here, so loadProvenance need not read them again
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
    m_residualCounts = counts.residuals;
    if (counts.outOfRange > 0)
      warn(std::to_string(counts.outOfRange) + " sample(s) have a residual word that is no 16-bit integer " +
           "(NaN, infinite or 65536 and more); read as invalid");
    decodeAnalog(layout, take.analog(), decode);
  }

  /// Integer storage holds ±32767 × scale: a coordinate past it wraps round, and its trajectory
  /// jumps by about 65536 × scale between two frames (seen in an ART file). A jump of over half
  /// that between consecutive valid samples of a marker cannot be motion, so it is reported as
  /// wrong data, not repaired. Markers only: an angle may wrap by 360° on purpose. O(#samples).
  void warnAboutWrappedIntegers(const DataLayout& layout, const Take& take)
  {
    const double limit = 32768.0 * layout.scale;
    const auto valid = take.valid();
    std::size_t markers = 0;
    std::string example;
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      if (take.pointType(m) != PointType::Marker)
        continue;
      const auto xyz = take.trajectory(m);
      for (Eigen::Index f = 1; f < take.frameCount(); ++f) {
        if (!valid(f - 1, m) || !valid(f, m))
          continue;
        const Eigen::Index axis = wrappedAxis(xyz.row(f - 1), xyz.row(f), limit);
        if (axis < 0)
          continue;
        if (markers++ == 0)
          example = take.label(m) + " " + "xyz"[axis] + " between frames " + std::to_string(take.firstFrame() + f - 1) +
                    " and " + std::to_string(take.firstFrame() + f) + " (" + numberText(xyz(f - 1, axis)) + " to " + numberText(xyz(f, axis)) +
                    ")";
        break;
      }
    }
    if (markers > 0)
      warnDataLoss(std::to_string(markers) + " marker(s) jump by over half the 16-bit range in one frame, e.g. " +
                   example + ": integer storage holds ±" + numberText(32767.0 * layout.scale) +
                   " at POINT:SCALE " + numberText(layout.scale) +
                   ", so coordinates past it have wrapped round and those samples are wrong");
  }

  /// The axis on which two consecutive positions differ by more than `limit`, or −1.
  static Eigen::Index wrappedAxis(const Eigen::RowVector3d& before, const Eigen::RowVector3d& after, double limit)
  {
    for (Eigen::Index axis = 0; axis < 3; ++axis)
      if (std::abs(after(axis) - before(axis)) > limit)
        return axis;
    return -1;
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
    if (layout.analog.channels == 0)
      return;
    const std::size_t bpv = layout.bytesPerValue();
    const std::size_t frameBytes = layout.frameBytes();
    const std::size_t channels = layout.analog.channels;
    const std::size_t samples = layout.analog.samples;
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
  C3dLayoutReport* m_layoutReport;
  std::optional<ResidualCounts> m_residualCounts;  // set by decodeFrames
  bool m_unitDeclared = false;  // POINT:UNITS names a length unit (set by makeTake)
  Processor m_processor = Processor::Intel;
  Header m_header;
  std::size_t m_parameterOffset = 0;
  std::size_t m_parameterEnd = 0;  // past the last byte a parameter record used
  C3dParameterTree m_tree;
};

} // namespace

Take parseC3d(const unsigned char* data, std::size_t size, const std::string& sourceName,
              std::vector<std::string>* warnings, std::vector<std::string>* dataLoss, C3dLayoutReport* layout)
{
  std::vector<std::string> own;  // findings are recorded with the take even when the caller does not ask for them
  std::vector<std::string>& findings = dataLoss ? *dataLoss : own;
  const std::size_t firstNew = findings.size();
  Take take = C3dParser(data, size, sourceName, warnings, &findings, layout).parse();
  carryDataLoss(take, sourceName, findings, firstNew, warnings);
  return take;
}

Take readC3d(const std::filesystem::path& path, std::vector<std::string>* warnings, std::vector<std::string>* dataLoss,
             C3dLayoutReport* layout)
{
  const MappedFile file(path);
  return parseC3d(file.data(), file.size(), path.string(), warnings, dataLoss, layout);
}

} // namespace mocap
