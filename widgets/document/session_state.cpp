#include "document/session_state.h"

#include "mocap/base/error.h"
#include "mocap/deform/actor_profile_io.h"

#include <QBuffer>
#include <QDataStream>

#include <cstdint>
#include <exception>
#include <string>
#include <type_traits>
#include <utility>

namespace mocap::ui {

// One description of each structure's fields (visitFields) serves both directions, so writing and
// reading cannot drift apart; the format is versioned as a whole: a version adds fields after the
// previous version's (visitFields asks the stream's version), so every earlier version still reads.
namespace session_state_format {

constexpr quint32 kMagic = 0x4d535354;  // "MSST"
/// 1: files, binding, curves, videos, layout plan; 2: + the actor profile and the retarget map.
constexpr quint32 kVersion = 2;
constexpr quint32 kFirstVersion = 1;
constexpr Eigen::Index kMaxMarkers = 1000000;  // far beyond any take; a larger count is damage

template <class Stream>
void visitFields(Stream& s, ReadWeightCurves& v)
{
  s(v.path, v.frameRate, v.recordedRate, v.startSeconds, v.firstTimecode, v.headRotation);
}

template <class Stream>
void visitFields(Stream& s, BlendshapeSolveResult& v)
{
  s(v.weights, v.residual, v.held, v.lambda, v.lambdaChosen, v.iterations, v.solveSeconds);
}

template <class Stream>
void visitFields(Stream& s, BlendshapeSolveOptions& v)
{
  s(v.method, v.lambda, v.smoothness, v.sparsity, v.scale, v.neutralFrame, v.minimumMarkerShare, v.maximumWeight);
}

template <class Stream>
void visitFields(Stream& s, SessionVideo& v)
{
  s(v.path, v.offset);
}

template <class Stream>
void visitFields(Stream& s, LayoutFrames& v)
{
  s(v.labels, v.frames, v.training, v.test, v.origin, v.droppedFrames, v.stabilized);
}

template <class Stream>
void visitFields(Stream& s, DetectedPair& v)
{
  s(v.first, v.second, v.mismatch, v.fromLabels);
}

template <class Stream>
void visitFields(Stream& s, PairDetection& v)
{
  s(v.symmetry, v.pairs, v.midline, v.unpaired, v.planeNormal, v.planePoint, v.tolerance);
}

template <class Stream>
void visitFields(Stream& s, ScoredLayout& v)
{
  s(v.markers, v.k, v.unitFrequency, v.stability, v.blendshapeError, v.reconstructionRmse);
}

template <class Stream>
void visitFields(Stream& s, LayoutSize& v)
{
  s(v.markerCount, v.pfa, v.greedy, v.randomCount, v.randomBlendshapeError, v.randomReconstructionRmse);
}

template <class Stream>
void visitFields(Stream& s, PfaSelection& v)
{
  s(v.k, v.markers, v.unitFrequency, v.stability);
}

template <class Stream>
void visitFields(Stream& s, BlendshapeBasis& v)
{
  s(v.neutral, v.deltas, v.neutralFrame, v.keyFrames);
}

template <class Stream>
void visitFields(Stream& s, LayoutPlan& v)
{
  s(v.method, v.sizes, v.pfaSweep, v.pcaComponents, v.explainedVariance, v.basis, v.motionRms, v.recommendedSize,
    v.recommendationRule, v.cancelled);
}

template <class Stream>
void visitFields(Stream& s, RigLayoutError& v)
{
  s(v.boundMarkers, v.frames, v.mse);
}

template <class Stream>
void visitFields(Stream& s, LayoutSizeRigErrors& v)
{
  s(v.markerCount, v.pfa, v.greedy, v.randomCount, v.randomMse);
}

template <class Stream>
void visitFields(Stream& s, PlanRigErrors& v)
{
  s(v.sizes, v.planned, v.boundMarkers, v.frames, v.seconds, v.cancelled);
}

template <class Stream>
void visitFields(Stream& s, LayoutPlanResult& v)
{
  s(v.frames, v.symmetry, v.detection, v.stabilizeLabels, v.plan, v.pairSource, v.error, v.rig, v.rigError);
}

template <class Stream>
void visitFields(Stream& s, RetargetSource& v)
{
  s(v.shape, v.gain);
}

template <class Stream>
void visitFields(Stream& s, RetargetChannel& v)
{
  s(v.name, v.sources, v.offset, v.min, v.max, v.line);
}

template <class Stream>
void visitFields(Stream& s, RetargetMap& v)
{
  s(v.channels);
}

template <class Stream>
void visitFields(Stream& s, SessionState& v)
{
  s(v.meshPath, v.binding, v.rigPath, v.rigShapeFolder, v.curves, v.solvedWith, v.readCurves, v.selectedShapes,
    v.videos, v.currentVideo, v.layoutPlan, v.layoutSize);
  if (s.version() >= 2)
    s(v.actorPath, v.actor, v.solvedWith.actor, v.retargetMapName, v.retargetMap, v.retargetMapEdited);
}

/// Writes values to a QDataStream. It takes them by non-const reference only to share
/// visitFields with the Reader; it never changes them.
class Writer
{
public:
  explicit Writer(QDataStream& out) : m_out(out) {}

