#include "mocap/io/pc2_io.h"

#include "mocap/base/error.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace mocap {

namespace {

constexpr char kMagic[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};
constexpr std::size_t kHeaderSize = 32;

template <typename T>
void put(std::string& out, std::size_t offset, T value)
{
  std::memcpy(out.data() + offset, &value, sizeof(T));
}

template <typename T>
T get(const unsigned char* bytes, std::size_t offset)
{
  T value;
  std::memcpy(&value, bytes + offset, sizeof(T));
  return value;
}

} // namespace

PointCache readPc2(const std::filesystem::path& path)
{
  const MappedFile file(path);
  return parsePc2(std::string_view(reinterpret_cast<const char*>(file.data()), file.size()), path.string());
}

PointCache parsePc2(std::string_view bytes, const std::string& name)
{
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < kHeaderSize || std::memcmp(data, kMagic, sizeof kMagic) != 0)
    throw FormatError(name, 0, "not a PC2 point cache (no POINTCACHE2 signature)");
  if (get<std::int32_t>(data, 12) != 1)
    throw FormatError(name, 12, "PC2 version " + std::to_string(get<std::int32_t>(data, 12)) + " (expected 1)");
  const std::int32_t points = get<std::int32_t>(data, 16);
  const std::int32_t samples = get<std::int32_t>(data, 28);
  if (points < 0 || samples < 0)
    throw FormatError(name, 16, "negative point or sample count");
  // Samples of no points take no bytes, so a 32-byte file could claim 2^31 of them.
  if (points == 0 && samples > 0)
    throw FormatError(name, 16, "samples of no points");
  const std::uint64_t expected = kHeaderSize + std::uint64_t{12} * static_cast<std::uint64_t>(points) *
                                                   static_cast<std::uint64_t>(samples);
  if (expected != bytes.size())
    throw FormatError(name, "size " + std::to_string(bytes.size()) + " bytes does not match " +
                                std::to_string(points) + " points × " + std::to_string(samples) +
                                " samples (" + std::to_string(expected) + " bytes)");
  PointCache cache;
  cache.startFrame = get<float>(data, 20);
  cache.sampleRate = get<float>(data, 24);
  const std::size_t block = 12u * static_cast<std::size_t>(points);
  for (std::int32_t s = 0; s < samples; ++s) {
    cache.samples.emplace_back(points, 3);
    std::memcpy(cache.samples.back().data(), data + kHeaderSize + block * static_cast<std::size_t>(s), block);
  }
  return cache;
}

Pc2Writer::Pc2Writer(const std::filesystem::path& path, Eigen::Index pointCount, float startFrame, float sampleRate)
    : m_file(path), m_header(kHeaderSize, '\0'), m_pointCount(pointCount)
{
  if (pointCount < 0 || pointCount > 100000000 || !std::isfinite(startFrame) || !(sampleRate > 0.0f))
    throw InvalidArgument("PC2: bad point count, start frame or sample rate");
  std::memcpy(m_header.data(), kMagic, sizeof kMagic);
  put<std::int32_t>(m_header, 12, 1);
  put<std::int32_t>(m_header, 16, static_cast<std::int32_t>(pointCount));
  put<float>(m_header, 20, startFrame);
  put<float>(m_header, 24, sampleRate);
  // The header is written with 0 samples first and patched by finish(), so frames can stream.
  m_file.write(m_header);
}

void Pc2Writer::addFrame(const Eigen::Ref<const MeshVertices>& points)
{
  if (points.rows() != m_pointCount)
    throw InvalidArgument("PC2: a frame of " + std::to_string(points.rows()) + " points for a cache of " +
                          std::to_string(m_pointCount));
  if (!points.allFinite())
    throw InvalidArgument("PC2: frame " + std::to_string(m_samples) + " has a coordinate that is not finite");
  m_buffer.resize(static_cast<std::size_t>(m_pointCount) * 12);
  const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> single = points.cast<float>();
  std::memcpy(m_buffer.data(), single.data(), m_buffer.size());
  m_file.write(m_buffer);
  ++m_samples;
}

void Pc2Writer::finish()
{
  put<std::int32_t>(m_header, 28, m_samples);
  m_file.patch(0, m_header);
  m_file.commit();
}

} // namespace mocap
