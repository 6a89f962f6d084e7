// Data-loss findings kept in a take's history (issue 30): what kind each is, how they travel
// through a TRC and its sidecar, and a person's acknowledgement of them.
#include "test_support.h"

#include "mocap/base/file_io.h"
#include "mocap/io/take_io.h"
#include "mocap/model/data_loss_record.h"
#include "mocap/model/provenance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace mocap {
namespace {

const char* const kWrappedFile = "c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d";

struct Read
{
  Take take;
  std::vector<std::string> warnings;
  std::vector<std::string> dataLoss;
};

Read readWithFindings(const std::filesystem::path& path)
{
  Read read;
  read.take = readTake(path, &read.warnings, &read.dataLoss);
  return read;
}

long dataLossSteps(const Take& take)
{
  return std::count_if(take.history().begin(), take.history().end(),
                       [](const ProcessingStep& step) { return step.operation == kDataLossOperation; });
}

std::string joined(const std::vector<std::string>& texts)
{
  std::string all;
  for (const std::string& text : texts)
    all += "\n  " + text;
  return all;
}

TEST(DataLossRecord, EachFindingSaysWhetherDataIsMissingOrWrong)
{
  // The ART file's head marker wrapped round: its samples are there but wrong, not missing.
  const Read wrapped = readWithFindings(test::dataFile(kWrappedFile));
  ASSERT_EQ(wrapped.dataLoss.size(), 1u) << joined(wrapped.dataLoss);
  EXPECT_EQ(dataLossKind(wrapped.dataLoss.front()), DataLossKind::Wrong) << wrapped.dataLoss.front();
  // A C3D and a TRC cut short: data is missing.
  test::TempDir dir;
  const std::string bytes = readFileBytes(test::sampleTake());
  writeFileAtomically(dir.file("cut.c3d"), std::string_view(bytes).substr(0, bytes.size() / 2));
  const Read cut = readWithFindings(dir.file("cut.c3d"));
  ASSERT_EQ(cut.dataLoss.size(), 1u) << joined(cut.dataLoss);
  EXPECT_EQ(dataLossKind(cut.dataLoss.front()), DataLossKind::Missing) << cut.dataLoss.front();
  writeTake(cut.take, dir.file("whole.trc"));
  const std::string trc = readFileBytes(dir.file("whole.trc"));
  writeFileAtomically(dir.file("cut.trc"), std::string_view(trc).substr(0, trc.size() / 2));
  const Read cutTrc = readWithFindings(dir.file("cut.trc"));
  ASSERT_FALSE(cutTrc.dataLoss.empty());
  EXPECT_EQ(dataLossKind(cutTrc.dataLoss.front()), DataLossKind::Missing) << cutTrc.dataLoss.front();
  const DataLossKinds both = dataLossKinds({wrapped.dataLoss.front(), cut.dataLoss.front()});
  EXPECT_TRUE(both.missing && both.wrong);
  // A carried finding is judged by the finding, not by the file's name.
  const DataLossRecord carried{"truncated.c3d", wrapped.dataLoss.front(), false};
  EXPECT_EQ(dataLossKind(recordedFindingText(carried)), DataLossKind::Wrong);
  EXPECT_EQ(dataLossKindName(DataLossKind::Missing), "missing");
  EXPECT_EQ(dataLossKindName(DataLossKind::Wrong), "wrong");
}

TEST(DataLossRecord, AFindingTravelsThroughATrcAndItsSidecarOnce)
{
  // The ART file saved as TRC (positions and a sidecar with the history), read, saved again:
  // each read reports the finding once, as recorded when the ART file was read.
  const Read original = readWithFindings(test::dataFile(kWrappedFile));
  ASSERT_EQ(original.dataLoss.size(), 1u);
  test::TempDir dir;
  Take take = original.take;
  for (int save = 0; save < 3; ++save) {
    const std::filesystem::path path = dir.file("saved" + std::to_string(save) + ".trc");
    writeTake(take, path);
    ASSERT_TRUE(std::filesystem::exists(provenanceSidecarPath(path))) << "save " << save;
    const Read again = readWithFindings(path);
    ASSERT_EQ(again.dataLoss.size(), 1u) << "save " << save << joined(again.dataLoss);
    EXPECT_EQ(again.dataLoss.front(), "recorded when ART-Human_tools_integer_6dofLimbs.c3d was read: " +
                                          original.dataLoss.front());
    EXPECT_EQ(std::count(again.warnings.begin(), again.warnings.end(), again.dataLoss.front()), 1)
        << joined(again.warnings);
    EXPECT_EQ(dataLossSteps(again.take), 1) << "save " << save;
    take = again.take;
  }
  // Saved over itself, the same.
  writeTake(take, dir.file("saved2.trc"));
  EXPECT_EQ(readWithFindings(dir.file("saved2.trc")).dataLoss.size(), 1u);
}

TEST(DataLossRecord, AnAcknowledgedFindingIsKeptButNotRaisedAgain)
{
  Read read = readWithFindings(test::dataFile(kWrappedFile));
  std::vector<DataLossRecord> records = dataLossRecords(read.take);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_FALSE(records.front().acknowledged);
  EXPECT_EQ(records.front().file, "ART-Human_tools_integer_6dofLimbs.c3d");
  EXPECT_EQ(records.front().finding, read.dataLoss.front());
  read.take.history().push_back(acknowledgementOf(records.front(), "test", "2026-12-06T17:00:00Z"));
  records = dataLossRecords(read.take);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_TRUE(records.front().acknowledged);

  test::TempDir dir;
  for (const char* name : {"acknowledged.trc", "acknowledged.c3d"}) {
    writeTake(read.take, dir.file(name));
    const Read again = readWithFindings(dir.file(name));
    EXPECT_TRUE(again.dataLoss.empty()) << name << joined(again.dataLoss);
    EXPECT_TRUE(std::none_of(again.warnings.begin(), again.warnings.end(),
                             [](const std::string& w) { return w.rfind("recorded when ", 0) == 0; }))
        << name << joined(again.warnings);
    const std::vector<DataLossRecord> kept = dataLossRecords(again.take);
    ASSERT_EQ(kept.size(), 1u) << name;
    EXPECT_TRUE(kept.front().acknowledged) << name;
    EXPECT_EQ(dataLossSteps(again.take), 1) << name;
  }
  // Without the acknowledgement (undone), the saved copy raises it again.
  read.take.history().pop_back();
  writeTake(read.take, dir.file("unacknowledged.trc"));
  EXPECT_EQ(readWithFindings(dir.file("unacknowledged.trc")).dataLoss.size(), 1u);
}

} // namespace
} // namespace mocap
