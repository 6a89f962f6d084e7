#include "take_input.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/json_writer.h"
#include "mocap/evaluation/spike_evaluation.h"
#include "mocap/io/take_io.h"

#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

namespace mocap::cli {

namespace {

void writeSpikeEvaluationJson(const std::string& file, const SpikeEvaluationOptions& options,
                              const std::vector<SpikeEvaluation>& results)
{
  JsonWriter json;
  json.beginObject();
  json.key("take").value(file);
  json.key("amplitude").value(options.amplitude);
  json.key("count").value(options.count);
  json.key("seed").value(static_cast<std::int64_t>(options.seed));
  json.key("passes").value(static_cast<std::int64_t>(options.detector.maxPasses));
  json.key("methods").beginArray();
  for (const SpikeEvaluation& result : results) {
    json.beginObject();
    json.key("method").value(result.method);
    json.key("recall").value(result.recall);
    json.key("false_alarm_rate").value(result.falseAlarmRate);
    json.key("injected").value(static_cast<std::int64_t>(result.injected));
    json.key("detected").value(static_cast<std::int64_t>(result.detected));
    json.key("false_alarms").value(static_cast<std::int64_t>(result.falseAlarms));
    json.key("restored_rmse").value(result.restoredRmse);
    json.key("clean_samples").value(static_cast<std::int64_t>(result.cleanSamples));
    json.key("flagged_before").value(static_cast<std::int64_t>(result.flaggedBefore));
    json.endObject();
  }
  json.endArray();
  json.endObject();
  std::cout << json.str() << '\n';
}

void writeSpikeEvaluationText(const std::string& file, const SpikeEvaluationOptions& options,
                              const std::vector<SpikeEvaluation>& results)
{
  std::cout << file << ": " << options.count << " spikes of " << options.amplitude << " mm, seed "
            << options.seed;
  if (!results.empty() && results.front().spikes < options.count)
    std::cout << " (room for " << results.front().spikes << ")";
  std::cout << '\n';
  char line[200];
  std::snprintf(line, sizeof line, "%-8s %9s %9s %8s %9s %11s %12s %11s %12s\n", "method", "injected",
                "detected", "recall", "false", "false rate", "restored mm", "clean", "flagged before");
  std::cout << line;
  for (const SpikeEvaluation& result : results) {
    std::snprintf(line, sizeof line, "%-8s %9lld %9lld %7.2f%% %9lld %10.3f%% %12.3f %11lld %12lld\n",
                  result.method.c_str(), static_cast<long long>(result.injected),
                  static_cast<long long>(result.detected), 100.0 * result.recall,
                  static_cast<long long>(result.falseAlarms), 100.0 * result.falseAlarmRate,
                  result.restoredRmse, static_cast<long long>(result.cleanSamples),
                  static_cast<long long>(result.flaggedBefore));
    std::cout << line;
  }
}

struct EvalSpikesArguments
{
  std::string file;
  SpikeEvaluationOptions options;
  bool json = false;
};

int runEvalSpikes(const EvalSpikesArguments& arguments)
{
  const std::string& file = arguments.file;
  const SpikeEvaluationOptions& options = arguments.options;
  const Take take = readInputTake(file);
  const std::vector<SpikeEvaluation> results = evaluateSpikes(take, options);
  if (arguments.json)
    writeSpikeEvaluationJson(file, options, results);
  else
    writeSpikeEvaluationText(file, options, results);
  return kExitOk;
}

} // namespace

Command addEvalSpikes(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("eval-spikes", "inject spikes, report recall and false alarms per detector");
  const auto a = std::make_shared<EvalSpikesArguments>();
  SpikeEvaluationOptions& options = a->options;
  command->add_option("TAKE", a->file, "the take spikes are injected into")->required();
  wholeNumberIn(command->add_option("--count", options.count, "spikes injected")->type_name("N"), 1, 1000000)
      ->capture_default_str();
  numberIn(command->add_option("--amplitude", options.amplitude, "spike size")->type_name("MM"), 1e-6, 1e6)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--seed", options.seed, "random seed")->type_name("S"), 0,
                std::numeric_limits<long long>::max())
      ->capture_default_str();
  numberIn(command->add_option("--factor", options.detector.factor, "detection factor")->type_name("F"), 1e-6, 1e6)
      ->capture_default_str();
  numberIn(command->add_option("--threshold", options.detector.threshold, "detection threshold")->type_name("T"),
           1e-6, 1e6)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--passes", options.detector.maxPasses, "detection passes")->type_name("N"), 1,
                1000)
      ->capture_default_str();
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runEvalSpikes(*a); }};
}

} // namespace mocap::cli
