#pragma once

#include "mocap/video/review_video_writer.h"
#include "views/review_scene.h"

#include <QSize>
#include <QString>

#include <Eigen/Core>

#include <filesystem>
#include <functional>
#include <string>

namespace mocap::ui {

/// One review video (playblast) to write.
struct ReviewRequest
{
  std::filesystem::path output;  ///< ".mp4" (H.264 or MPEG-4, else MJPEG AVI beside it) or ".avi"
  QSize size{1280, 720};         ///< the whole frame, pixels (even)
  Eigen::Index first = 0;        ///< take frame indices (0-based), both included; last < 0: to the end
  Eigen::Index last = -1;
  QString video;                 ///< reference video drawn beside the view; empty: none
  double videoOffset = 0.0;      ///< seconds (video time = frame / take rate + offset)
  std::string takeName;          ///< burnt into the caption
};

struct ReviewOutcome
{
  bool done = false;
  bool cancelled = false;
  QString error;            ///< why it failed (neither done nor cancelled)
  ReviewEncoding encoding;  ///< the file written and its codec (done only)
  long long frames = 0;
  double seconds = 0.0;     ///< wall time of the export
};

/// Called after each frame with frames done and the total; returns false to cancel. The studio
/// serves its events here (progress dialog, Cancel).
using ReviewProgress = std::function<bool(long long done, long long total)>;

/// Renders `request`'s frames of `source` (a private ReviewScene, so the studio's session, view
/// and frame are left alone) and encodes them with the reference video frame beside them and the caption
/// burnt in. Rendering runs here, on the UI thread (the view's GL context lives there); reading
/// the reference video, composing and encoding run on a worker thread a few frames behind, so the
/// two overlap. A cancelled or failed export leaves no file (ReviewVideoWriter). Never throws.
/// O(#frames · (render + encode)).
[[nodiscard]] ReviewOutcome exportReview(const ReviewSource& source, const ReviewRequest& request,
                                         const ReviewProgress& progress);

} // namespace mocap::ui
