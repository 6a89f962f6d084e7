// `mocap stream`: a take's solved weights (or weight curves read from a file), and optionally its
// markers, sent live over UDP as Live Link Face or VMC datagrams while it plays in real time.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "frame_range.h"
#include "stop_signal.h"
#include "take_input.h"
#include "take_solve.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/base/number_text.h"
#include "mocap/base/stopwatch.h"
#include "mocap/io/live_link_face_csv.h"
#include "mocap/io/live_link_face_map.h"
#include "mocap/io/shipped_retarget_maps.h"
#include "mocap/io/weights_csv_reader.h"
#include "mocap/stream/live_streamer.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

namespace mocap::cli {

namespace {

struct StreamArguments
{
  SolveInput input;  // meshPath is --rig
  std::optional<std::string> weights, map, to, frames, rate;
  std::string protocol = "livelink";
  std::string subject = StreamSettings{}.subject;
  bool loop = false, markers = false, json = false;
};

std::optional<RetargetMap> mapArgument(const StreamArguments& arguments)
{
  return arguments.map ? std::optional<RetargetMap>(readRetargetMapByNameOrPath(*arguments.map)) : std::nullopt;
}

bool isLiveLinkRecording(const std::string& path)
{
  return readFileBytes(path).rfind("Timecode,", 0) == 0;
}

/// --weights: a Live Link Face recording as it is, or our weight curves through --map (by
/// default the shipped ICT → ARKit names) onto the 52 curves.
StreamFrames framesFromWeightsFile(const StreamArguments& arguments)
{
  const std::string& path = *arguments.weights;
  if (isLiveLinkRecording(path)) {
    if (arguments.map)
      throw UsageError("a Live Link Face recording already holds the 52 curves: --map applies to weight curves");
    const LiveLinkFaceRecording recording = readLiveLinkFaceCsv(path);
    const double rate = liveLinkFaceRate(recording);
    if (!(rate > 0.0))
      throw UsageError(path + ": a recording needs two rows or more with increasing timecodes");
    return streamFramesFromRecording(recording, rate, 0);
  }
  const WeightCurves curves = readWeightsCsv(path);
  if (!(curves.frameRate > 0.0))
    throw UsageError(path + ": weight curves need two rows or more to have a rate");
  return streamFramesFromRecording(
      liveLinkFaceRecordingOfRig(curves.names, curves.weights, mapArgument(arguments), curves.frameRate,
                                 Eigen::MatrixXd()),
      curves.frameRate, curves.firstFrame);
}

/// What the arguments ask to stream: weights from --weights, or solved from the take on --rig,
/// and the take's markers with --markers.
StreamFrames streamFrames(const StreamArguments& arguments)
{
  const bool solve = !arguments.input.meshPath.empty();
  if (solve && arguments.weights)
    throw UsageError("give --rig and --binding to solve the take, or --weights to stream curves already made, not both");
  if (solve && arguments.input.bindingPath.empty())
    throw UsageError("solving the take on --rig needs its --binding (mocap bind)");
  if (solve && arguments.input.takePath.empty())
    throw UsageError("solving needs the TAKE");
  StreamFrames frames;
  std::optional<Take> take;
  if (arguments.weights) {
    frames = framesFromWeightsFile(arguments);
  } else if (solve) {
    const std::optional<RetargetMap> map = mapArgument(arguments);
    SolvedTake solved = solveInputTake(arguments.input, [&](const BlendshapeRig& rig) {
      (void)liveLinkFaceMap(rig.shapeNames(), map);  // a wrong map fails before the solve
    });
    frames = streamFramesFromRecording(liveLinkFaceRecordingOfRig(solved.rig->shapeNames(), solved.result.weights,
                                                                  map, solved.take.frameRate(), solved.headRotation()),
                                       solved.take.frameRate(), solved.take.firstFrame());
    if (const std::string note = solved.unstabilizedHeadNote(); !note.empty())
      std::cerr << "note: " << note << '\n';  // stdout may be the --json statistics
    take = std::move(solved.take);
  }
  if (arguments.markers) {
    if (arguments.input.takePath.empty())
      throw UsageError("--markers streams the TAKE's markers: give the take");
    if (!take)
      take = readInputTake(arguments.input.takePath);
    addStreamMarkers(frames, *take);
  }
  if (frames.frameCount() == 0)
    throw UsageError("nothing to stream: give --rig and --binding to solve the take, --weights W.csv, or --markers "
                     "(VMC)");
  return frames;
}

StreamSettings streamSettings(const StreamArguments& arguments)
{
  StreamSettings settings;
  settings.protocol = parseStreamProtocol(arguments.protocol).value();
  settings.destination =
      parseStreamDestination(arguments.to.value_or("127.0.0.1"), defaultStreamPort(settings.protocol));
  settings.subject = arguments.subject;
  settings.sendMarkers = arguments.markers;
  if (arguments.rate) {
    double rate = 0.0;
    if (!parseNumber(*arguments.rate, rate) || !(rate > 0.0) || rate > kMaxStreamRate)
      throw UsageError("--rate must be above 0 and at most 1000 Hz, not '" + *arguments.rate + "'");
    settings.rate = rate;
  }
  return settings;
}

struct Lateness
{
  double median = 0.0, p95 = 0.0, max = 0.0, last = 0.0;  // milliseconds
};

Lateness summarizeLateness(std::vector<float> seconds)
{
  Lateness l;
  if (seconds.empty())
    return l;
  l.last = 1000.0 * static_cast<double>(seconds.back());
  std::sort(seconds.begin(), seconds.end());
  const auto at = [&](double q) {
    const std::size_t index = std::min(seconds.size() - 1, static_cast<std::size_t>(q * static_cast<double>(seconds.size())));
    return 1000.0 * static_cast<double>(seconds[index]);
  };
  l.median = at(0.5);
  l.p95 = at(0.95);
  l.max = 1000.0 * static_cast<double>(seconds.back());
  return l;
}

void printJson(const StreamArguments& arguments, const LiveStreamer& streamer, const StreamFrames& frames,
               std::pair<Eigen::Index, Eigen::Index> range, double seconds, bool interrupted)
{
  const StreamStats stats = streamer.stats();
  const Lateness late = summarizeLateness(stats.lateness);
  JsonWriter json;
  json.beginObject();
  json.key("protocol").value(arguments.protocol);
  json.key("to").value(describeDestination(streamer.settings().destination));
  json.key("subject").value(streamer.settings().subject);
  json.key("rate").value(streamer.rate());
  json.key("frame_rate").value(frames.frameRate);
  json.key("first_frame").value(static_cast<std::int64_t>(frames.firstFrame + range.first));
  json.key("last_frame").value(static_cast<std::int64_t>(frames.firstFrame + range.second - 1));
  json.key("weights").value(frames.hasCurves() && streamer.settings().sendWeights);
  json.key("markers").value(static_cast<std::int64_t>(streamer.settings().sendMarkers ? frames.markerNames.size() : 0));
  json.key("loop").value(arguments.loop);
  json.key("datagrams_sent").value(stats.sent);
  json.key("datagrams_refused").value(stats.failed);
  if (stats.lastError.empty())
    json.key("last_error").null();
  else
    json.key("last_error").value(stats.lastError);
  json.key("seconds").value(seconds);
  json.key("lateness_ms").beginObject();
  json.key("median").value(late.median);
  json.key("p95").value(late.p95);
  json.key("max").value(late.max);
  json.key("last").value(late.last);
  json.endObject();
  json.key("interrupted").value(interrupted);
  json.endObject();
  std::cout << json.str() << '\n';
}

int runStream(const StreamArguments& arguments)
{
  const StreamSettings settings = streamSettings(arguments);  // usage errors before any work
  (void)mapArgument(arguments);  // a wrong map fails before the take is read or solved
  const auto frames = std::make_shared<const StreamFrames>(streamFrames(arguments));
  const std::pair<Eigen::Index, Eigen::Index> range =
      parseFrameRange(arguments.frames, frames->firstFrame, frames->frameCount());
  LiveStreamer streamer(settings, frames);
  const std::atomic<bool>& stop = installStopSignals();
  if (!arguments.json)
    std::cout << "streaming frames " << frames->firstFrame + range.first << "…" << frames->firstFrame + range.second - 1
              << (arguments.loop ? " in a loop" : "") << " to " << describeDestination(settings.destination)
              << " over " << arguments.protocol << " at " << numberText(streamer.rate()) << " Hz"
              << (settings.protocol == StreamProtocol::LiveLink ? " as subject '" + settings.subject + "'" : "")
              << "; Ctrl+C stops" << std::endl;
  const Stopwatch clock;
  streamer.playRange(range.first, range.second - 1, arguments.loop);
  bool warned = false;
  while (streamer.running() && !stop.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (!warned && !arguments.json) {
      const StreamStats stats = streamer.stats();
      if (stats.failed > 0) {
        std::cerr << "warning: " << stats.lastError << "; still sending" << std::endl;
        warned = true;
      }
    }
  }
  const bool interrupted = stop.load() && streamer.running();
  streamer.stop();
  const double seconds = clock.seconds();
  const StreamStats stats = streamer.stats();
  if (arguments.json) {
    printJson(arguments, streamer, *frames, range, seconds, interrupted);
  } else {
    const Lateness late = summarizeLateness(stats.lateness);
    std::cout << "sent " << stats.sent << " datagrams in " << fixedNumber(seconds, 2) << " s";
    if (stats.failed > 0)
      std::cout << ", " << stats.failed << " refused (" << stats.lastError << ")";
    std::cout << "; late by " << fixedNumber(late.median, 3) << " ms median, " << fixedNumber(late.p95, 3)
              << " ms p95, " << fixedNumber(late.max, 3) << " ms max, last " << fixedNumber(late.last, 3) << " ms"
              << (interrupted ? " (stopped)" : "") << '\n';
  }
  if (stats.sent == 0 && stats.failed > 0) {
    std::cerr << "error: nothing took the stream: " << stats.lastError << '\n';
    return kExitBadInput;
  }
  return interrupted && !arguments.loop ? kExitInterrupted : kExitOk;
}

} // namespace

Command addStream(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "stream", "stream the take's solved weights (Live Link Face, VMC) and markers (VMC) over UDP in real time");
  const auto a = std::make_shared<StreamArguments>();
  SolveInput& input = a->input;
  command->add_option("TAKE", input.takePath, "the take to solve and stream (its markers with --markers)");
  command->add_option("--rig", input.meshPath, "the rig to solve to: a glTF rig, or a neutral (.obj, .ply) with --shapes")
      ->type_name("RIG.glb|NEUTRAL.obj");
  command->add_option("--shapes", input.shapesPath, "folder with one OBJ per shape, named after it")->type_name("DIR");
  command->add_option("--binding", input.bindingPath, "the binding mocap bind wrote")->type_name("BIND.json");
  command->add_option("--actor", input.actor, "an actor profile (mocap actor) for the solve")->type_name("ACTOR.json");
  command->add_option("--stabilize", input.stabilize,
                      "head-mounted markers: their motion is removed before the solve and sent as the head's rotation")
      ->type_name("LABELS");
  oneOf(command->add_option("--method", input.method, "solve"), blendshapeSolveMethodNames())->capture_default_str();
  command->add_option("--weights", a->weights,
                      "stream curves already made instead of solving: weight curves (mocap solve's CSV) or a Live "
                      "Link Face recording as the app writes it")
      ->type_name("W.csv");
  command->add_option("--map", a->map,
                      "the rig's shapes onto ARKit's 52 curves: a shipped map or a map file (default: ict_to_arkit "
                      "for ICT FaceKit names, identity for ARKit names)")
      ->type_name("NAME|MAP.json");
  oneOf(command->add_option("--protocol", a->protocol, "what the receiver speaks"), streamProtocolNames())
      ->capture_default_str();
  command->add_option("--to", a->to,
                      "the receiver (default 127.0.0.1 on the protocol's port: 11111 Live Link, 39539 VMC)")
      ->type_name("HOST[:PORT]");
  command->add_option("--rate", a->rate, "datagrams per second (default: the take's rate); the take still plays at its speed")
      ->type_name("HZ");
  command->add_flag("--loop", a->loop, "play the frames over and over until Ctrl+C");
  command->add_option("--frames", a->frames, "stream only these frames (numbers as the take numbers them)")
      ->type_name("FIRST:LAST");
  command->add_option("--subject", a->subject, "Live Link: the subject name the engine lists")->capture_default_str();
  command->add_flag("--markers", a->markers, "VMC: send each marker as a tracker (/VMC/Ext/Tra/Pos, metres)");
  command->add_flag("--json", a->json, "print JSON: datagrams sent and refused, lateness against the schedule");
  return {command, [a] { return runStream(*a); }};
}

} // namespace mocap::cli
