// `mocap eval-track TAKE [--seed S] [--fragment-length N] [--cut-gap N] [--swaps N] [--keep-fragments]
// [--json]`: the
// issue-8 protocol (core/include/mocap/evaluation/tracking_evaluation.h): label recovery of an unlabelled,
// fragmented copy and swaps found / false alarms on a copy with injected swaps.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/json_writer.h"
#include "mocap/io/take_io.h"
#include "mocap/evaluation/tracking_evaluation.h"

#include <iostream>
#include <memory>

namespace mocap::cli {

namespace {

std::string evaluationJson(const std::string& file, const TrackingEvaluation& e)
{
  JsonWriter json;
  json.beginObject();
  json.key("take").value(file);
  json.key("seed").value(static_cast<std::int64_t>(e.seed));
  json.key("markers").value(static_cast<std::int64_t>(e.markers));
  json.key("frames").value(static_cast<std::int64_t>(e.frames));
  json.key("fragments").value(static_cast<std::int64_t>(e.fragments));
  json.key("tracked_fragments").value(static_cast<std::int64_t>(e.track.fragments));
  json.key("unlabelled_fragments").value(static_cast<std::int64_t>(e.track.unlabelledFragments));
  json.key("samples").value(static_cast<std::int64_t>(e.samples));
  json.key("recovered").value(static_cast<std::int64_t>(e.recovered));
  json.key("label_recovery").value(e.labelRecovery);
  json.key("clean_samples").value(static_cast<std::int64_t>(e.cleanSamples));
  json.key("clean_recovered").value(static_cast<std::int64_t>(e.cleanRecovered));
  json.key("clean_label_recovery").value(e.cleanLabelRecovery);
  json.key("swaps_injected").value(e.swapsInjected);
  json.key("swaps_found").value(e.swapsFound);
  json.key("false_alarms").value(e.falseAlarms);
  json.key("swaps_in_original").value(e.swapsInOriginal);
  json.key("swapped_agreement").value(e.swappedAgreement);
  json.key("repaired_agreement").value(e.repairedAgreement);
  json.endObject();
  return json.str() + "\n";
}

struct EvalTrackArguments
{
  std::string file;
  TrackingEvaluationOptions options;
  bool keepFragments = false;
  bool json = false;
};

int runEvalTrack(const EvalTrackArguments& arguments)
{
  const std::string& file = arguments.file;
  TrackingEvaluationOptions options = arguments.options;
  options.track.retrack = !arguments.keepFragments;
  std::vector<std::string> warnings;
  const Take take = readTake(file, &warnings);
  const TrackingEvaluation e = evaluateTracking(take, options);
  if (arguments.json) {
    std::cout << evaluationJson(file, e);
    return kExitOk;
  }
  std::cout << file << ": " << e.markers << " markers, " << e.frames << " frames, seed " << e.seed << '\n'
            << "  labelling: " << e.fragments << " fragments (" << e.track.fragments << " after re-tracking), "
            << fixedNumber(100.0 * e.labelRecovery, 3) << " % of " << e.samples
            << " samples back under their true label\n"
            << "             " << fixedNumber(100.0 * e.cleanLabelRecovery, 3) << " % of the " << e.cleanSamples
            << " samples in runs of the take without a jump (its own tracking errors left out)\n"
            << "  swaps: " << e.swapsFound << " of " << e.swapsInjected << " found, " << e.falseAlarms
            << " false alarms (" << e.swapsInOriginal << " in the untouched take); agreement "
            << fixedNumber(100.0 * e.swappedAgreement, 3) << " % -> " << fixedNumber(100.0 * e.repairedAgreement, 3)
            << " %\n";
  return kExitOk;
}

} // namespace

Command addEvalTrack(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "eval-track", "label recovery of a fragmented unlabelled copy; injected swaps found");
  const auto a = std::make_shared<EvalTrackArguments>();
  TrackingEvaluationOptions& options = a->options;
  command->add_option("TAKE", a->file, "a labelled take")->required();
  wholeNumberIn(command->add_option("--seed", options.seed, "random seed")->type_name("S"), 0, 1LL << 53)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--fragment-length", options.meanFragmentLength, "mean fragment length, in frames")
                    ->type_name("N"),
                1, 1000000)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--cut-gap", options.maxCutGap, "longest gap cut between fragments, in frames")
                    ->type_name("N"),
                0, 1000)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--swaps", options.swaps, "label swaps injected")->type_name("N"), 0, 1000)
      ->capture_default_str();
  command->add_flag("--keep-fragments", a->keepFragments, "label the fragments as cut, without re-tracking");
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runEvalTrack(*a); }};
}

} // namespace mocap::cli
