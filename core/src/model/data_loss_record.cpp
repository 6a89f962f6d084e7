#include "mocap/model/data_loss_record.h"

#include "mocap/model/processing_step.h"

#include <algorithm>
#include <filesystem>

namespace mocap {

namespace {

std::string parameterOf(const ProcessingStep& step, std::string_view name)
{
  for (const auto& [key, value] : step.parameters)
    if (key == name)
      return value;
  return {};
}

bool isDataLossStep(const ProcessingStep& step)
{
  return step.operation == kDataLossOperation;
}

} // namespace

void carryDataLoss(Take& take, const std::string& source, std::vector<std::string>& dataLoss, std::size_t firstNew,
                   std::vector<std::string>* warnings)
{
  std::vector<ProcessingStep>& history = take.history();
  const std::size_t heldBefore = history.size();
  const auto recorded = [&](const std::string& finding) {
    return std::any_of(history.begin(), history.end(), [&](const ProcessingStep& step) {
      return isDataLossStep(step) && parameterOf(step, "finding") == finding;
    });
  };
  const std::vector<std::string> found(dataLoss.begin() + static_cast<std::ptrdiff_t>(std::min(firstNew, dataLoss.size())),
                                       dataLoss.end());
  const std::string file = std::filesystem::path(source).filename().string();
  for (const std::string& finding : found) {
    if (recorded(finding))
      continue;
    ProcessingStep step;
    step.operation = std::string(kDataLossOperation);
    step.parameters = {{"file", file}, {"finding", finding}};
    step.tool = "mocap reader";
    history.push_back(std::move(step));
  }
  for (std::size_t i = 0; i < heldBefore; ++i) {
    const ProcessingStep& step = history[i];
    const std::string finding = parameterOf(step, "finding");
    if (!isDataLossStep(step) || std::find(found.begin(), found.end(), finding) != found.end())
      continue;
    const std::string carried = "recorded when " + parameterOf(step, "file") + " was read: " + finding;
    dataLoss.push_back(carried);
    if (warnings)
      warnings->push_back(carried);
  }
}

} // namespace mocap
