#include "actions/labelling_actions.h"

#include "commands/record_step_command.h"
#include "commands/replace_take_command.h"
#include "dialogs/job_dialog.h"
#include "dialogs/swap_review_dialog.h"
#include "document/take_document.h"
#include "views/status_timeout.h"

#include "mocap/base/job_control.h"
#include "mocap/tracking/take_tracking.h"

#include <QMessageBox>
#include <QUndoStack>
#include <QWidget>

namespace mocap::ui {

namespace {

constexpr int kReportMs = 10000;

} // namespace

LabellingActions::LabellingActions(TakeDocument& document, QWidget& dialogParent, QObject* parent)
    : QObject(parent), m_document(document), m_dialogParent(dialogParent)
{
}

void LabellingActions::trackAndLabel()
{
  const Take& take = m_document.take();
  if (take.empty())
    return;
  TrackReport report;
  Take tracked;
  try {
    if (!runJob(&m_dialogParent, tr("Tracking and labelling…"),
                [&](const JobControl& job) { tracked = trackTake(take, nullptr, {}, &report, job); })) {
      emit message(tr("Track and Label cancelled; the take is unchanged"), kStatusMessageMs);
      return;
    }
  } catch (const std::exception& e) {
    QMessageBox::warning(&m_dialogParent, tr("Track and Label"), QString::fromStdString(e.what()));
    return;
  }
  const auto labelled = static_cast<int>(report.labelledFragments);
  const auto fragments = static_cast<int>(report.fragments);
  if (labelled == 0) {
    // Re-tracking alone would only repack the unlabelled points: a change of nothing, so no step.
    emit message(report.unlabelledMarkers == 0
                     ? tr("Nothing to label: every marker has a label")
                     : tr("Nothing to label: none of the %n unlabelled fragment(s) matches a marker", nullptr, fragments),
                 kReportMs);
    return;
  }
  ProcessingStep step =
      studioStep(m_document, "track and label",
                 {{"fragments labelled", std::to_string(labelled) + " of " + std::to_string(fragments)}}, {}, 0, -1, 0);
  m_document.undoStack()->push(new ReplaceTakeCommand(
      m_document, std::move(tracked), tr("Track and label (%1 of %2 fragments labelled)").arg(labelled).arg(fragments),
      std::move(step)));
  emit message(tr("%1 of %2 fragments labelled; %3 samples left unlabelled")
                   .arg(labelled)
                   .arg(fragments)
                   .arg(static_cast<qlonglong>(report.unlabelledSamples)),
               kReportMs);
}

std::optional<std::vector<LabelSwap>> LabellingActions::findSwaps()
{
  std::vector<LabelSwap> swaps;
  try {
    if (!runJob(&m_dialogParent, tr("Looking for label swaps…"),
                [&](const JobControl& job) { swaps = detectSwaps(m_document.take(), {}, job); })) {
      emit message(tr("Swap search cancelled"), kStatusMessageMs);
      return std::nullopt;
    }
  } catch (const std::exception& e) {
    QMessageBox::warning(&m_dialogParent, tr("Fix Swaps"), QString::fromStdString(e.what()));
    return std::nullopt;
  }
  return swaps;
}

void LabellingActions::reviewSwaps()
{
  const Take& take = m_document.take();
  if (take.empty())
    return;
  std::optional<std::vector<LabelSwap>> found = findSwaps();
  if (!found)
    return;
  if (found->empty()) {
    emit message(tr("No label swaps found"), kStatusMessageMs);
    return;
  }
  SwapReviewDialog dialog(take, std::move(*found), &m_dialogParent);
  connect(&dialog, &SwapReviewDialog::frameRequested, &m_document, &TakeDocument::setCurrentFrame);
  if (dialog.exec() != QDialog::Accepted)
    return;
  const std::vector<LabelSwap> accepted = dialog.acceptedSwaps();
  if (accepted.empty()) {
    emit message(tr("No swap accepted; the take is unchanged"), kStatusMessageMs);
    return;
  }
  Take repaired = take;
  for (const LabelSwap& swap : accepted)  // in frame order, as found
    exchangeMarkersFrom(repaired, swap.first, swap.second, swap.frame);
  const int count = static_cast<int>(accepted.size());
  m_document.undoStack()->push(
      new ReplaceTakeCommand(m_document, std::move(repaired), tr("Repair %n label swap(s)", nullptr, count),
                             studioStep(m_document, "repair label swaps", {{"swaps", std::to_string(count)}}, {}, 0, -1, 0)));
}

} // namespace mocap::ui
