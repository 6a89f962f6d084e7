// Autosave and crash recovery: the recovery file exists exactly while there are unsaved edits,
// holds them, and a file left by a dead process is found with the name of what it was editing.
#include "sample_files.h"
#include "../core/test_support.h"

#include "commands/apply_patches_command.h"
#include "document/autosave.h"
#include "document/take_document.h"

#include "mocap/io/take_io.h"

#include <QFile>
#include <QUndoStack>

#include <gtest/gtest.h>

namespace mocap {
namespace {

using test::qpath;

using ui::Autosave;
using ui::TakeDocument;

TEST(Autosave, KeepsUnsavedEditsUntilSavedAndOffersLeftoversOfDeadSessions)
{
  test::TempDir dir;
  TakeDocument document;
  ASSERT_EQ(document.open(qpath(test::sampleTake())), QString());
  Autosave autosave(document, qpath(dir.path()));
  EXPECT_EQ(autosave.saveNow(), QString());
  EXPECT_FALSE(QFile::exists(autosave.recoveryPath())) << "nothing unsaved, nothing written";

  const Eigen::Index marker = *document.take().markerIndex("root-1");
  document.undoStack()->push(new ui::ApplyPatchesCommand(
      document, {deleteSamples(document.take(), marker, 100, 109)}, QStringLiteral("delete")));
  ASSERT_EQ(autosave.saveNow(), QString());
  ASSERT_TRUE(QFile::exists(autosave.recoveryPath()));
  const Take recovered = readTake(autosave.recoveryPath().toStdString());
  EXPECT_FALSE(recovered.valid().col(marker).segment(100, 10).any()) << "the edit is in the recovery file";
  EXPECT_TRUE(Autosave::leftovers(qpath(dir.path())).empty()) << "our own file is not a leftover";

  // A file written by a process that no longer runs.
  const QString dead = qpath(dir.file("take-2147480000.c3d"));
  ASSERT_TRUE(QFile::copy(autosave.recoveryPath(), dead));
  ASSERT_TRUE(QFile::copy(autosave.recoveryPath() + ".ini", dead + ".ini"));
  const auto leftovers = Autosave::leftovers(qpath(dir.path()));
  ASSERT_EQ(leftovers.size(), 1u);
  EXPECT_EQ(leftovers.front().path, dead);
  EXPECT_EQ(leftovers.front().originalPath, qpath(test::sampleTake()));
  Autosave::remove(leftovers.front());
  EXPECT_FALSE(QFile::exists(dead));

  // Saving makes the recovery copy stale: it goes.
  ASSERT_EQ(document.save(qpath(dir.file("saved.c3d"))), QString());
  EXPECT_FALSE(QFile::exists(autosave.recoveryPath()));
}

TEST(Autosave, AnUnwritableFolderIsAnErrorMessageNotACrash)
{
  test::TempDir dir;
  QFile blocker(qpath(dir.file("blocker")));
  ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  TakeDocument document;
  ASSERT_EQ(document.open(qpath(test::sampleTake())), QString());
  Autosave autosave(document, qpath(dir.file("blocker")) + "/recovery");
  document.undoStack()->push(new ui::ApplyPatchesCommand(
      document, {deleteSamples(document.take(), 0, 10, 19)}, QStringLiteral("delete")));
  EXPECT_FALSE(autosave.saveNow().isEmpty());
}

} // namespace
} // namespace mocap
