#pragma once

#include "mocap/model/c3d_parameters.h"
#include "mocap/base/length_unit.h"
#include "mocap/model/processing_step.h"
#include "mocap/model/sample_buffer.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// Where a sample's value came from. The numbers are the low two bits of a SampleState byte (and
/// the codes version 1 of the PROCESSING group gave filled and edited samples).
enum class SampleOrigin : std::uint8_t
{
  Measured = 0,  ///< as read from the capture (or never touched)
  Filled = 1,    ///< invented for a gap
  Edited = 3,    ///< replaced by a person or a repair (bad-point repair, a drag, a deletion)
};

/// What was done to a sample's value after it got its origin; bits of a SampleState byte, any
/// combination.
enum class SampleOperation : std::uint8_t
{
  Smoothed = 4,    ///< moved by a smoothing filter
  Stabilized = 8,  ///< held in the head frame (head motion removed and not restored)
};

/// What happened to a sample since it was read, so views can colour it and exports can say so:
/// its origin and the operations applied to it since, in one byte (origin in bits 0-1,
/// operations in bits 2-3). A filled sample that is smoothed stays filled and is also smoothed;
/// a new origin clears the operations, which were done to a value that is gone.
class SampleState
{
public:
  static constexpr std::uint8_t kOriginBits = 0x03;
  static constexpr std::uint8_t kOperationBits = 0x0C;

  constexpr SampleState() = default;
  /// An origin with no operations (implicit: that is what a bare origin means).
  constexpr SampleState(SampleOrigin origin) : m_bits(static_cast<std::uint8_t>(origin)) {}  // NOLINT
  /// The state a stored byte holds; unknown bits (and the unused origin 2) are dropped. O(1).
  [[nodiscard]] static constexpr SampleState fromBits(std::uint8_t bits)
  {
    SampleState state;
    const auto origin = static_cast<std::uint8_t>(bits & kOriginBits);
    state.m_bits = static_cast<std::uint8_t>((origin == 2 ? 0 : origin) | (bits & kOperationBits));
    return state;
  }
  [[nodiscard]] constexpr std::uint8_t bits() const { return m_bits; }
  [[nodiscard]] constexpr SampleOrigin origin() const { return static_cast<SampleOrigin>(m_bits & kOriginBits); }
  /// The operation bits (SampleOperation values or'ed).
  [[nodiscard]] constexpr std::uint8_t operations() const { return static_cast<std::uint8_t>(m_bits & kOperationBits); }
  [[nodiscard]] constexpr bool has(SampleOperation operation) const
  {
    return (m_bits & static_cast<std::uint8_t>(operation)) != 0;
  }
  [[nodiscard]] constexpr SampleState with(SampleOperation operation) const
  {
    return fromBits(static_cast<std::uint8_t>(m_bits | static_cast<std::uint8_t>(operation)));
  }
  [[nodiscard]] constexpr SampleState without(SampleOperation operation) const
  {
    return fromBits(static_cast<std::uint8_t>(m_bits & ~static_cast<std::uint8_t>(operation)));
  }
  /// Measured and never operated on.
  [[nodiscard]] constexpr bool untouched() const { return m_bits == 0; }

  friend constexpr bool operator==(SampleState a, SampleState b) { return a.m_bits == b.m_bits; }
  friend constexpr bool operator!=(SampleState a, SampleState b) { return a.m_bits != b.m_bits; }

private:
  std::uint8_t m_bits = 0;
};

/// What one point of a take holds: a measured marker, or a model output C3D stores as a point
/// (Vicon Nexus's joint angles, forces, moments and powers; `Other` for further kinds a file names;
/// `Virtual` for a model's positions that no camera saw: Plug-in Gait's segment axes PELO, LFEA…,
/// its CentreOfMass).
enum class PointType : std::uint8_t
{
  Marker = 0,
  Angle = 1,
  Force = 2,
  Moment = 3,
  Power = 4,
  Other = 5,
  Virtual = 6,
};

