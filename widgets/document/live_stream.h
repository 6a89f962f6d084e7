#pragma once

#include "mocap/stream/live_streamer.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>

namespace mocap::ui {

class JobRunner;
class StudioSession;

/// The session's live stream (issue 34): while it runs, the current frame of the take goes out
/// over UDP (Live Link Face or VMC) at the take's rate, from the streamer's own thread, so
/// playback, scrubbing and edits reach the engine as they happen and the UI thread never waits on
/// the network. The frames are rebuilt (after a short pause, so a drag of a weight edit sends its
/// end) when the solve, the weights or the take's samples change. Starting resolves the host on a
/// worker. An error (a closed port, an unknown host, nothing to send) is reported, never thrown,
/// and the studio keeps playing.
class LiveStream final : public QObject
{
  Q_OBJECT

public:
  explicit LiveStream(StudioSession& session, QObject* parent = nullptr);
  ~LiveStream() override;

  /// Starts streaming with `settings` (the destination resolved on a worker): started() or
  /// failed(message) follows. A running stream is stopped first.
  void start(const StreamSettings& settings);
  void stop();
  [[nodiscard]] bool running() const { return m_streamer != nullptr; }
  [[nodiscard]] bool starting() const;
  /// What has been sent since start(); empty when not running.
  [[nodiscard]] StreamStats stats() const;
  [[nodiscard]] const StreamSettings& settings() const { return m_settings; }
  /// The frames to stream now from the session: its solved weights on the 52 ARKit curves (when
  /// `weights` and there is a solve) and the take's markers (when `markers`). Throws
  /// InvalidArgument as the recording does. O(#frames · (61 + 3 · #markers)).
  [[nodiscard]] std::shared_ptr<const StreamFrames> framesNow(bool weights, bool markers) const;

signals:
  void started();
  void stopped();
  void failed(const QString& message);

private:
  void scheduleRebuild();
  void rebuild();

  StudioSession& m_session;
  StreamSettings m_settings;
  std::shared_ptr<LiveStreamer> m_streamer;  // made on the worker that resolved its host
  JobRunner* m_connecting = nullptr;
  QTimer m_rebuild;
};

} // namespace mocap::ui
