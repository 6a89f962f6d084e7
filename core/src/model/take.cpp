#include "mocap/model/take.h"

#include "mocap/base/enum_table.h"
#include "mocap/base/error.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace mocap {

Eigen::VectorXd AnalogData::physical(Eigen::Index c) const
{
  if (c < 0 || c >= channelCount())
    throw InvalidArgument("analog channel " + std::to_string(c) + " out of range");
  const AnalogChannel& channel = channels[static_cast<std::size_t>(c)];
  return ((stored.col(c).array() - channel.offset) * (channel.scale * generalScale)).matrix();
}

namespace {

constexpr EnumTable<PointType, kPointTypeCount> kPointTypes{{{
    {PointType::Marker, "marker"},
    {PointType::Angle, "angle"},
    {PointType::Force, "force"},
    {PointType::Moment, "moment"},
    {PointType::Power, "power"},
    {PointType::Other, "other"},
    {PointType::Virtual, "virtual"},
}}};

/// "M<index+1>", suffixed "_2", "_3"... until it is none of `labels` and not in `seen`.
/// O(1) expected per suffix tried.
std::string fallbackLabel(std::size_t index, const std::unordered_set<std::string>& labels,
                          const std::unordered_set<std::string>& seen)
{
  const std::string base = "M" + std::to_string(index + 1);
  std::string candidate = base;
  for (int suffix = 2; labels.count(candidate) != 0 || seen.count(candidate) != 0; ++suffix)
    candidate = base + "_" + std::to_string(suffix);
  return candidate;
}

} // namespace

std::string_view pointTypeName(PointType type)
{
  return kPointTypes.name(type, "other");
}

std::optional<PointType> parsePointType(std::string_view name)
{
  return kPointTypes.parse(name);
}

std::vector<std::string> makeLabelsUnique(std::vector<std::string>& labels)
{
  std::vector<std::string> warnings;
  const std::unordered_set<std::string> given(labels.begin(), labels.end());
  std::unordered_set<std::string> seen;
  // Next suffix to try per label, so a label repeated n times costs O(n), not O(n²).
  std::unordered_map<std::string, int> nextSuffix;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    std::string& label = labels[i];
    if (label.empty()) {
      label = fallbackLabel(i, given, seen);
      warnings.push_back("marker " + std::to_string(i + 1) + " has no label; named " + label);
    }
    if (seen.insert(label).second)
      continue;
    int& suffix = nextSuffix.try_emplace(label, 2).first->second;
    std::string candidate;
    for (;; ++suffix) {
      candidate = label + "_" + std::to_string(suffix);
      if (seen.count(candidate) == 0)
        break;
    }
    ++suffix;
    warnings.push_back("duplicate marker label '" + label + "' renamed to '" + candidate + "'");
    label = candidate;
    seen.insert(label);
  }
  return warnings;
}

std::vector<Eigen::Index> markerIndices(const Take& take, const std::vector<std::string>& labels)
{
  std::vector<Eigen::Index> indices;
  indices.reserve(labels.size());
  for (const std::string& label : labels) {
    const auto index = take.markerIndex(label);
    if (!index)
      throw InvalidArgument("the take has no marker labelled '" + label + "'");
    indices.push_back(*index);
  }
  return indices;
}

Take::Take(std::vector<std::string> labels, Eigen::Index frameCount, double frameRate)
    : Take(std::move(labels), frameCount, frameRate, Uninitialized{})
{
  std::fill_n(m_positions.data(), m_positions.size(), 0.0);
  std::fill_n(m_valid.data(), m_valid.size(), false);
  std::fill_n(m_residuals.data(), m_residuals.size(), -1.0);
  std::fill_n(m_cameraMasks.data(), m_cameraMasks.size(), std::uint8_t{0});
}

Take::Take(std::vector<std::string> labels, Eigen::Index frameCount, double frameRate, Uninitialized)
    : m_labels(std::move(labels)), m_frameCount(frameCount)
{
  if (frameCount < 0)
    throw InvalidArgument("negative frame count");
  setFrameRate(frameRate);
  makeLabelsUnique(m_labels);
  m_pointTypes.assign(m_labels.size(), PointType::Marker);
  const auto samples = static_cast<std::size_t>(markerCount() * frameCount);
  m_positions = SampleBuffer<double>(samples * 3);
  m_valid = SampleBuffer<bool>(samples);
  m_residuals = SampleBuffer<double>(samples);
  m_cameraMasks = SampleBuffer<std::uint8_t>(samples);
  m_states = SampleBuffer<std::uint8_t>(samples);
  std::fill_n(m_states.data(), samples, std::uint8_t{0});
}

const std::string& Take::label(Eigen::Index marker) const
{
  checkIndex(0, marker);
  return m_labels[static_cast<std::size_t>(marker)];
}

