#include "document/live_stream.h"

#include "document/blendshape_solve_model.h"
#include "document/job_runner.h"
#include "document/live_link_recording.h"
#include "document/studio_session.h"
#include "document/take_document.h"

namespace mocap::ui {

namespace {

constexpr int kRebuildPauseMs = 150;  // edits come in bursts (a drag): stream their end

} // namespace

LiveStream::LiveStream(StudioSession& session, QObject* parent)
    : QObject(parent), m_session(session), m_connecting(new JobRunner(this))
{
  m_rebuild.setSingleShot(true);
  m_rebuild.setInterval(kRebuildPauseMs);
  connect(&m_rebuild, &QTimer::timeout, this, &LiveStream::rebuild);
  TakeDocument& document = session.document();
  connect(&document, &TakeDocument::currentFrameChanged, this, [this](Eigen::Index frame) {
    if (m_streamer)
      m_streamer->setCurrentFrame(frame);
  });
  connect(&document, &TakeDocument::samplesChanged, this, &LiveStream::scheduleRebuild);
  connect(&document, &TakeDocument::markersChanged, this, &LiveStream::scheduleRebuild);
  // Another take: its frames are not the stream's.
  connect(&document, &TakeDocument::takeReset, this, &LiveStream::stop);
  BlendshapeSolveModel& solve = session.blendshapes();
  connect(&solve, &BlendshapeSolveModel::resultChanged, this, &LiveStream::scheduleRebuild);
  connect(&solve, &BlendshapeSolveModel::weightsEdited, this, &LiveStream::scheduleRebuild);
  connect(m_connecting, &JobRunner::failed, this, [this](const QString& message) { emit failed(message); });
}

LiveStream::~LiveStream() = default;

bool LiveStream::starting() const
{
  return m_connecting->running();
}

std::shared_ptr<const StreamFrames> LiveStream::framesNow(bool weights, bool markers) const
{
  const Take& take = m_session.document().take();
  auto frames = std::make_shared<StreamFrames>();
  if (weights && m_session.blendshapes().hasResult())
    *frames = streamFramesFromRecording(sessionLiveLinkRecording(m_session), take.frameRate(), take.firstFrame());
  frames->frameRate = take.frameRate();
  frames->firstFrame = take.firstFrame();
  if (markers)
    addStreamMarkers(*frames, take);
  return frames;
}

void LiveStream::start(const StreamSettings& settings)
{
  stop();
  m_settings = settings;
  std::shared_ptr<const StreamFrames> frames;
  try {
    frames = framesNow(settings.sendWeights, settings.sendMarkers);
    checkStreamSettings(settings, *frames);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
    return;
  }
  // The host lookup may wait on a DNS server: on a worker, never the UI thread.
  m_connecting->start(
      [settings, frames](const JobControl& control) {
        auto streamer = std::make_shared<LiveStreamer>(settings, frames);
        control.checkpoint(1.0);  // stopped while the host resolved: no stream
        return streamer;
      },
                      [this](std::shared_ptr<LiveStreamer> streamer) {
                        m_streamer = std::move(streamer);
                        m_streamer->setCurrentFrame(m_session.document().currentFrame());
                        m_streamer->followCurrentFrame();
                        emit started();
                      });
}

void LiveStream::stop()
{
  m_connecting->cancel();
  m_rebuild.stop();
  if (!m_streamer)
    return;
  m_streamer.reset();  // stops and joins its thread at once
  emit stopped();
}

StreamStats LiveStream::stats() const
{
  return m_streamer ? m_streamer->stats() : StreamStats{};
}

void LiveStream::scheduleRebuild()
{
  if (m_streamer)
    m_rebuild.start();
}

void LiveStream::rebuild()
{
  if (!m_streamer)
    return;
  try {
    m_streamer->setFrames(framesNow(m_settings.sendWeights, m_settings.sendMarkers));
  } catch (const std::exception& e) {
    const QString message = QString::fromStdString(e.what());
    stop();  // the solve was cleared, the markers removed: nothing left to send as asked
    emit failed(message);
  }
}

} // namespace mocap::ui
