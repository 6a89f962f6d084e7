// libFuzzer target for the C3D reader's choice of data layout: starting from valid files, it
// changes only the header's and the parameters' pointers and counts (data start, point and analog
// counts, frames, scale, rates), never the data. Any such file must load or raise mocap::Error, and
// a file that loads must not have been read past its end: the data start plus the frames read
// times the frame size fit in the file.
#include "mocap/base/error.h"
#include "mocap/io/c3d_binary.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/model/take.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

namespace {

using mocap::c3d::Processor;

enum class FieldType
{
  U8,
  I16,
  F32,
};

/// One number of the header or the parameter section that says where data is or how much there is.
struct Field
{
  std::size_t offset = 0;
  FieldType type = FieldType::I16;
};

std::optional<Processor> processorOf(const std::uint8_t* data, std::size_t size)
{
  if (size < 2 * mocap::c3d::kBlockSize || data[0] == 0)
    return std::nullopt;
  const std::size_t parameters = (std::size_t{data[0]} - 1) * mocap::c3d::kBlockSize;
  if (parameters + 4 > size)
    return std::nullopt;
  const int type = data[parameters + 3];
  if (type < 84 || type > 86)
    return std::nullopt;
  return static_cast<Processor>(type);
}

/// The header words that hold pointers and counts (C3D user guide, the header section).
void addHeaderFields(std::vector<Field>& fields)
{
  fields.push_back({0, FieldType::U8});    // parameter section's first block
  fields.push_back({2, FieldType::I16});   // points per frame
  fields.push_back({4, FieldType::I16});   // analog values per frame
  fields.push_back({6, FieldType::I16});   // first frame
  fields.push_back({8, FieldType::I16});   // last frame
  fields.push_back({12, FieldType::F32});  // scale (negative: float storage)
  fields.push_back({16, FieldType::I16});  // data section's first block
  fields.push_back({18, FieldType::I16});  // analog samples per frame
  fields.push_back({20, FieldType::F32});  // frame rate
}

struct ParameterName
{
  std::string_view group;
  std::string_view name;
};

constexpr std::array kLayoutParameters{
    ParameterName{"POINT", "USED"},         ParameterName{"POINT", "FRAMES"},
    ParameterName{"POINT", "LONG_FRAMES"},  ParameterName{"POINT", "DATA_START"},
    ParameterName{"POINT", "SCALE"},        ParameterName{"POINT", "RATE"},
    ParameterName{"ANALOG", "USED"},        ParameterName{"ANALOG", "RATE"},
    ParameterName{"TRIAL", "ACTUAL_START_FIELD"}, ParameterName{"TRIAL", "ACTUAL_END_FIELD"},
};

bool namedAs(const std::uint8_t* name, std::size_t length, std::string_view wanted)
{
  return length == wanted.size() && std::memcmp(name, wanted.data(), length) == 0;
}

/// Walks the parameter section and adds the value of each layout parameter (every element of it).
/// Stops at the first record that does not fit, so a broken section yields fewer fields.
void addParameterFields(const std::uint8_t* data, std::size_t size, Processor processor, std::vector<Field>& fields)
{
  const std::size_t start = (std::size_t{data[0]} - 1) * mocap::c3d::kBlockSize;
  constexpr std::array<std::string_view, 3> groups{"POINT", "ANALOG", "TRIAL"};
  std::array<int, 3> idOfGroup{0, 0, 0};
  // Two passes: groups may come after their parameters.
  for (int pass = 0; pass < 2; ++pass) {
    std::size_t at = start + 4;
    while (at + 2 <= size) {
      const int nameLength = std::abs(static_cast<std::int8_t>(data[at]));
      const int id = static_cast<std::int8_t>(data[at + 1]);
      if (nameLength == 0 || at + 4 + static_cast<std::size_t>(nameLength) > size)
        return;
      const std::uint8_t* name = data + at + 2;
      const std::size_t next = at + 2 + static_cast<std::size_t>(nameLength);
      const std::int16_t step = mocap::c3d::readI16(data + next, processor);
      if (pass == 0 && id < 0) {
        for (std::size_t g = 0; g < groups.size(); ++g)
          if (namedAs(name, static_cast<std::size_t>(nameLength), groups[g]))
            idOfGroup[g] = -id;
      }
      if (pass == 1 && id > 0 && next + 4 <= size) {
        const int type = static_cast<std::int8_t>(data[next + 2]);
        const std::size_t dimensions = data[next + 3];
        std::size_t count = 1;
        for (std::size_t d = 0; d < dimensions && next + 4 + d < size; ++d)
          count *= data[next + 4 + d];
        const std::size_t values = next + 4 + dimensions;
        for (const ParameterName& wanted : kLayoutParameters) {
          std::size_t g = 0;
          while (groups[g] != wanted.group)
            ++g;
          if (idOfGroup[g] != id || !namedAs(name, static_cast<std::size_t>(nameLength), wanted.name))
            continue;
          const std::size_t bytes = type == 4 ? 4 : type == 2 ? 2 : 1;
          for (std::size_t i = 0; i < count && values + (i + 1) * bytes <= size; ++i)
            fields.push_back({values + i * bytes, type == 4 ? FieldType::F32 : type == 2 ? FieldType::I16 : FieldType::U8});
        }
      }
      if (step <= 0)
        break;
      at = next + static_cast<std::size_t>(step);
    }
  }
}

void writeI16(std::uint8_t* p, std::int16_t value, Processor processor)
{
  const auto u = static_cast<std::uint16_t>(value);
  if (processor == Processor::Mips) {
    p[0] = static_cast<std::uint8_t>(u >> 8);
    p[1] = static_cast<std::uint8_t>(u & 0xFFu);
  } else {
    p[0] = static_cast<std::uint8_t>(u & 0xFFu);
    p[1] = static_cast<std::uint8_t>(u >> 8);
  }
}

/// The inverse of c3d::readF32 (a VAX F-float is an IEEE single with the exponent two higher and
/// its 16-bit words swapped; values it cannot hold become zero).
void writeF32(std::uint8_t* p, float value, Processor processor)
{
  std::uint32_t bits;
  std::memcpy(&bits, &value, 4);
  switch (processor) {
  case Processor::Intel:
    std::memcpy(p, &bits, 4);
    return;
  case Processor::Mips:
    for (int i = 0; i < 4; ++i)
      p[i] = static_cast<std::uint8_t>(bits >> (24 - 8 * i));
    return;
  case Processor::Dec:
    if (((bits >> 23) & 0xFFu) >= 0xFDu || ((bits >> 23) & 0xFFu) == 0)
      bits &= 0x80000000u;
    else
      bits += (2u << 23);
    p[0] = static_cast<std::uint8_t>(bits >> 16);
    p[1] = static_cast<std::uint8_t>(bits >> 24);
    p[2] = static_cast<std::uint8_t>(bits);
    p[3] = static_cast<std::uint8_t>(bits >> 8);
    return;
  }
}

/// A new integer for a pointer or count: the edge values readers get wrong, a step of one or of a
/// block's worth of words, a scaling, or anything.
int mutatedInteger(int old, std::mt19937& random)
{
  switch (random() % 10) {
  case 0: return 0;
  case 1: return 1;
  case 2: return -1;
  case 3: return old + 1;
  case 4: return old - 1;
  case 5: return old + (random() % 2 == 0 ? 256 : -256);
  case 6: return old * 2;
  case 7: return old / 2;
  case 8: return random() % 2 == 0 ? 32767 : -32768;
  default: return static_cast<int>(random() % 65536) - 32768;
  }
}

float mutatedFloat(float old, std::mt19937& random)
{
  switch (random() % 9) {
  case 0: return 0.0f;
  case 1: return -old;
  case 2: return old * 2.0f;
  case 3: return old / 2.0f;
  case 4: return old * 2.6f;
  case 5: return std::numeric_limits<float>::quiet_NaN();
  case 6: return std::numeric_limits<float>::infinity();
  case 7: return 1e30f;
  default: return std::uniform_real_distribution<float>(-1000.0f, 1000.0f)(random);
  }
}

void mutate(std::uint8_t* data, const Field& field, Processor processor, std::mt19937& random)
{
  std::uint8_t* p = data + field.offset;
  switch (field.type) {
  case FieldType::U8:
    *p = static_cast<std::uint8_t>(mutatedInteger(*p, random));
    return;
  case FieldType::I16:
    writeI16(p, static_cast<std::int16_t>(mutatedInteger(mocap::c3d::readI16(p, processor), random)), processor);
    return;
  case FieldType::F32:
    writeF32(p, mutatedFloat(mocap::c3d::readF32(p, processor), random), processor);
    return;
  }
}

} // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t /*maxSize*/,
                                               unsigned int seed)
{
  std::mt19937 random(seed);
  const int changes = 1 + static_cast<int>(random() % 3);
  for (int change = 0; change < changes; ++change) {
    const std::optional<Processor> processor = processorOf(data, size);
    if (!processor)
      return size;  // not a C3D file any more: nothing left to point at
    std::vector<Field> fields;
    addHeaderFields(fields);
    addParameterFields(data, size, *processor, fields);
    mutate(data, fields[random() % fields.size()], *processor, random);
  }
  return size;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  mocap::C3dLayoutReport layout;
  try {
    const mocap::Take take = mocap::parseC3d(data, size, "fuzz.c3d", nullptr, nullptr, &layout);
    const std::size_t start = (layout.dataStartBlock - 1) * mocap::c3d::kBlockSize;
    const auto frames = static_cast<std::size_t>(take.frameCount());
    if (layout.dataStartBlock == 0 || start > size || (layout.frameBytes > 0 && frames > (size - start) / layout.frameBytes)) {
      std::fprintf(stderr, "read past the end: data start block %zu, %zu frames of %zu bytes, file %zu bytes\n",
                   layout.dataStartBlock, frames, layout.frameBytes, size);
      std::abort();
    }
  } catch (const mocap::Error&) {
  }
  return 0;
}
