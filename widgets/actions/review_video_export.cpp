#include "actions/review_video_export.h"

#include "dialogs/review_export.h"
#include "dialogs/review_export_dialog.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "views/review_scene.h"
#include "views/status_timeout.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QProgressDialog>

namespace mocap::ui {

namespace {
constexpr int kReviewWrittenMessageMs = 8000;  // a path to read and copy
} // namespace

void exportReviewVideo(const ReviewSource& source, QWidget& dialogParent,
                       const std::function<void(const QString&, int)>& message)
{
  const TakeDocument& document = source.session->document();
  if (!document.hasTake())
    return;
  const ReferenceVideo* video = source.session->referenceVideos().current();
  const bool shown = video && video->isOpen();
  ReviewExportDialog dialog(document, shown ? video->path() : QString(), video ? video->offset() : 0.0, &dialogParent);
  if (dialog.exec() != QDialog::Accepted)
    return;
  const ReviewRequest request = dialog.request();
  QProgressDialog progress(ReviewExportDialog::tr("Rendering the review video…"), ReviewExportDialog::tr("Cancel"), 0,
                           static_cast<int>(request.last - request.first + 1), &dialogParent);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(300);
  // Frames render on this thread (the view's GL context is here); events are served between them.
  const ReviewOutcome outcome = exportReview(source, request, [&progress](long long done, long long) {
    progress.setValue(static_cast<int>(done));
    QCoreApplication::processEvents();
    return !progress.wasCanceled();
  });
  progress.reset();
  if (outcome.cancelled) {
    message(ReviewExportDialog::tr("Review video cancelled; nothing was written."), kStatusMessageMs);
    return;
  }
  const QString title = ReviewExportDialog::tr("Export Review Video");
  if (!outcome.done) {
    QMessageBox::warning(&dialogParent, title, ReviewExportDialog::tr("The review video was not written: %1").arg(outcome.error));
    return;
  }
  const QString written = QString::fromStdString(outcome.encoding.path.string());
  const QString codec = QString::fromStdString(outcome.encoding.codec);
  if (outcome.encoding.path != request.output)
    QMessageBox::information(
        &dialogParent, title,
        ReviewExportDialog::tr("This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1").arg(written));
  message(ReviewExportDialog::tr("Wrote %1 (%2 frames, %3)").arg(written).arg(outcome.frames).arg(codec),
          kReviewWrittenMessageMs);
}

} // namespace mocap::ui