void Take::setLabel(Eigen::Index marker, std::string label)
{
  checkIndex(0, marker);
  if (label.empty())
    throw InvalidArgument("a marker label cannot be empty");
  const auto existing = markerIndex(label);
  if (existing && *existing != marker)
    throw InvalidArgument("marker label '" + label + "' is already used");
  m_labels[static_cast<std::size_t>(marker)] = std::move(label);
}

PointType Take::pointType(Eigen::Index marker) const
{
  checkIndex(0, marker);
  return m_pointTypes[static_cast<std::size_t>(marker)];
}

void Take::setPointType(Eigen::Index marker, PointType type)
{
  checkIndex(0, marker);
  m_pointTypes[static_cast<std::size_t>(marker)] = type;
}

std::optional<Eigen::Index> Take::markerIndex(std::string_view label) const
{
  for (std::size_t i = 0; i < m_labels.size(); ++i)
    if (m_labels[i] == label)
      return static_cast<Eigen::Index>(i);
  return std::nullopt;
}

void Take::setFrameRate(double rate)
{
  if (!std::isfinite(rate) || rate <= 0.0)
    throw InvalidArgument("frame rate must be a positive number, got " + std::to_string(rate));
  m_frameRate = rate;
}

void Take::convertUnits(LengthUnit unit)
{
  const double factor = millimetresPer(m_units) / millimetresPer(unit);
  m_units = unit;
  if (factor == 1.0)
    return;
  Eigen::Map<Eigen::VectorXd>(m_positions.data(), static_cast<Eigen::Index>(m_positions.size())) *= factor;
  auto r = residuals();
  r = (r >= 0.0).select(r * factor, r);
}

TrajectoryMap Take::trajectory(Eigen::Index marker)
{
  checkIndex(0, marker);
  return TrajectoryMap(m_positions.data() + marker * m_frameCount * 3, m_frameCount, 3);
}

ConstTrajectoryMap Take::trajectory(Eigen::Index marker) const
{
  checkIndex(0, marker);
  return ConstTrajectoryMap(m_positions.data() + marker * m_frameCount * 3, m_frameCount, 3);
}

Eigen::Vector3d Take::position(Eigen::Index frame, Eigen::Index marker) const
{
  checkIndex(frame, marker);
  const double* block = m_positions.data() + marker * m_frameCount * 3;
  return {block[frame], block[frame + m_frameCount], block[frame + 2 * m_frameCount]};
}

void Take::setPosition(Eigen::Index frame, Eigen::Index marker, const Eigen::Vector3d& xyz)
{
  checkIndex(frame, marker);
  double* block = m_positions.data() + marker * m_frameCount * 3;
  block[frame] = xyz.x();
  block[frame + m_frameCount] = xyz.y();
  block[frame + 2 * m_frameCount] = xyz.z();
}

SampleState Take::state(Eigen::Index frame, Eigen::Index marker) const
{
  checkIndex(frame, marker);
  return SampleState::fromBits(m_states.data()[marker * m_frameCount + frame]);
}

void Take::setState(Eigen::Index frame, Eigen::Index marker, SampleState state)
{
  checkIndex(frame, marker);
  m_states.data()[marker * m_frameCount + frame] = state.bits();
}

Eigen::Index Take::addMarker(std::string label)
{
  std::vector<std::string> labels = m_labels;
  labels.push_back(std::move(label));
  makeLabelsUnique(labels);
  m_labels = std::move(labels);
  m_pointTypes.push_back(PointType::Marker);
  // Column-major per-marker storage: a new marker is a new block at the end of each buffer.
  const auto frames = static_cast<std::size_t>(m_frameCount);
  auto appendBlock = [](auto& buffer, std::size_t count, auto value) {
    const std::size_t old = buffer.size();
    buffer.resize(old + count);
    std::fill_n(buffer.data() + old, count, value);
  };
  appendBlock(m_positions, frames * 3, 0.0);
  appendBlock(m_valid, frames, false);
  appendBlock(m_residuals, frames, -1.0);
  appendBlock(m_cameraMasks, frames, std::uint8_t{0});
  appendBlock(m_states, frames, std::uint8_t{0});
  return markerCount() - 1;
}

namespace {

// Moves the block of `count` elements at `from` to `to` (block indices) by rotation, shifting the
// blocks in between by one. O(buffer size).
template <typename T>
void moveBlock(SampleBuffer<T>& buffer, std::size_t count, std::size_t from, std::size_t to)
{
  T* data = buffer.data();
  if (from < to)
    std::rotate(data + from * count, data + (from + 1) * count, data + (to + 1) * count);
  else if (to < from)
    std::rotate(data + to * count, data + from * count, data + (from + 1) * count);
}

} // namespace