/// How many PointType values there are: the size of a count per type.
inline constexpr std::size_t kPointTypeCount = 7;

/// "marker", "angle", "force", "moment", "power", "other", "virtual". O(1).
[[nodiscard]] std::string_view pointTypeName(PointType type);
/// The type pointTypeName gives `name` (lower case), or nullopt. O(1).
[[nodiscard]] std::optional<PointType> parsePointType(std::string_view name);

/// Validity of one trajectory: #frames booleans.
using ValidMask = Eigen::Array<bool, Eigen::Dynamic, 1>;
/// Per-sample arrays of a take: #frames × #markers, column m is marker m.
using SampleMask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;
using SampleBytes = Eigen::Array<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic>;
/// One marker's trajectory, #frames × 3 (x, y, z columns), viewing the take's storage.
using TrajectoryMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3>>;
using ConstTrajectoryMap = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3>>;
/// Views of a take's per-sample arrays (#frames × #markers).
using SampleMaskMap = Eigen::Map<SampleMask>;
using ConstSampleMaskMap = Eigen::Map<const SampleMask>;
using ResidualMap = Eigen::Map<Eigen::ArrayXXd>;
using ConstResidualMap = Eigen::Map<const Eigen::ArrayXXd>;
using SampleBytesMap = Eigen::Map<SampleBytes>;
using ConstSampleBytesMap = Eigen::Map<const SampleBytes>;

/// One analog channel's identity and the conversion from stored to physical values:
/// physical = (stored − offset) · scale · generalScale (C3D ANALOG:SCALE, OFFSET, GEN_SCALE).
struct AnalogChannel
{
  std::string label;
  std::string description;
  std::string unit;
  double scale = 1.0;
  double offset = 0.0;
};

/// Analog channels sampled at an integer multiple of the point rate.
struct AnalogData
{
  double rate = 0.0;           ///< samples per second of each channel
  double generalScale = 1.0;   ///< ANALOG:GEN_SCALE
  std::vector<AnalogChannel> channels;
  /// Stored values as in the file (before scaling), #samples × #channels; doubles hold int16
  /// and float exactly, so a round trip is exact.
  Eigen::MatrixXd stored;

  [[nodiscard]] Eigen::Index sampleCount() const { return stored.rows(); }
  [[nodiscard]] Eigen::Index channelCount() const { return stored.cols(); }
  /// Channel `c` in physical units.
  [[nodiscard]] Eigen::VectorXd physical(Eigen::Index c) const;
};

/// A labelled moment of the take (C3D EVENT group or header events).
struct Event
{
  std::string label;
  std::string context;      ///< e.g. "Left", "Right", "General"
  std::string description;
  std::string subject;
  double time = 0.0;        ///< seconds from the start of the trial
};

/// Everything a take holds for one marker, detached from it: what removeMarker hands back and
/// insertMarker takes, so deleting a marker can be undone bit for bit.
struct MarkerColumn
{
  std::string label;
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;  ///< #frames × 3
  ValidMask valid;
  Eigen::ArrayXd residuals;
  std::vector<std::uint8_t> cameraMasks;
  std::vector<SampleState> states;
  PointType type = PointType::Marker;

  [[nodiscard]] Eigen::Index frameCount() const { return positions.rows(); }
};

/// A motion-capture take: labelled marker trajectories with an explicit validity mask,
/// residuals, camera masks and per-sample edit states, plus analog data, events and the full
/// C3D parameter tree so a round trip loses nothing.
///
/// Positions are one contiguous buffer of #markers blocks, each a column-major #frames × 3
/// matrix, so a trajectory is one Eigen::Map and per-marker algorithms touch contiguous memory.
/// Invalid samples keep whatever position they hold; only `valid()` says whether they count.
class Take
{
public:
  Take() = default;
  /// A take with the given labels (made unique), every sample invalid at the origin.
  Take(std::vector<std::string> labels, Eigen::Index frameCount, double frameRate);

