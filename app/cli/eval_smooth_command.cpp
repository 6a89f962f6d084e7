#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/base/json_writer.h"
#include "mocap/evaluation/smoothing_evaluation.h"
#include "mocap/io/take_io.h"

#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

namespace mocap::cli {

namespace {

void writeSmoothingEvaluationJson(const std::string& file, const SmoothingEvaluation& evaluation)
{
  JsonWriter json;
  json.beginObject();
  json.key("take").value(file);
  json.key("noise").value(evaluation.noiseMm);
  json.key("seed").value(static_cast<std::int64_t>(evaluation.seed));
  json.key("units").value("rmse: mm, acceleration_rmse: mm/s^2");
  json.key("samples").value(static_cast<std::int64_t>(evaluation.samples));
  json.key("acceleration_samples").value(static_cast<std::int64_t>(evaluation.accelerationSamples));
  json.key("noisy_rmse").value(evaluation.noisyRmse);
  json.key("noisy_acceleration_rmse").value(evaluation.noisyAccelerationRmse);
  json.key("methods").beginArray();
  for (const SmoothingScore& score : evaluation.scores) {
    json.beginObject();
    json.key("method").value(smoothMethodName(score.options.method));
    json.key("parameters").value(score.parameters);
    json.key("default").value(score.isDefault);
    json.key("rmse").value(score.rmse);
    json.key("acceleration_rmse").value(score.accelerationRmse);
    json.key("seconds").value(score.seconds);
    json.endObject();
  }
  json.endArray();
  json.endObject();
  std::cout << json.str() << '\n';
}

void writeSmoothingEvaluationText(const std::string& file, const SmoothingEvaluation& evaluation)
{
  char line[200];
  std::cout << "take: " << file << "  noise: " << evaluation.noiseMm
            << " mm per axis  seed: " << evaluation.seed << '\n';
  std::snprintf(line, sizeof line, "%-12s %-28s %10s %14s %9s\n", "method", "parameters", "rmse mm",
                "accel mm/s^2", "seconds");
  std::cout << line;
  std::snprintf(line, sizeof line, "%-12s %-28s %10.4f %14.1f\n", "(noisy)", "", evaluation.noisyRmse,
                evaluation.noisyAccelerationRmse);
  std::cout << line;
  for (const SmoothingScore& score : evaluation.scores) {
    const std::string name =
        std::string(smoothMethodName(score.options.method)) + (score.isDefault ? "*" : "");
    std::snprintf(line, sizeof line, "%-12s %-28s %10.4f %14.1f %9.3f\n", name.c_str(),
                  score.parameters.c_str(), score.rmse, score.accelerationRmse, score.seconds);
    std::cout << line;
  }
  std::cout << "* default (SmoothOptions{})\n";
}

struct EvalSmoothArguments
{
  std::string file;
  SmoothingEvaluationOptions options;
  bool json = false;
};

int runEvalSmooth(const EvalSmoothArguments& arguments)
{
  const std::string& file = arguments.file;
  const Take take = readTake(file);
  const SmoothingEvaluation evaluation = evaluateSmoothing(take, arguments.options);
  if (arguments.json)
    writeSmoothingEvaluationJson(file, evaluation);
  else
    writeSmoothingEvaluationText(file, evaluation);
  return kExitOk;
}

} // namespace

Command addEvalSmooth(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("eval-smooth", "add noise, report position and acceleration RMSE per smoother");
  const auto a = std::make_shared<EvalSmoothArguments>();
  command->add_option("TAKE", a->file, "the clean take noise is added to")->required();
  numberIn(command->add_option("--noise", a->options.noiseMm, "noise per axis")->type_name("MM"), 0.0, 1e4)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--seed", a->options.seed, "random seed")->type_name("S"), 0,
                std::numeric_limits<long long>::max())
      ->capture_default_str();
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runEvalSmooth(*a); }};
}

} // namespace mocap::cli