  /// Writes the newest version only.
  [[nodiscard]] static quint32 version() { return kVersion; }

  template <class... T>
  void operator()(T&... values)
  {
    (write(values), ...);
  }

private:
  void write(bool v) { m_out << v; }
  void write(int v) { m_out << static_cast<qint32>(v); }
  void write(long v) { m_out << static_cast<qint64>(v); }
  void write(long long v) { m_out << static_cast<qint64>(v); }
  void write(unsigned long v) { m_out << static_cast<quint64>(v); }
  void write(double v) { m_out << v; }
  // Leaves by non-const reference like the fallback below, which would otherwise be the closer match.
  void write(QString& v) { m_out << v; }
  void write(std::string& v) { m_out << QByteArray::fromStdString(v); }
  void writeCount(std::size_t n) { m_out << static_cast<qint64>(n); }

  template <class Matrix>
  void writeMatrix(const Matrix& m)
  {
    m_out << static_cast<qint64>(m.rows()) << static_cast<qint64>(m.cols());
    for (Eigen::Index i = 0; i < m.size(); ++i)
      m_out << m.data()[i];
  }
  void write(Eigen::MatrixXd& v) { writeMatrix(v); }
  void write(Eigen::VectorXd& v) { writeMatrix(v); }
  void write(Eigen::RowVectorXd& v) { writeMatrix(v); }
  void write(Eigen::Vector3d& v) { writeMatrix(v); }

  void write(BlendshapeSolveMethod& v) { write(static_cast<int>(v)); }
  void write(RetargetScale& v) { write(static_cast<int>(v)); }
  void write(SelectionMethod& v) { write(static_cast<int>(v)); }

  void write(MarkerSymmetry& v)
  {
    write(v.markerCount());
    std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs = v.pairs();
    write(pairs);
  }
  void write(std::vector<bool>& v)
  {
    writeCount(v.size());
    for (const bool b : v)
      m_out << b;
  }
  template <class T>
  void write(std::vector<T>& v)
  {
    writeCount(v.size());
    for (T& item : v)
      write(item);
  }
  template <class T>
  void write(std::optional<T>& v)
  {
    write(v.has_value());
    if (v)
      write(*v);
  }
  template <class A, class B>
  void write(std::pair<A, B>& v)
  {
    write(v.first);
    write(v.second);
  }
  void write(std::shared_ptr<const LayoutPlanResult>& v)
  {
    write(v != nullptr);
    if (v)
      write(const_cast<LayoutPlanResult&>(*v));  // only read: see the class comment
  }
  /// A profile as its own JSON file format (actor_profile_io), which checks it when read back.
  void write(std::shared_ptr<const ActorProfile>& v)
  {
    write(v != nullptr);
    if (v) {
      std::string json = actorProfileJson(*v);
      write(json);
    }
  }
  template <class T>
  void write(T& v)
  {
    visitFields(*this, v);
  }

  QDataStream& m_out;
};

/// Reads what Writer wrote. A count or size the remaining bytes cannot hold marks the stream
/// corrupt (no allocation follows it); the caller checks the stream's status at the end.
class Reader
{
public:
  Reader(QDataStream& in, quint32 version) : m_in(in), m_version(version) {}

  /// The version the bytes were written in.
  [[nodiscard]] quint32 version() const { return m_version; }

  template <class... T>
  void operator()(T&... values)
  {
    (read(values), ...);
  }

  [[nodiscard]] bool ok() const { return m_in.status() == QDataStream::Ok; }
  /// Marks the stream corrupt: every later read yields zeros and the whole decode fails.
  void corrupt() { m_in.setStatus(QDataStream::ReadCorruptData); }

private:
  [[nodiscard]] qint64 remaining() const { return m_in.device()->bytesAvailable(); }

  void read(bool& v) { m_in >> v; }
  void read(int& v)
  {
    qint32 x = 0;
    m_in >> x;
    v = x;
  }
  void read(long& v)
  {
    qint64 x = 0;
    m_in >> x;
    v = static_cast<long>(x);
  }
  void read(long long& v)
  {
    qint64 x = 0;
    m_in >> x;
    v = x;
  }
  void read(unsigned long& v)
  {
    quint64 x = 0;
    m_in >> x;
    v = static_cast<unsigned long>(x);
  }
  void read(double& v) { m_in >> v; }
  void read(QString& v) { m_in >> v; }
  void read(std::string& v)
  {
    QByteArray bytes;
    m_in >> bytes;
    v = bytes.toStdString();
  }
  /// A count of items of at least `itemBytes` each; 0 (and the stream corrupt) when the rest cannot hold them.
  std::size_t readCount(qint64 itemBytes)
  {
    qint64 n = 0;
    m_in >> n;
    if (!ok() || n < 0 || n > remaining() / itemBytes) {
      corrupt();
      return 0;
    }
    return static_cast<std::size_t>(n);
  }

