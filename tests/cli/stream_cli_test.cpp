// `mocap stream`: what a user can get wrong gets a clear message and the right exit code, never a
// crash or a hang; and a short stream reaches a receiver on loopback with the summary it prints.
#include "shell_run.h"

#include "../core/test_support.h"
#include "checkout_paths.h"
#include "loopback_receiver.h"

#include "mocap/base/json_reader.h"
#include "mocap/io/weights_csv_writer.h"
#include "mocap/stream/live_link_face_packet.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

std::string sampleTake()
{
  return test::shellQuote(std::filesystem::path(checkout::sampleDir()) / "Facial-Sing.c3d");
}

test::ShellResult stream(const std::string& arguments, const test::TempDir& dir)
{
  return test::runShell(test::shellQuote(std::string(checkout::cliProgram())) + " stream " + arguments, dir.path());
}

void expectFailure(const std::string& arguments, int exitCode, const std::string& message)
{
  const test::TempDir dir;
  const test::ShellResult run = stream(arguments, dir);
  EXPECT_EQ(run.exitCode, exitCode) << arguments << "\n" << run.out << run.err;
  EXPECT_NE(run.err.find(message), std::string::npos) << arguments << ": " << run.err;
}

TEST(StreamCli, BadRequestsAreClearErrorsBeforeAnythingIsSent)
{
  expectFailure(sampleTake() + " --protocol vmc --markers --rate 0", 2, "--rate must be above 0 and at most 1000 Hz");
  expectFailure(sampleTake() + " --protocol vmc --markers --rate 10000", 2, "at most 1000 Hz");
  expectFailure(sampleTake() + " --protocol vmc --markers --to no-such-host.invalid:9000", 1,
                "cannot resolve host 'no-such-host.invalid'");
  expectFailure(sampleTake() + " --protocol vmc --markers --to 127.0.0.1:70000", 2, "1…65535");
  expectFailure(sampleTake() + " --protocol livelink", 2, "nothing to stream");
  expectFailure(sampleTake() + " --protocol livelink --markers", 2, "Live Link Face carries no markers");
  expectFailure(sampleTake() + " --rig " + sampleTake(), 2, "needs its --binding");
  expectFailure("--protocol vmc --markers", 2, "give the take");
}

TEST(StreamCli, AClosedPortIsWarnedAndAStreamNobodyTookIsAnError)
{
  int closedPort = 0;
  {
    const test::LoopbackReceiver gone;
    closedPort = gone.port();
  }
  const test::TempDir dir;
  const test::ShellResult run = stream(sampleTake() + " --protocol vmc --markers --frames 1:30 --rate 200 --to 127.0.0.1:" +
                                           std::to_string(closedPort),
                                       dir);
  EXPECT_NE(run.err.find("nothing listens on 127.0.0.1:" + std::to_string(closedPort)), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("refused"), std::string::npos) << run.out;
}

TEST(StreamCli, WeightCurvesFromAFileReachALiveLinkReceiverFrameByFrame)
{
  const test::TempDir dir;
  Eigen::MatrixXd weights(20, 2);
  for (Eigen::Index f = 0; f < 20; ++f)
    weights.row(f) << 0.05 * static_cast<double>(f), 1.0 - 0.05 * static_cast<double>(f);
  writeWeightsCsv(dir.file("w.csv"), {"jawOpen", "eyeBlink_L"}, weights, 7, 100.0);
  test::LoopbackReceiver receiver;
  const test::ShellResult run = stream("--weights " + test::shellQuote(dir.file("w.csv")) +
                                           " --protocol livelink --subject Rig --json --to 127.0.0.1:" +
                                           std::to_string(receiver.port()),
                                       dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::vector<test::LoopbackReceiver::Datagram> got = receiver.receive(100);
  ASSERT_EQ(got.size(), 20U);
  const auto& names = liveLinkFacePacketNames();
  const auto column = [&](std::string_view name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (std::size_t i = 0; i < got.size(); ++i) {
    const LiveLinkFaceFrame frame = decodeLiveLinkFacePacket(got[i].bytes.data(), got[i].bytes.size());
    EXPECT_EQ(frame.frame, 7 + static_cast<std::int32_t>(i));
    EXPECT_EQ(frame.subject, "Rig");
    EXPECT_NEAR(frame.values[column("JawOpen")], weights(static_cast<Eigen::Index>(i), 0), 1e-6);
    EXPECT_NEAR(frame.values[column("EyeBlinkLeft")], weights(static_cast<Eigen::Index>(i), 1), 1e-6);
  }
  const JsonValue json = parseJson(run.out, "stream --json");
  EXPECT_EQ(json.find("datagrams_sent", "stream")->number("sent"), 20.0);
  EXPECT_EQ(json.find("datagrams_refused", "stream")->number("refused"), 0.0);
  EXPECT_EQ(json.find("first_frame", "stream")->number("first"), 7.0);
  EXPECT_EQ(json.find("last_frame", "stream")->number("last"), 26.0);
}

TEST(StreamCli, CtrlCEndsALoopCleanlyWithItsSummary)
{
  const test::TempDir dir;
  test::LoopbackReceiver receiver;
  const test::ShellResult run = test::runShell(
      "timeout --preserve-status -s INT 1 " + test::shellQuote(std::string(checkout::cliProgram())) + " stream " + sampleTake() +
          " --protocol vmc --markers --loop --frames 1:50 --json --to 127.0.0.1:" + std::to_string(receiver.port()),
      dir.path());
  ASSERT_EQ(run.exitCode, 0) << "a loop ends with Ctrl+C as asked\n" << run.err;
  const JsonValue json = parseJson(run.out, "stream --json");
  EXPECT_TRUE(json.find("interrupted", "stream")->boolean("interrupted"));
  EXPECT_GT(json.find("datagrams_sent", "stream")->number("sent"), 50.0) << "the 50 frames looped at 100 Hz for 1 s";
  EXPECT_GE(receiver.receive(1000, std::chrono::milliseconds(100)).size(), 50U);
}

} // namespace
} // namespace mocap