  /// Tag for readers that overwrite every sample: skips clearing positions, validity,
  /// residuals and camera masks (states start Original), which saves a pass over the take.
  struct Uninitialized
  {
  };
  Take(std::vector<std::string> labels, Eigen::Index frameCount, double frameRate, Uninitialized);

  [[nodiscard]] Eigen::Index frameCount() const { return m_frameCount; }
  [[nodiscard]] Eigen::Index markerCount() const { return static_cast<Eigen::Index>(m_labels.size()); }
  [[nodiscard]] bool empty() const { return m_frameCount == 0 || m_labels.empty(); }

  [[nodiscard]] const std::vector<std::string>& labels() const { return m_labels; }
  [[nodiscard]] const std::string& label(Eigen::Index marker) const;
  /// Renames a marker; throws InvalidArgument when another marker already has `label`.
  void setLabel(Eigen::Index marker, std::string label);
  [[nodiscard]] std::optional<Eigen::Index> markerIndex(std::string_view label) const;
  /// What marker `marker` holds: Marker unless a reader said otherwise. The type travels with the
  /// marker (column, removeMarker, insertMarker).
  [[nodiscard]] PointType pointType(Eigen::Index marker) const;
  void setPointType(Eigen::Index marker, PointType type);

  [[nodiscard]] double frameRate() const { return m_frameRate; }
  /// Throws InvalidArgument unless `rate` is finite and positive.
  void setFrameRate(double rate);
  /// Number of the first frame as the capture system counts (C3D header word 4, 1-based usually).
  [[nodiscard]] std::int64_t firstFrame() const { return m_firstFrame; }
  void setFirstFrame(std::int64_t frame) { m_firstFrame = frame; }
  /// Seconds from the first frame to frame index `frame` (0-based).
  [[nodiscard]] double timeOf(Eigen::Index frame) const { return static_cast<double>(frame) / m_frameRate; }

  [[nodiscard]] LengthUnit units() const { return m_units; }
  /// Labels the data with `unit` without touching the numbers (use convertUnits to rescale).
  void setUnits(LengthUnit unit) { m_units = unit; }
  /// Rescales positions and residuals to `unit`. O(#frames · #markers).
  void convertUnits(LengthUnit unit);

  [[nodiscard]] TrajectoryMap trajectory(Eigen::Index marker);
  [[nodiscard]] ConstTrajectoryMap trajectory(Eigen::Index marker) const;
  [[nodiscard]] Eigen::Vector3d position(Eigen::Index frame, Eigen::Index marker) const;
  void setPosition(Eigen::Index frame, Eigen::Index marker, const Eigen::Vector3d& xyz);
  /// The whole position buffer (#markers · #frames · 3 doubles, per-marker blocks).
  [[nodiscard]] double* positionData() { return m_positions.data(); }
  [[nodiscard]] const double* positionData() const { return m_positions.data(); }

  [[nodiscard]] SampleMaskMap valid() { return {m_valid.data(), m_frameCount, markerCount()}; }
  [[nodiscard]] ConstSampleMaskMap valid() const { return {m_valid.data(), m_frameCount, markerCount()}; }
  [[nodiscard]] bool isValid(Eigen::Index frame, Eigen::Index marker) const { return valid()(frame, marker); }
  /// Residual of each sample in the take's units (0 for a filled or perfect sample; −1 when invalid).
  [[nodiscard]] ResidualMap residuals() { return {m_residuals.data(), m_frameCount, markerCount()}; }
  [[nodiscard]] ConstResidualMap residuals() const { return {m_residuals.data(), m_frameCount, markerCount()}; }
  /// C3D camera contribution bits (high byte of the residual word), 0 when unknown.
  [[nodiscard]] SampleBytesMap cameraMasks() { return {m_cameraMasks.data(), m_frameCount, markerCount()}; }
  [[nodiscard]] ConstSampleBytesMap cameraMasks() const { return {m_cameraMasks.data(), m_frameCount, markerCount()}; }
  [[nodiscard]] SampleState state(Eigen::Index frame, Eigen::Index marker) const;
  void setState(Eigen::Index frame, Eigen::Index marker, SampleState state);
  [[nodiscard]] ConstSampleBytesMap states() const { return {m_states.data(), m_frameCount, markerCount()}; }
  /// The states as bytes (each a SampleState's bits()), for loops over many samples without
  /// setState's index check per sample; write only SampleState bits.
  [[nodiscard]] SampleBytesMap states() { return {m_states.data(), m_frameCount, markerCount()}; }