MarkerColumn Take::column(Eigen::Index marker) const
{
  checkIndex(0, marker);
  MarkerColumn column;
  column.label = m_labels[static_cast<std::size_t>(marker)];
  column.type = m_pointTypes[static_cast<std::size_t>(marker)];
  column.positions = trajectory(marker);
  column.valid = valid().col(marker);
  column.residuals = residuals().col(marker);
  const auto frames = static_cast<std::size_t>(m_frameCount);
  const auto offset = static_cast<std::size_t>(marker) * frames;
  column.cameraMasks.assign(m_cameraMasks.data() + offset, m_cameraMasks.data() + offset + frames);
  column.states.resize(frames);
  for (std::size_t f = 0; f < frames; ++f)
    column.states[f] = SampleState::fromBits(m_states.data()[offset + f]);
  return column;
}

MarkerColumn Take::removeMarker(Eigen::Index marker)
{
  if (marker < 0 || marker >= markerCount())
    throw InvalidArgument("no marker " + std::to_string(marker) + " to remove: the take has " +
                          std::to_string(markerCount()) + " markers");
  MarkerColumn removed = column(marker);
  const auto frames = static_cast<std::size_t>(m_frameCount);
  const auto index = static_cast<std::size_t>(marker);
  const std::size_t last = m_labels.size() - 1;
  auto dropBlock = [&](auto& buffer, std::size_t count) {
    moveBlock(buffer, count, index, last);
    buffer.resize(buffer.size() - count);
  };
  dropBlock(m_positions, frames * 3);
  dropBlock(m_valid, frames);
  dropBlock(m_residuals, frames);
  dropBlock(m_cameraMasks, frames);
  dropBlock(m_states, frames);
  m_labels.erase(m_labels.begin() + static_cast<std::ptrdiff_t>(marker));
  m_pointTypes.erase(m_pointTypes.begin() + static_cast<std::ptrdiff_t>(marker));
  return removed;
}

void Take::insertMarker(Eigen::Index marker, MarkerColumn column)
{
  if (marker < 0 || marker > markerCount())
    throw InvalidArgument("cannot insert a marker at index " + std::to_string(marker) + ": the take has " +
                          std::to_string(markerCount()) + " markers");
  const auto frames = static_cast<std::size_t>(m_frameCount);
  if (column.frameCount() != m_frameCount || column.valid.size() != m_frameCount ||
      column.residuals.size() != m_frameCount || column.cameraMasks.size() != frames ||
      column.states.size() != frames)
    throw InvalidArgument("marker '" + column.label + "' has " + std::to_string(column.frameCount()) +
                          " frames but the take has " + std::to_string(m_frameCount));
  if (column.label.empty())
    throw InvalidArgument("a marker needs a label");
  if (markerIndex(column.label))
    throw InvalidArgument("the take already has a marker labelled '" + column.label + "'");
  const auto index = static_cast<std::size_t>(marker);
  const std::size_t last = m_labels.size();
  auto addBlock = [&](auto& buffer, std::size_t count, const auto* values) {
    const std::size_t old = buffer.size();
    buffer.resize(old + count);
    std::copy_n(values, count, buffer.data() + old);
    moveBlock(buffer, count, last, index);
  };
  std::vector<std::uint8_t> states(frames);
  for (std::size_t f = 0; f < frames; ++f)
    states[f] = column.states[f].bits();
  addBlock(m_positions, frames * 3, column.positions.data());
  addBlock(m_valid, frames, column.valid.data());
  addBlock(m_residuals, frames, column.residuals.data());
  addBlock(m_cameraMasks, frames, column.cameraMasks.data());
  addBlock(m_states, frames, states.data());
  m_labels.insert(m_labels.begin() + static_cast<std::ptrdiff_t>(marker), std::move(column.label));
  m_pointTypes.insert(m_pointTypes.begin() + static_cast<std::ptrdiff_t>(marker), column.type);
}

double Take::validFraction() const
{
  if (m_valid.size() == 0)
    return 0.0;
  return static_cast<double>(valid().count()) / static_cast<double>(m_valid.size());
}

void Take::checkIndex(Eigen::Index frame, Eigen::Index marker) const
{
  if (marker < 0 || marker >= markerCount())
    throw InvalidArgument("marker index " + std::to_string(marker) + " out of range (take has " +
                          std::to_string(markerCount()) + " markers)");
  if (frame < 0 || (frame >= m_frameCount && !(frame == 0 && m_frameCount == 0)))
    throw InvalidArgument("frame index " + std::to_string(frame) + " out of range (take has " +
                          std::to_string(m_frameCount) + " frames)");
}

} // namespace mocap
