// The studio's live stream (issue 34) without a window: the session's LiveStream driven through
// the Live Stream dock streams the current frame of the take to a receiver on loopback, follows
// scrubbing and edits, and shows a clear error (nothing to send, an unknown host, a closed port)
// while the take stays usable.
#include "../core/test_support.h"
#include "loopback_receiver.h"

#include "commands/apply_patches_command.h"
#include "document/live_stream.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/live_stream_panel.h"

#include "mocap/io/take_io.h"
#include "mocap/model/sample_patch.h"
#include "mocap/stream/osc_packet.h"

#include <QSignalSpy>
#include <QUndoStack>
#include <QTest>

#include <gtest/gtest.h>

namespace mocap {
namespace {

/// A take of two markers over 10 frames at 100 Hz: marker "nose" at x = frame index (mm).
void openMovingTake(ui::StudioSession& session, const std::filesystem::path& path)
{
  Take take({"nose", "chin"}, 10, 100.0);
  take.setUnits(LengthUnit::Millimetre);
  for (Eigen::Index f = 0; f < 10; ++f) {
    take.setPosition(f, 0, Eigen::Vector3d(static_cast<double>(f), 0.0, 0.0));
    take.setPosition(f, 1, Eigen::Vector3d(0.0, -50.0, 0.0));
    take.valid()(f, 0) = true;
    take.valid()(f, 1) = true;
  }
  writeTake(take, path.string());
  const QString file = QString::fromStdString(path.string());
  session.document().open(ui::TakeDocument::read(file), file);
}

/// The nose's x in metres of each VMC datagram.
std::vector<float> noseX(const std::vector<test::LoopbackReceiver::Datagram>& datagrams)
{
  std::vector<float> xs;
  for (const auto& datagram : datagrams)
    for (const OscMessage& message : decodeOscPacket(datagram.bytes.data(), datagram.bytes.size()))
      if (message.address == "/VMC/Ext/Tra/Pos" && std::get<std::string>(message.arguments[0]) == "nose")
        xs.push_back(std::get<float>(message.arguments[1]));
  return xs;
}

bool waitForStart(ui::LiveStream& stream)
{
  QSignalSpy started(&stream, &ui::LiveStream::started);
  QSignalSpy failed(&stream, &ui::LiveStream::failed);
  return started.wait(5000) || !failed.isEmpty();
}

TEST(LiveStreamDock, StreamsTheCurrentFrameAndFollowsScrubbingOverVmc)
{
  test::TempDir dir;
  ui::StudioSession session;
  openMovingTake(session, dir.file("take.c3d"));
  test::LoopbackReceiver receiver;
  ui::LiveStreamPanel panel(session);
  panel.setProtocol(QStringLiteral("vmc"));
  panel.setDestination(QStringLiteral("127.0.0.1"), receiver.port());
  panel.setSendMarkers(true);
  session.document().setCurrentFrame(3);
  panel.toggle();
  ASSERT_TRUE(waitForStart(session.liveStream())) << panel.statusText().toStdString();
  ASSERT_TRUE(session.liveStream().running()) << panel.statusText().toStdString();
  QTest::qWait(100);
  std::vector<float> xs = noseX(receiver.receive(5));
  ASSERT_FALSE(xs.empty());
  EXPECT_FLOAT_EQ(xs.back(), 0.003F) << "frame 3's nose, 3 mm, in metres";

  session.document().setCurrentFrame(8);  // scrubbing
  QTest::qWait(100);
  receiver.drain();
  xs = noseX(receiver.receive(5));
  ASSERT_FALSE(xs.empty());
  EXPECT_FLOAT_EQ(xs.back(), 0.008F);
  QTest::qWait(600);  // the dock's counts refresh twice a second
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("sent"))) << panel.statusText().toStdString();

  // An edit reaches the stream: the nose deleted at frame 8 is no longer sent there, and undo
  // brings it back.
  ui::TakeDocument& document = session.document();
  document.undoStack()->push(
      new ui::ApplyPatchesCommand(document, {deleteSamples(document.take(), 0, 7, 9)}, QStringLiteral("delete")));
  QTest::qWait(400);  // the stream rebuilds its frames a moment after an edit
  receiver.drain();
  EXPECT_TRUE(noseX(receiver.receive(5)).empty()) << "a deleted sample is not sent";
  document.undoStack()->undo();
  QTest::qWait(400);
  receiver.drain();
  xs = noseX(receiver.receive(5));
  ASSERT_FALSE(xs.empty());
  EXPECT_FLOAT_EQ(xs.back(), 0.008F);

  panel.toggle();  // Stop
  EXPECT_FALSE(session.liveStream().running());
  receiver.drain();
  EXPECT_TRUE(receiver.receive(1, std::chrono::milliseconds(100)).empty()) << "nothing after Stop";
}

TEST(LiveStreamDock, SaysWhatIsWrongAndNeverStopsTheTake)
{
  test::TempDir dir;
  ui::StudioSession session;
  openMovingTake(session, dir.file("take.c3d"));
  ui::LiveStreamPanel panel(session);
  QSignalSpy failed(&session.liveStream(), &ui::LiveStream::failed);

  // Live Link Face without a solve: nothing it could send.
  panel.setProtocol(QStringLiteral("livelink"));
  panel.setDestination(QStringLiteral("127.0.0.1"), 11111);
  panel.toggle();
  ASSERT_EQ(failed.count(), 1);
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("solve the take"))) << panel.statusText().toStdString();
  EXPECT_FALSE(session.liveStream().running());

  // A host that does not resolve: found on the worker, shown in the dock.
  panel.setProtocol(QStringLiteral("vmc"));
  panel.setSendMarkers(true);
  panel.setDestination(QStringLiteral("no-such-host.invalid"), 39539);
  panel.toggle();
  ASSERT_TRUE(failed.count() == 2 || failed.wait(10000));
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("cannot resolve host"))) << panel.statusText().toStdString();

  // A closed port: the refusals are counted and shown while the stream goes on.
  int closedPort = 0;
  {
    const test::LoopbackReceiver gone;
    closedPort = gone.port();
  }
  panel.setDestination(QStringLiteral("127.0.0.1"), closedPort);
  panel.toggle();
  ASSERT_TRUE(waitForStart(session.liveStream()));
  QTest::qWait(700);
  EXPECT_TRUE(session.liveStream().running());
  EXPECT_TRUE(panel.statusText().contains(QStringLiteral("nothing listens"))) << panel.statusText().toStdString();
  session.document().setCurrentFrame(5);  // the take still moves
  EXPECT_EQ(session.document().currentFrame(), 5);
  panel.toggle();
}

} // namespace
} // namespace mocap