  template <class Matrix>
  void readMatrix(Matrix& m)
  {
    qint64 rows = 0;
    qint64 cols = 0;
    m_in >> rows >> cols;
    const bool fits = ok() && rows >= 0 && cols >= 0 && (rows == 0 || cols <= remaining() / 8 / rows);
    const bool shaped = (Matrix::RowsAtCompileTime == Eigen::Dynamic || rows == Matrix::RowsAtCompileTime) &&
                        (Matrix::ColsAtCompileTime == Eigen::Dynamic || cols == Matrix::ColsAtCompileTime);
    if (!fits || !shaped) {
      corrupt();
      return;
    }
    m.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    for (Eigen::Index i = 0; i < m.size(); ++i)
      m_in >> m.data()[i];
  }
  void read(Eigen::MatrixXd& v) { readMatrix(v); }
  void read(Eigen::VectorXd& v) { readMatrix(v); }
  void read(Eigen::RowVectorXd& v) { readMatrix(v); }
  void read(Eigen::Vector3d& v) { readMatrix(v); }

  template <class Enum>
  void readEnum(Enum& v, Enum last)
  {
    int x = 0;
    read(x);
    if (x < 0 || x > static_cast<int>(last))
      corrupt();
    else
      v = static_cast<Enum>(x);
  }
  void read(BlendshapeSolveMethod& v) { readEnum(v, BlendshapeSolveMethod::Temporal); }
  void read(RetargetScale& v) { readEnum(v, RetargetScale::PerAxis); }
  void read(SelectionMethod& v) { readEnum(v, SelectionMethod::Greedy); }

  void read(MarkerSymmetry& v)
  {
    Eigen::Index markers = 0;
    std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
    read(markers);
    read(pairs);
    if (!ok() || markers < 0 || markers > kMaxMarkers) {
      corrupt();
      return;
    }
    try {
      v = MarkerSymmetry(markers, pairs);
    } catch (const std::exception&) {  // pairs out of range or repeated
      corrupt();
    }
  }
  void read(std::vector<bool>& v)
  {
    v.assign(readCount(1), false);
    for (std::size_t i = 0; i < v.size(); ++i) {
      bool b = false;
      m_in >> b;
      v[i] = b;
    }
  }
  template <class T>
  void read(std::vector<T>& v)
  {
    v.clear();
    v.resize(readCount(1));
    for (T& item : v)
      read(item);
  }
  template <class T>
  void read(std::optional<T>& v)
  {
    bool has = false;
    read(has);
    v.reset();
    if (has && ok())
      read(v.emplace());
  }
  template <class A, class B>
  void read(std::pair<A, B>& v)
  {
    read(v.first);
    read(v.second);
  }
  void read(std::shared_ptr<const LayoutPlanResult>& v)
  {
    bool has = false;
    read(has);
    v.reset();
    if (has && ok()) {
      auto result = std::make_shared<LayoutPlanResult>();
      read(*result);
      v = std::move(result);
    }
  }
  void read(std::shared_ptr<const ActorProfile>& v)
  {
    bool has = false;
    read(has);
    v.reset();
    if (!has || !ok())
      return;
    std::string json;
    read(json);
    try {
      v = std::make_shared<const ActorProfile>(parseActorProfile(json, "the session state's actor profile"));
    } catch (const std::exception&) {  // damaged bytes inside the text
      corrupt();
    }
  }
  template <class T>
  void read(T& v)
  {
    visitFields(*this, v);
  }

  QDataStream& m_in;
  quint32 m_version;
};

} // namespace session_state_format

QByteArray encodeSessionState(const SessionState& state)
{
  using namespace session_state_format;
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  QDataStream out(&buffer);
  out.setVersion(QDataStream::Qt_6_0);
  out << kMagic << kVersion;
  Writer writer(out);
  writer(const_cast<SessionState&>(state));  // only read: see Writer
  return bytes;
}

SessionState decodeSessionState(const QByteArray& bytes, const std::string& source)
{
  using namespace session_state_format;
  QByteArray copy = bytes;
  QBuffer buffer(&copy);
  buffer.open(QIODevice::ReadOnly);
  QDataStream in(&buffer);
  in.setVersion(QDataStream::Qt_6_0);
  quint32 magic = 0;
  quint32 version = 0;
  in >> magic >> version;
  if (in.status() != QDataStream::Ok || magic != kMagic)
    throw FormatError(source, "not a session state of Mocap Studio");
  if (version < kFirstVersion || version > kVersion)
    throw FormatError(source, "a session state of version " + std::to_string(version) +
                                  " (this program reads versions " + std::to_string(kFirstVersion) + " to " +
                                  std::to_string(kVersion) + ")");
  SessionState state;
  Reader reader(in, version);
  reader(state);
  if (!reader.ok())
    throw FormatError(source, static_cast<std::uint64_t>(buffer.pos()), "cut short or damaged session state");
  if (!in.atEnd())
    throw FormatError(source, static_cast<std::uint64_t>(buffer.pos()), "unexpected bytes after the session state");
  return state;
}

} // namespace mocap::ui
