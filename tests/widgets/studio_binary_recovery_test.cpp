// Crash recovery of the real program (issue 31): build/bin/mocap-studio on a copy of the sample with
// the face mesh and its binding, an edit typed into its window (xdotool: the marker selected on the
// command line deleted with Ctrl+Delete), its autosave every second (--autosave-seconds); killed with
// SIGKILL, then started again with --recover (the offer's Yes without the question): the edit and the
// face mesh are back, as the recovered studio's own recovery copy shows; killed again, a third start
// recovers that copy and pictures the window (build/tests/studio_recovered.png, to look at).
#include "sample_files.h"
#include "../core/test_support.h"

#include "document/session_state.h"

#include "mocap/base/file_io.h"
#include "mocap/io/take_io.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTest>

#include <gtest/gtest.h>

#include <functional>

#include <signal.h>
#include <sys/types.h>

namespace mocap {
namespace {

constexpr char kDeletedMarker[] = "Unlabeled1";  // neither bound to the mesh nor a head marker
constexpr int kWaitMs = 20000;

/// A studio of the test's own: its settings and recovery files under `home`, on the test's display.
class StudioRun
{
public:
  explicit StudioRun(const QString& home)
  {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home + QStringLiteral("/config"));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home + QStringLiteral("/data"));
    m_process.setProcessEnvironment(environment);
    m_process.setProcessChannelMode(QProcess::SeparateChannels);
  }
  ~StudioRun()
  {
    if (m_process.state() != QProcess::NotRunning)
      kill();
  }
  StudioRun(const StudioRun&) = delete;
  StudioRun& operator=(const StudioRun&) = delete;

  void start(const QStringList& arguments)
  {
    m_process.start(QString::fromUtf8(checkout::binDir()) + QStringLiteral("/mocap-studio"), arguments);
    ASSERT_TRUE(m_process.waitForStarted(kWaitMs)) << m_process.errorString().toStdString();
  }
  [[nodiscard]] qint64 pid() const { return m_process.processId(); }
  void kill()
  {
    ASSERT_EQ(::kill(static_cast<pid_t>(m_process.processId()), SIGKILL), 0);
    ASSERT_TRUE(m_process.waitForFinished(kWaitMs));
  }
  [[nodiscard]] bool finish()
  {
    return m_process.waitForFinished(kWaitMs) && m_process.exitStatus() == QProcess::NormalExit &&
           m_process.exitCode() == 0;
  }
  /// What it printed so far (stdout, then stderr).
  [[nodiscard]] std::string output()
  {
    m_out += m_process.readAllStandardOutput();
    m_err += m_process.readAllStandardError();
    return (m_out + m_err).toStdString();
  }

private:
  QProcess m_process;
  QByteArray m_out;
  QByteArray m_err;
};

QString recoveryFolder(const QString& home)
{
  return home + QStringLiteral("/data/MocapStudio/Mocap Studio/recovery");  // AppDataLocation/recovery
}

/// Waits until `done` holds (polling every 100 ms); false after kWaitMs.
bool pollUntil(const std::function<bool()>& done)
{
  for (int waited = 0; waited < kWaitMs; waited += 100) {
    if (done())
      return true;
    QTest::qWait(100);
  }
  return done();
}

/// Runs xdotool with `arguments` (10 s at most) and returns what it printed, trimmed.
QString xdotool(const QStringList& arguments)
{
  QProcess process;
  process.start(QStringLiteral("xdotool"), arguments);
  if (!process.waitForFinished(10000))
    process.kill();
  return QString::fromUtf8(process.readAllStandardOutput()).trimmed();
}

/// The recovery copy of the studio `pid` and its session state: the take and state, once written.
struct RecoveryCopy
{
  Take take;
  ui::SessionState state;
};

std::optional<RecoveryCopy> readRecoveryCopy(const QString& home, qint64 pid)
{
  const QString take = recoveryFolder(home) + QStringLiteral("/take-%1.c3d").arg(pid);
  if (!QFileInfo::exists(take) || !QFileInfo::exists(take + QStringLiteral(".session")))
    return std::nullopt;
  const std::string state = (take + QStringLiteral(".session")).toStdString();
  return RecoveryCopy{readTake(take.toStdString()),
                      ui::decodeSessionState(QByteArray::fromStdString(readFileBytes(state)), state)};
}

