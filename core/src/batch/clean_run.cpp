#include "mocap/batch/clean_run.h"

#include "mocap/io/bvh_writer.h"
#include "mocap/io/take_io.h"
#include "mocap/model/processing_step.h"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <sstream>

namespace mocap {

std::string processingTime()
{
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  long long seconds = 0;
  if (epoch == nullptr || *epoch == '\0')
    return currentUtcTime();
  const char* end = epoch + std::strlen(epoch);
  const auto [at, error] = std::from_chars(epoch, end, seconds);
  if (error != std::errc() || at != end || seconds < 0)
    return currentUtcTime();
  const auto time = static_cast<std::time_t>(seconds);
  std::tm utc{};
  gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

void recordCleanSteps(Take& take, const CleanOptions& options, const CleanReport& report, const std::string& tool)
{
  const std::string time = processingTime();
  auto step = [&](std::string operation, std::vector<std::pair<std::string, std::string>> parameters,
                  std::int64_t samples) {
    ProcessingStep s;
    s.operation = std::move(operation);
    s.parameters = std::move(parameters);
    s.firstFrame = take.firstFrame();
    s.lastFrame = take.firstFrame() + take.frameCount() - 1;
    s.samples = samples;
    s.time = time;
    s.tool = tool;
    take.history().push_back(std::move(s));
  };
  auto number = [](double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  };
  if (!options.stabilizeLabels.empty()) {
    std::string labels;
    for (const std::string& label : options.stabilizeLabels)
      labels += (labels.empty() ? "" : ",") + label;
    step("stabilize head", {{"reference markers", labels}, {"kept", options.keepStabilized ? "yes" : "no"}}, 0);
  }
  if (options.spikes)
    step("repair spikes",
         {{"method", std::string(spikeMethodName(options.spikes->method))},
          {"factor", number(options.spikes->factor)},
          {"threshold", number(options.spikes->threshold)}},
         static_cast<std::int64_t>(report.repairedSamples));
  if (options.fill) {
    const Eigen::Index longest = longestGapFrames(*options.fill, take.frameRate());
    step("fill gaps",
         {{"method", std::string(fillMethodName(options.fill->method))},
          {"max gap", longest == 0 ? std::string("unlimited") : std::to_string(longest) + " frames"},
          {"extrapolate", options.fill->extrapolate ? "yes" : "no"},
          {"min valid", number(options.fill->minValidFraction)},
          {"neighbours", std::to_string(options.fill->neighbours)}},
         static_cast<std::int64_t>(report.filledSamples));
  }
  if (options.smooth)
    step("smooth", {{"method", std::string(smoothMethodName(options.smooth->method))}},
         static_cast<std::int64_t>(report.smoothedSamples));
}

CleanReport cleanAndRecord(Take& take, const CleanOptions& options, const std::string& tool, const JobControl& job)
{
  CleanReport report = cleanTake(take, options, job);
  recordCleanSteps(take, options, report, tool);
  return report;
}

void writeCleanedTake(Take& take, const CleanReport& report, const CleanOptions& options,
                      const std::filesystem::path& output)
{
  if (formatFromPath(output) == TakeFormat::Bvh && report.headMotion && !options.keepStabilized) {
    removeHeadMotion(take, *report.headMotion);
    writeBvh(take, output, BvhOptions{report.headMotion->poses});
  } else {
    writeTake(take, output);
  }
}

} // namespace mocap
