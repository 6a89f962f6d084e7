// `mocap eval-fill TAKE [--lengths 10,30,60,120,240] [--copies N] [--seed S] [--methods a,b,...]
// [--neighbours N] [--gaps-per-copy N] [--stabilize LABEL,LABEL,LABEL...] [--keep-jumps] [--json]`:
// every gap-filling method against hidden truth, Gløersen & Federolf's protocol
// (core/include/mocap/evaluation/fill_evaluation.h), as a text table or JSON. --stabilize removes the head
// motion given by head-mounted markers first (head_stabilization.h); --keep-jumps also hides
// (and scores against) stretches where the take jumps, such as label swaps.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include "mocap/evaluation/fill_evaluation.h"
#include "mocap/cleaning/head_stabilization.h"
#include "mocap/base/json_writer.h"
#include "mocap/io/take_io.h"
#include "mocap/base/text.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

// A whole number in [min, max] given to `option`; UsageError otherwise.
std::uint64_t parseNumber(const std::string& option, std::string_view text, std::uint64_t min,
                          std::uint64_t max)
{
  const std::string digits(trim(text));
  const bool wellFormed = !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
  errno = 0;
  const unsigned long long value = wellFormed ? std::strtoull(digits.c_str(), nullptr, 10) : 0;
  if (!wellFormed || errno == ERANGE || value < min || value > max)
    throw UsageError(option + " expects a whole number from " + std::to_string(min) + " to " +
                     std::to_string(max) + ", got '" + std::string(text) + "'");
  return value;
}

std::vector<Eigen::Index> parseLengths(const std::string& text)
{
  std::vector<Eigen::Index> lengths;
  for (const std::string_view field : split(text, ','))
    lengths.push_back(
        static_cast<Eigen::Index>(parseNumber("--lengths (gap lengths in frames)", field, 1, 1000000)));
  return lengths;
}

std::vector<FillMethod> parseMethods(const std::string& text)
{
  std::vector<FillMethod> methods;
  for (const std::string_view field : split(text, ',')) {
    const auto method = parseFillMethod(trim(field));
    if (!method) {
      std::string known;
      for (const FillMethod m : allFillMethods())
        known += (known.empty() ? "" : ", ") + std::string(fillMethodName(m));
      throw UsageError("--methods: unknown method '" + std::string(field) + "' (known: " + known + ")");
    }
    methods.push_back(*method);
  }
  return methods;
}

std::vector<Eigen::Index> parseMarkers(const Take& take, const std::string& text)
{
  return markerIndices(take, splitList(text, "--stabilize"));
}


void writeFillEvaluationText(const std::string& file, const FillEvaluation& evaluation)
{
  std::cout << file << ": " << evaluation.copies << " corrupted copies per gap length, seed "
            << evaluation.seed << "; errors in mm, border velocity jump in mm/s (truth in brackets)\n";
  char line[200];
  std::snprintf(line, sizeof line, "%-13s %6s %8s %8s %8s %8s %18s %9s\n", "method", "length", "mean", "rmse",
                "p95", "max", "border jump", "unfilled");
  std::cout << line;
  Eigen::Index length = -1;
  for (const FillScore& s : evaluation.scores) {
    if (s.gapLength != length && length >= 0)
      std::cout << '\n';
    length = s.gapLength;
    const std::string jump =
        fixedNumber(s.borderVelocityJump, 1) + " (" + fixedNumber(s.trueBorderVelocityJump, 1) + ")";
    const std::string unfilled = std::to_string(s.unfilled) + "/" + std::to_string(s.gaps);
    std::snprintf(line, sizeof line, "%-13s %6lld %8s %8s %8s %8s %18s %9s\n",
                  std::string(fillMethodName(s.method)).c_str(), static_cast<long long>(s.gapLength),
                  fixedNumber(s.meanError, 3).c_str(), fixedNumber(s.rmse, 3).c_str(),
                  fixedNumber(s.p95, 3).c_str(), fixedNumber(s.max, 3).c_str(), jump.c_str(),
                  unfilled.c_str());
    std::cout << line;
  }
}