TEST(StudioBinaryRecovery, AKilledStudioComesBackWithItsEditAndFaceMesh)
{
  if (QStandardPaths::findExecutable(QStringLiteral("xdotool")).isEmpty())
    GTEST_SKIP() << "xdotool not found: the edit is typed into the studio's window with it (apt-get install xdotool)";
  test::TempDir dir;
  const QString home = test::qpath(dir.path());
  const QString take = home + QStringLiteral("/take.c3d");
  ASSERT_TRUE(QFile::copy(test::qpath(test::sampleTake()), take));

  // 1. The studio with the face mesh; the selected marker deleted from the keyboard; autosaved.
  StudioRun first(home);
  ASSERT_NO_FATAL_FAILURE(first.start({take, QStringLiteral("--mesh"), test::sampleMesh(), QStringLiteral("--binding"),
                                       test::sampleBinding(), QStringLiteral("--select"), QLatin1String(kDeletedMarker),
                                       QStringLiteral("--autosave-seconds"), QStringLiteral("1")}));
  QString window;
  ASSERT_TRUE(pollUntil([&] {
    window = xdotool({QStringLiteral("search"), QStringLiteral("--onlyvisible"), QStringLiteral("--pid"),
                      QString::number(first.pid()), QStringLiteral("--name"), QStringLiteral("Mocap Studio")})
                 .section(QLatin1Char('\n'), 0, 0);
    return !window.isEmpty();
  })) << "no studio window:\n" << first.output();
  (void)xdotool({QStringLiteral("windowfocus"), QStringLiteral("--sync"), window});
  (void)xdotool({QStringLiteral("key"), QStringLiteral("--clearmodifiers"), QStringLiteral("ctrl+Delete")});
  std::optional<RecoveryCopy> killed;
  ASSERT_TRUE(pollUntil([&] { return (killed = readRecoveryCopy(home, first.pid())).has_value(); }))
      << "no autosave of the edit:\n" << first.output();
  EXPECT_EQ(killed->take.markerCount(), 37) << "the sample's 38 markers less the deleted one";
  EXPECT_FALSE(killed->take.markerIndex(kDeletedMarker).has_value());
  EXPECT_EQ(killed->state.meshPath, test::sampleMesh());
  EXPECT_FALSE(killed->state.binding.empty());
  ASSERT_NO_FATAL_FAILURE(first.kill());

  // 2. Started again, it recovers the killed studio's take and session and keeps its own copy.
  StudioRun second(home);
  ASSERT_NO_FATAL_FAILURE(second.start({QStringLiteral("--recover"), QStringLiteral("--autosave-seconds"), QStringLiteral("1")}));
  std::optional<RecoveryCopy> recovered;
  ASSERT_TRUE(pollUntil([&] { return (recovered = readRecoveryCopy(home, second.pid())).has_value(); }))
      << "the recovered studio kept no copy:\n" << second.output();
  ASSERT_TRUE(pollUntil([&] { return second.output().find("Recovered unsaved edits of take.c3d") != std::string::npos; }))
      << second.output();
  EXPECT_EQ(second.output().find("not restored"), std::string::npos) << second.output();
  EXPECT_FALSE(QFileInfo::exists(recoveryFolder(home) + QStringLiteral("/take-%1.c3d").arg(first.pid())))
      << "the killed studio's copy is gone once recovered";
  EXPECT_EQ(recovered->take.markerCount(), 37);
  EXPECT_FALSE(recovered->take.markerIndex(kDeletedMarker).has_value()) << "the deleted marker came back";
  EXPECT_EQ(recovered->state.meshPath, killed->state.meshPath) << "the face mesh did not come back";
  EXPECT_EQ(recovered->state.binding, killed->state.binding);
  ASSERT_NO_FATAL_FAILURE(second.kill());

  // 3. Killed again, the next start recovers that and pictures the window, then closes cleanly.
  const QString picture = QDir(QString::fromUtf8(checkout::testBuildDir())).filePath(QStringLiteral("studio_recovered.png"));
  QFile::remove(picture);
  StudioRun third(home);
  ASSERT_NO_FATAL_FAILURE(third.start({QStringLiteral("--recover"), QStringLiteral("--screenshot"), picture}));
  ASSERT_TRUE(third.finish()) << third.output();
  EXPECT_NE(third.output().find("Recovered unsaved edits of take.c3d"), std::string::npos) << third.output();
  EXPECT_FALSE(QImage(picture).isNull());
  EXPECT_TRUE(QDir(recoveryFolder(home)).entryList({QStringLiteral("take-*")}, QDir::Files).isEmpty())
      << "a clean close leaves nothing to recover";
}

} // namespace
} // namespace mocap
