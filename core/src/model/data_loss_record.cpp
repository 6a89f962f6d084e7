#include "mocap/model/data_loss_record.h"

#include "mocap/model/processing_step.h"

#include <algorithm>
#include <filesystem>

namespace mocap {

namespace {

constexpr std::string_view kRecordedPrefix = "recorded when ";
constexpr std::string_view kRecordedMiddle = " was read: ";

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

/// The reader's finding inside a carried text, or the text itself.
std::string_view findingOf(std::string_view text)
{
  if (text.substr(0, kRecordedPrefix.size()) != kRecordedPrefix)
    return text;
  const std::size_t at = text.find(kRecordedMiddle);
  return at == std::string_view::npos ? text : text.substr(at + kRecordedMiddle.size());
}

} // namespace

DataLossKind dataLossKind(std::string_view finding)
{
  const std::string_view words = findingOf(finding);
  const bool missing = words.find("truncated") != std::string_view::npos ||
                       words.find("shorter than declared") != std::string_view::npos;
  return missing ? DataLossKind::Missing : DataLossKind::Wrong;
}

std::string_view dataLossKindName(DataLossKind kind)
{
  return kind == DataLossKind::Missing ? "missing" : "wrong";
}

DataLossKinds dataLossKinds(const std::vector<std::string>& findings)
{
  DataLossKinds kinds;
  for (const std::string& finding : findings)
    (dataLossKind(finding) == DataLossKind::Missing ? kinds.missing : kinds.wrong) = true;
  return kinds;
}

std::vector<DataLossRecord> dataLossRecords(const Take& take)
{
  const std::vector<ProcessingStep>& history = take.history();
  std::vector<DataLossRecord> records;
  for (std::size_t i = 0; i < history.size(); ++i) {
    if (!isDataLossStep(history[i]))
      continue;
    DataLossRecord record{parameterOf(history[i], "file"), parameterOf(history[i], "finding"), false};
    record.acknowledged = std::any_of(history.begin() + static_cast<std::ptrdiff_t>(i) + 1, history.end(),
                                      [&](const ProcessingStep& step) {
                                        return step.operation == kDataLossAcknowledgedOperation &&
                                               parameterOf(step, "file") == record.file &&
                                               parameterOf(step, "finding") == record.finding;
                                      });
    records.push_back(std::move(record));
  }
  return records;
}

std::string recordedFindingText(const DataLossRecord& record)
{
  return std::string(kRecordedPrefix) + record.file + std::string(kRecordedMiddle) + record.finding;
}

ProcessingStep acknowledgementOf(const DataLossRecord& record, std::string tool, std::string time)
{
  ProcessingStep step;
  step.operation = std::string(kDataLossAcknowledgedOperation);
  step.parameters = {{"file", record.file}, {"finding", record.finding}};
  step.tool = std::move(tool);
  step.time = std::move(time);
  return step;
}

void carryDataLoss(Take& take, const std::string& source, std::vector<std::string>& dataLoss, std::size_t firstNew,
                   std::vector<std::string>* warnings)
{
  const std::vector<DataLossRecord> held = dataLossRecords(take);  // what the file's history kept
  const std::vector<std::string> found(dataLoss.begin() + static_cast<std::ptrdiff_t>(std::min(firstNew, dataLoss.size())),
                                       dataLoss.end());
  const std::string file = std::filesystem::path(source).filename().string();
  for (const std::string& finding : found) {
    const std::vector<ProcessingStep>& history = take.history();
    if (std::any_of(history.begin(), history.end(), [&](const ProcessingStep& step) {
          return isDataLossStep(step) && parameterOf(step, "finding") == finding;
        }))
      continue;
    ProcessingStep step;
    step.operation = std::string(kDataLossOperation);
    step.parameters = {{"file", file}, {"finding", finding}};
    step.tool = "mocap reader";
    take.history().push_back(std::move(step));
  }
  for (const DataLossRecord& record : held) {
    if (record.acknowledged || std::find(found.begin(), found.end(), record.finding) != found.end())
      continue;
    const std::string carried = recordedFindingText(record);
    dataLoss.push_back(carried);
    if (warnings)
      warnings->push_back(carried);
  }
}

} // namespace mocap