void writeFillEvaluationJson(const std::string& file, const FillEvaluation& evaluation)
{
  JsonWriter json;
  json.beginObject();
  json.key("take").value(file);
  json.key("copies").value(evaluation.copies);
  json.key("seed").value(static_cast<std::int64_t>(evaluation.seed));
  json.key("results").beginArray();
  for (const FillScore& s : evaluation.scores) {
    json.beginObject();
    json.key("method").value(fillMethodName(s.method));
    json.key("gap_length").value(static_cast<std::int64_t>(s.gapLength));
    json.key("mean_error").value(s.meanError);
    json.key("rmse").value(s.rmse);
    json.key("p95").value(s.p95);
    json.key("max").value(s.max);
    json.key("border_velocity_jump").value(s.borderVelocityJump);
    json.key("true_border_velocity_jump").value(s.trueBorderVelocityJump);
    json.key("gaps").value(static_cast<std::int64_t>(s.gaps));
    json.key("unfilled").value(static_cast<std::int64_t>(s.unfilled));
    json.endObject();
  }
  json.endArray();
  json.endObject();
  std::cout << json.str() << '\n';
}

/// The options of `mocap eval-fill`; FillEvaluationOptions holds the defaults the usage shows.
struct EvalFillArguments
{
  std::string file;
  FillEvaluationOptions options;
  std::optional<std::string> lengths, methods, stabilize;
  bool keepJumps = false;
  bool json = false;
};

int runEvalFill(const EvalFillArguments& arguments)
{
  FillEvaluationOptions options = arguments.options;
  if (arguments.lengths)
    options.gapLengths = parseLengths(*arguments.lengths);
  if (arguments.methods)
    options.methods = parseMethods(*arguments.methods);
  options.skipJumps = !arguments.keepJumps;

  const std::string& file = arguments.file;
  Take take = readTake(file);
  if (arguments.stabilize)
    removeHeadMotion(take, estimateHeadMotion(take, parseMarkers(take, *arguments.stabilize)));
  if (options.gapsPerCopy > take.markerCount())
    throw UsageError("--gaps-per-copy exceeds the take's " + std::to_string(take.markerCount()) + " markers");
  for (const Eigen::Index length : options.gapLengths)
    if (length > take.frameCount() - 2)
      throw UsageError("--lengths: a gap of " + std::to_string(length) +
                       " frames does not fit in the take's " + std::to_string(take.frameCount()) + " frames");
  const FillEvaluation evaluation = evaluateFill(take, options);
  if (arguments.json)
    writeFillEvaluationJson(file, evaluation);
  else
    writeFillEvaluationText(file, evaluation);
  return kExitOk;
}

std::string lengthsText(const std::vector<Eigen::Index>& lengths)
{
  std::string text;
  for (const Eigen::Index length : lengths)
    text += (text.empty() ? "" : ",") + std::to_string(length);
  return text;
}

} // namespace

Command addEvalFill(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand(
      "eval-fill", "gap-filling methods against hidden truth (Gloersen & Federolf protocol)");
  const auto a = std::make_shared<EvalFillArguments>();
  command->add_option("TAKE", a->file, "the take whose valid samples are hidden and filled")->required();
  command->add_option("--lengths", a->lengths, "gap lengths in frames")
      ->type_name(lengthsText(a->options.gapLengths));
  wholeNumberIn(command->add_option("--copies", a->options.copies, "corrupted copies per gap length")
                    ->type_name("N"),
                1, 100000)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--seed", a->options.seed, "random seed")->type_name("S"), 0,
                std::numeric_limits<long long>::max())
      ->capture_default_str();
  command->add_option("--methods", a->methods, "the fill methods to score (default: all)")->type_name("a,b,...");
  wholeNumberIn(command->add_option("--neighbours", a->options.neighbours, "neighbour markers a fill may use")
                    ->type_name("N"),
                1, 1000)
      ->capture_default_str();
  wholeNumberIn(command->add_option("--gaps-per-copy", a->options.gapsPerCopy, "gaps hidden in each copy")
                    ->type_name("N"),
                0, 100000)
      ->capture_default_str();
  command->add_option("--stabilize", a->stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABEL,...");
  command->add_flag("--keep-jumps", a->keepJumps, "also hide (and score) stretches where the take jumps");
  command->add_flag("--json", a->json, "print JSON");
  return {command, [a] { return runEvalFill(*a); }};
}

} // namespace mocap::cli