  /// Appends a marker (label made unique) with every sample invalid; returns its index.
  Eigen::Index addMarker(std::string label);
  /// Takes marker `marker` out of the take and returns it (later markers move down one index).
  /// Throws InvalidArgument for an index outside the take. O(#frames · #markers).
  MarkerColumn removeMarker(Eigen::Index marker);
  /// Puts `column` in as marker `marker` (0..markerCount(); later markers move up one index).
  /// Throws InvalidArgument when the index is out of range, the column's frame count or array
  /// sizes differ from the take's, or its label is empty or already taken (the take is then
  /// unchanged). O(#frames · #markers).
  void insertMarker(Eigen::Index marker, MarkerColumn column);
  /// A copy of marker `marker`'s data. O(#frames).
  [[nodiscard]] MarkerColumn column(Eigen::Index marker) const;
  /// Fraction of valid samples over all markers and frames (0 for an empty take).
  [[nodiscard]] double validFraction() const;

  [[nodiscard]] AnalogData& analog() { return m_analog; }
  [[nodiscard]] const AnalogData& analog() const { return m_analog; }
  [[nodiscard]] std::vector<Event>& events() { return m_events; }
  [[nodiscard]] const std::vector<Event>& events() const { return m_events; }
  /// The C3D parameter tree as read (empty for takes from other formats); writers update it.
  [[nodiscard]] C3dParameterTree& parameters() { return m_parameters; }
  [[nodiscard]] const C3dParameterTree& parameters() const { return m_parameters; }
  /// The processing steps applied to the take, oldest first (provenance.h stores them with the
  /// per-sample states in C3D files and sidecars).
  [[nodiscard]] std::vector<ProcessingStep>& history() { return m_history; }
  [[nodiscard]] const std::vector<ProcessingStep>& history() const { return m_history; }

private:
  void checkIndex(Eigen::Index frame, Eigen::Index marker) const;

  std::vector<std::string> m_labels;
  std::vector<PointType> m_pointTypes;  // one per label
  Eigen::Index m_frameCount = 0;
  double m_frameRate = 100.0;
  std::int64_t m_firstFrame = 1;
  LengthUnit m_units = LengthUnit::Millimetre;
  // Per-sample storage; see SampleBuffer for why it is not Eigen's own.
  SampleBuffer<double> m_positions;  // #markers blocks of #frames × 3, column-major
  SampleBuffer<bool> m_valid;        // the rest: #frames × #markers, column-major
  SampleBuffer<double> m_residuals;
  SampleBuffer<std::uint8_t> m_cameraMasks;
  SampleBuffer<std::uint8_t> m_states;
  AnalogData m_analog;
  std::vector<Event> m_events;
  C3dParameterTree m_parameters;
  std::vector<ProcessingStep> m_history;
};

/// The indices of `labels` in `take`, in the given order. Throws InvalidArgument naming the first
/// label the take does not have. O(#labels · #markers).
[[nodiscard]] std::vector<Eigen::Index> markerIndices(const Take& take, const std::vector<std::string>& labels);

/// Makes `labels` unique: an empty label becomes "M<index+1>", a repeated one gets "_2", "_3"...
/// The name given to an empty label avoids every label of the list, so a real "M3" keeps its name
/// when an earlier label is empty (that one becomes "M3_2").
/// Returns one warning per label it changed. O(#labels) expected.
std::vector<std::string> makeLabelsUnique(std::vector<std::string>& labels);

} // namespace mocap
