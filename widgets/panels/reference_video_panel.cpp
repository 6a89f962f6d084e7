#include "panels/reference_video_panel.h"

#include "document/reference_video.h"
#include "document/take_document.h"
#include "panels/panel_folder.h"
#include "panels/status_line.h"
#include "views/video_view.h"

#include "mocap/video/video_sync.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("referenceVideo/");
constexpr int kSaveDelayMs = 400;  // offsets nudged in a row are written once

std::filesystem::path toPath(const QString& path)
{
  return std::filesystem::path(path.toStdString());
}

QString fromPath(const std::filesystem::path& path)
{
  return QString::fromStdString(path.string());
}

bool sameLinks(const std::vector<ReferenceVideoLink>& a, const std::vector<ReferenceVideoLink>& b)
{
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const ReferenceVideoLink& x, const ReferenceVideoLink& y) {
    return x.path == y.path && x.relative == y.relative && x.offset == y.offset;
  });
}

} // namespace

ReferenceVideoPanel::ReferenceVideoPanel(TakeDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document), m_none(new ReferenceVideo(document, this))
{
  m_none->setActive(false);
  auto* layout = new QVBoxLayout(this);
  auto* files = new QHBoxLayout;
  m_choice = new QComboBox(this);
  m_choice->setToolTip(tr("The take's reference videos: the one picked here is shown"));
  m_choice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_choice->setMinimumContentsLength(12);
  connect(m_choice, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0 && index != m_current)
      setCurrentIndex(index);
  });
  files->addWidget(m_choice, 1);
  auto* add = new QPushButton(tr("Add Reference Video…"), this);
  add->setToolTip(tr("A video of the session (MP4, MOV, AVI, MKV) shown at the take's current frame"));
  connect(add, &QPushButton::clicked, this, &ReferenceVideoPanel::openDialog);
  m_locate = new QPushButton(tr("Locate…"), this);
  m_locate->setToolTip(tr("Find a video that is no longer where the take remembers it"));
  connect(m_locate, &QPushButton::clicked, this, &ReferenceVideoPanel::locateDialog);
  m_remove = new QPushButton(tr("Remove"), this);
  m_remove->setToolTip(tr("Remove the shown video from the take"));
  connect(m_remove, &QPushButton::clicked, this, [this] { removeVideo(m_current); });
  files->addWidget(add);
  files->addWidget(m_locate);
  files->addWidget(m_remove);
  layout->addLayout(files);
  m_info = new QLabel(this);
  m_info->setWordWrap(true);
  layout->addWidget(m_info);

  auto* sync = new QGridLayout;
  sync->addWidget(new QLabel(tr("Offset:"), this), 0, 0);
  m_offset = new QDoubleSpinBox(this);
  m_offset->setRange(-86400.0, 86400.0);
  m_offset->setDecimals(3);
  m_offset->setSingleStep(0.001);
  m_offset->setSuffix(tr(" s"));
  m_offset->setToolTip(tr("Video time at the take's first frame: video time = (take frame − first) / take rate + offset"));
  connect(m_offset, &QDoubleSpinBox::valueChanged, this, [this](double seconds) { video().setOffset(seconds); });
  sync->addWidget(m_offset, 0, 1);
  auto* earlier = new QPushButton(tr("−1 frame"), this);
  earlier->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Comma));
  earlier->setToolTip(tr("Show the video one of its frames earlier (Alt+,)"));
  connect(earlier, &QPushButton::clicked, this, [this] { nudgeOrStep(-1); });
  auto* later = new QPushButton(tr("+1 frame"), this);
  later->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Period));
  later->setToolTip(tr("Show the video one of its frames later (Alt+.)"));
  connect(later, &QPushButton::clicked, this, [this] { nudgeOrStep(1); });
  sync->addWidget(earlier, 0, 2);
  sync->addWidget(later, 0, 3);

  sync->addWidget(new QLabel(tr("Video frame:"), this), 1, 0);
  m_frame = new QSpinBox(this);
  // −1 reads "none": the take's frame has no video frame (before or after the video), so the
  // box never claims a frame the view does not show; stepping down to it follows the take again.
  m_frame->setRange(-1, std::numeric_limits<int>::max());
  m_frame->setSpecialValueText(tr("none"));
  m_frame->setKeyboardTracking(false);
  m_frame->setToolTip(tr("The video frame shown. Type or step it to hold the video at a moment, step the take to "
                         "the same moment, then press Sync here"));
  connect(m_frame, &QSpinBox::valueChanged, this, [this](int frame) {
    video().hold(frame < 0 ? std::nullopt : std::optional<Eigen::Index>(frame));
  });
  sync->addWidget(m_frame, 1, 1);
  m_syncHere = new QPushButton(tr("Sync here"), this);
  m_syncHere->setToolTip(tr("Set the offset so the held video frame shows at the take's current frame"));
  connect(m_syncHere, &QPushButton::clicked, this, &ReferenceVideoPanel::syncHere);
  m_follow = new QPushButton(tr("Follow take"), this);
  m_follow->setToolTip(tr("Stop holding the video: show the frame for the take's current frame again"));
  connect(m_follow, &QPushButton::clicked, this, [this] { video().hold(std::nullopt); });
  sync->addWidget(m_syncHere, 1, 2);
  sync->addWidget(m_follow, 1, 3);

  sync->addWidget(new QLabel(tr("Event:"), this), 2, 0);
  m_eventChoice = new QComboBox(this);
  m_eventChoice->setToolTip(tr("The take's events (C3D EVENT parameters); a sync event is picked first"));
  sync->addWidget(m_eventChoice, 2, 1);
  m_syncEvent = new QPushButton(tr("Sync to event"), this);
  m_syncEvent->setToolTip(tr("Set the offset so the event shows the video's first frame, or the held one"));
  connect(m_syncEvent, &QPushButton::clicked, this, [this] {
    const int index = m_eventChoice->currentIndex();
    if (index >= 0 && static_cast<std::size_t>(index) < m_events.size())
      (void)syncToEvent(m_events[static_cast<std::size_t>(index)]);
  });
  sync->addWidget(m_syncEvent, 2, 2, 1, 2);
  sync->setColumnStretch(1, 1);
  layout->addLayout(sync);

  m_views = new QStackedWidget(this);
  m_noneView = new VideoView(*m_none, m_views);
  m_views->addWidget(m_noneView);
  layout->addWidget(m_views, 1);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);

  m_saveTimer.setSingleShot(true);
  m_saveTimer.setInterval(kSaveDelayMs);
  connect(&m_saveTimer, &QTimer::timeout, this, &ReferenceVideoPanel::saveSidecar);
  connect(&document, &TakeDocument::takeReset, this, &ReferenceVideoPanel::restore);
  connect(&document, &TakeDocument::filePathChanged, this, &ReferenceVideoPanel::takePathChanged);
  connect(&document, &TakeDocument::currentFrameChanged, this, [this] {
    if (m_current >= 0)
      updateInfo();
  });
  restore();
}

ReferenceVideoPanel::~ReferenceVideoPanel()
{
  saveSidecar();
}

ReferenceVideo& ReferenceVideoPanel::video() const
{
  return m_current >= 0 ? *m_entries[static_cast<std::size_t>(m_current)].video : *m_none;
}

ReferenceVideo& ReferenceVideoPanel::video(int index) const
{
  return *m_entries.at(static_cast<std::size_t>(index)).video;
}

VideoView& ReferenceVideoPanel::view() const
{
  return m_current >= 0 ? *m_entries[static_cast<std::size_t>(m_current)].view : *m_noneView;
}

bool ReferenceVideoPanel::isMissing(int index) const
{
  return !video(index).isOpen();
}

int ReferenceVideoPanel::addEntry(const ReferenceVideoLink& link, ReferenceVideo* opened)
{
  Entry entry;
  entry.video = opened ? opened : new ReferenceVideo(m_document, this);
  entry.video->setActive(false);
  entry.stored = link;
  entry.view = new VideoView(*entry.video, m_views);
  m_views->addWidget(entry.view);
  ReferenceVideo* video = entry.video;
  connect(video, &ReferenceVideo::changed, this, [this, video] {
    if (m_current >= 0 && video == m_entries[static_cast<std::size_t>(m_current)].video)
      updateInfo();
    scheduleSave();
  });
  connect(video, &ReferenceVideo::frameShown, this, [this, video] {
    if (m_current >= 0 && video == m_entries[static_cast<std::size_t>(m_current)].video)
      updateInfo();
  });
  m_entries.push_back(entry);
  const QSignalBlocker blocker(m_choice);
  m_choice->addItem(QString());
  return videoCount() - 1;
}

void ReferenceVideoPanel::clearEntries()
{
  for (Entry& entry : m_entries) {
    delete entry.view;
    delete entry.video;
  }
  m_entries.clear();
  const QSignalBlocker blocker(m_choice);
  m_choice->clear();
  m_current = -1;
}

void ReferenceVideoPanel::setCurrentIndex(int index)
{
  m_current = index >= 0 && index < videoCount() ? index : (m_entries.empty() ? -1 : 0);
  for (int i = 0; i < videoCount(); ++i)
    video(i).setActive(i == m_current);  // only the shown video decodes
  m_views->setCurrentWidget(&view());
  {
    const QSignalBlocker blocker(m_choice);
    m_choice->setCurrentIndex(m_current);
  }
  updateInfo();
}

QString ReferenceVideoPanel::openVideo(const QString& path)
{
  const QString absolute = QFileInfo(path).absoluteFilePath();
  for (int i = 0; i < videoCount(); ++i)
    if (video(i).isOpen() && QFileInfo(video(i).path()).absoluteFilePath() == absolute) {
      setCurrentIndex(i);  // already linked: show it
      return {};
    }
  auto* opened = new ReferenceVideo(m_document, this);
  opened->setActive(false);
  const QString error = opened->open(absolute);
  if (!error.isEmpty()) {
    delete opened;
    showStatusLine(*m_status, tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error), true);
    return m_status->text();
  }
  const std::filesystem::path take = m_document.filePath().isEmpty() ? toPath(absolute) : toPath(m_document.filePath());
  const int index = addEntry(linkReferenceVideo(toPath(absolute), take, 0.0), opened);
  setCurrentIndex(index);
  showStatusLine(*m_status, QString(), false);
  scheduleSave();
  return {};
}

void ReferenceVideoPanel::removeVideo(int index)
{
  if (index < 0 || index >= videoCount())
    return;
  Entry entry = m_entries[static_cast<std::size_t>(index)];
  m_entries.erase(m_entries.begin() + index);
  {
    const QSignalBlocker blocker(m_choice);
    m_choice->removeItem(index);
  }
  m_current = -1;
  delete entry.view;
  delete entry.video;
  setCurrentIndex(std::min(index, videoCount() - 1));
  showStatusLine(*m_status, QString(), false);
  scheduleSave();
}

QString ReferenceVideoPanel::locateVideo(int index, const QString& path)
{
  if (index < 0 || index >= videoCount())
    return {};
  ReferenceVideo& located = video(index);
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const QString error = located.open(absolute);  // keeps the offset
  if (!error.isEmpty()) {
    showStatusLine(*m_status, tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error), true);
    return m_status->text();
  }
  const std::filesystem::path take = m_document.filePath().isEmpty() ? toPath(absolute) : toPath(m_document.filePath());
  m_entries[static_cast<std::size_t>(index)].stored = linkReferenceVideo(toPath(absolute), take, located.offset());
  setCurrentIndex(index);
  showStatusLine(*m_status, QString(), false);
  scheduleSave();
  return {};
}

void ReferenceVideoPanel::nudgeOrStep(int frames)
{
  ReferenceVideo& shown = video();
  if (shown.heldFrame())
    shown.hold(*shown.heldFrame() + frames);  // a held video steps through its own frames
  else
    shown.nudge(frames);
}

void ReferenceVideoPanel::syncHere()
{
  ReferenceVideo& shown = video();
  if (!shown.isOpen() || !shown.heldFrame()) {
    showStatusLine(*m_status, tr("First hold the video at a moment: type its frame or step it, then step the take to "
                                 "the same moment"), false);
    return;
  }
  const Eigen::Index videoFrame = *shown.heldFrame();
  const Eigen::Index takeFrame = m_document.currentFrame();
  shown.syncTo(takeFrame, videoFrame);
  showStatusLine(*m_status,
                 tr("Video frame %1 now shows at take frame %2 (offset %3 s)")
                     .arg(static_cast<qlonglong>(videoFrame))
                     .arg(static_cast<qlonglong>(takeFrame + m_document.take().firstFrame()))
                     .arg(shown.offset(), 0, 'f', 3),
                 false);
}

QString ReferenceVideoPanel::syncToEvent(std::size_t eventIndex)
{
  const Take& take = m_document.take();
  ReferenceVideo& shown = video();
  if (!shown.isOpen() || eventIndex >= take.events().size() || take.frameRate() <= 0.0)
    return {};
  const Event& event = take.events()[eventIndex];
  const Eigen::Index takeFrame = takeFrameOfEvent(event.time, take.frameRate(), take.firstFrame());
  if (takeFrame < 0 || takeFrame >= take.frameCount()) {
    showStatusLine(*m_status, tr("The event “%1” (%2 s) lies outside the take's frames")
                                  .arg(QString::fromStdString(event.label))
                                  .arg(event.time, 0, 'f', 3),
                   true);
    return m_status->text();
  }
  const Eigen::Index videoFrame = shown.heldFrame().value_or(0);
  shown.syncTo(takeFrame, videoFrame);
  showStatusLine(*m_status,
                 tr("Video frame %1 now shows at the event “%2” (take frame %3; offset %4 s)")
                     .arg(static_cast<qlonglong>(videoFrame))
                     .arg(QString::fromStdString(event.label))
                     .arg(static_cast<qlonglong>(takeFrame + take.firstFrame()))
                     .arg(shown.offset(), 0, 'f', 3),
                 false);
  return {};
}

QString ReferenceVideoPanel::statusText() const
{
  return m_status->text();
}

QString ReferenceVideoPanel::videoFrameText() const
{
  return m_frame->text();
}

void ReferenceVideoPanel::updateInfo()
{
  ReferenceVideo& shown = video();
  const bool open = shown.isOpen();
  {
    const QSignalBlocker blockOffset(m_offset);
    m_offset->setValue(shown.offset());
    const QSignalBlocker blockFrame(m_frame);
    const int last = open ? static_cast<int>(std::min<Eigen::Index>(shown.info().frames - 1, 1 << 30)) : 0;
    if (m_frame->maximum() != last)  // setMaximum relayouts the window even when it stays
      m_frame->setMaximum(last);
    m_frame->setValue(static_cast<int>(shown.wantedFrame().value_or(-1)));
  }
  m_offset->setEnabled(m_current >= 0);
  m_frame->setEnabled(open);
  m_remove->setEnabled(m_current >= 0);
  m_locate->setEnabled(m_current >= 0 && !open);
  m_syncHere->setEnabled(open && shown.heldFrame().has_value());
  m_follow->setEnabled(open && shown.heldFrame().has_value());
  m_syncEvent->setEnabled(open && !m_events.empty());
  m_choice->setEnabled(!m_entries.empty());
  for (int i = 0; i < videoCount(); ++i) {
    const QString name = QFileInfo(video(i).path()).fileName();
    m_choice->setItemText(i, video(i).isOpen() ? name : tr("%1 (missing)").arg(name));
  }
  if (m_entries.empty())
    m_choice->setPlaceholderText(tr("No reference video"));
  if (!open) {
    m_info->setText(m_current >= 0 ? tr("%1 is not available").arg(QFileInfo(shown.path()).fileName())
                                   : tr("No reference video"));
    return;
  }
  const VideoInfo& info = shown.info();
  QString text = tr("%1: %2×%3, %4 fps, %5 frames (%6 s), %7")
                     .arg(QFileInfo(shown.path()).fileName())
                     .arg(info.width)
                     .arg(info.height)
                     .arg(info.rate, 0, 'g', 5)
                     .arg(static_cast<qlonglong>(info.frames))
                     .arg(info.seconds(), 0, 'f', 2)
                     .arg(QString::fromStdString(info.codec));
  if (info.variableRate)
    text += tr("; variable frame rate: frames are placed by their timestamps");
  m_info->setText(text);
}

void ReferenceVideoPanel::updateEvents()
{
  const std::vector<Event>& events = m_document.take().events();
  m_events.clear();
  const std::optional<std::size_t> likely = syncEventIndex(events);
  if (likely)
    m_events.push_back(*likely);
  for (std::size_t i = 0; i < events.size(); ++i)
    if (i != likely)
      m_events.push_back(i);
  const QSignalBlocker blocker(m_eventChoice);
  m_eventChoice->clear();
  const Take& take = m_document.take();
  for (const std::size_t i : m_events) {
    const Event& e = events[i];
    const QString label = QString::fromStdString(e.label.empty() ? std::string("event") : e.label);
    const QString context = QString::fromStdString(e.context);
    const Eigen::Index frame = take.frameRate() > 0.0 ? takeFrameOfEvent(e.time, take.frameRate(), take.firstFrame()) : 0;
    m_eventChoice->addItem(tr("%1%2 · frame %3")
                               .arg(label, context.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(context))
                               .arg(static_cast<qlonglong>(frame + take.firstFrame())));
  }
  m_eventChoice->setEnabled(!m_events.empty());
  if (m_events.empty())
    m_eventChoice->setPlaceholderText(tr("The take has no events"));
}

void ReferenceVideoPanel::restore()
{
  saveSidecar();  // a change still pending belongs to the take that was open
  m_restoring = true;
  clearEntries();
  m_sidecarTake = m_document.filePath();
  m_sidecarReadable = true;
  m_saved.clear();
  QString problem;
  int missing = 0;
  if (!m_sidecarTake.isEmpty()) {
    try {
      m_saved = readReferenceVideoSidecar(toPath(m_sidecarTake));
    } catch (const std::exception& e) {
      m_sidecarReadable = false;
      problem = tr("The videos remembered for this take cannot be read (%1); that file is left as it is and "
                   "changes here are not remembered.")
                    .arg(QString::fromStdString(e.what()));
    }
    for (const ReferenceVideoLink& link : m_saved) {
      const int index = addEntry(link);
      ReferenceVideo& restored = video(index);
      restored.setOffset(link.offset);
      const QString path = fromPath(link.path);
      const QString error = link.found ? restored.open(path) : QString();
      if (!link.found)
        restored.setUnavailable(path, tr("%1 is missing: the take remembers it at %2. Locate… finds it; until "
                                         "then it stays linked to the take.")
                                          .arg(QFileInfo(path).fileName(), QDir::toNativeSeparators(path)));
      else if (!error.isEmpty())
        restored.setUnavailable(path, tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error));
      if (!restored.isOpen())
        ++missing;
    }
  }
  m_restoring = false;
  updateEvents();
  int shown = -1;
  for (int i = 0; i < videoCount() && shown < 0; ++i)
    if (video(i).isOpen())
      shown = i;
  setCurrentIndex(shown >= 0 ? shown : 0);
  if (!problem.isEmpty())
    showStatusLine(*m_status, problem, true);
  else if (missing > 0)
    showStatusLine(*m_status,
                   tr("%n of the take's reference videos cannot be found where the take remembers them. Pick one "
                      "and press Locate… to find it; they stay remembered meanwhile.",
                      "", missing),
                   true);
  else
    showStatusLine(*m_status, QString(), false);
  if (!m_entries.empty())
    emit videosRestored(videoCount(), missing);
}

void ReferenceVideoPanel::takePathChanged(const QString& path)
{
  if (path == m_sidecarTake)
    return;
  // Saved under a new name: the videos go with it (relative to its folder), the old sidecar stays.
  saveSidecar();
  m_sidecarTake = path;
  m_sidecarReadable = true;
  m_saved.clear();
  for (Entry& entry : m_entries)
    if (!entry.video->isOpen() && !path.isEmpty())
      entry.stored = linkReferenceVideo(entry.stored.path, toPath(path), entry.video->offset());
  scheduleSave();
}

std::vector<ReferenceVideoLink> ReferenceVideoPanel::links() const
{
  std::vector<ReferenceVideoLink> result;
  const std::filesystem::path take = toPath(m_sidecarTake);
  for (const Entry& entry : m_entries) {
    ReferenceVideoLink link = entry.video->isOpen()
                                  ? linkReferenceVideo(toPath(entry.video->path()), take, entry.video->offset())
                                  : entry.stored;  // missing: as stored, so nothing is lost
    link.offset = entry.video->offset();
    result.push_back(std::move(link));
  }
  return result;
}

void ReferenceVideoPanel::scheduleSave()
{
  if (!m_restoring)
    m_saveTimer.start();
}

void ReferenceVideoPanel::saveSidecar()
{
  m_saveTimer.stop();
  if (m_restoring || m_sidecarTake.isEmpty() || !m_sidecarReadable)
    return;
  std::vector<ReferenceVideoLink> current = links();
  if (sameLinks(current, m_saved))
    return;
  try {
    writeReferenceVideoSidecar(toPath(m_sidecarTake), current);
    m_saved = std::move(current);
  } catch (const std::exception& e) {
    showStatusLine(*m_status, tr("Cannot remember the videos beside the take: %1").arg(QString::fromStdString(e.what())),
                   true);
  }
}

void ReferenceVideoPanel::openDialog()
{
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Add reference video"), panelFolder(kGroup),
      tr("Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)"));
  if (path.isEmpty())
    return;
  rememberPanelFolder(kGroup, path);
  (void)openVideo(path);
}

void ReferenceVideoPanel::locateDialog()
{
  if (m_current < 0)
    return;
  const QString missing = video().path();
  QString folder = QFileInfo(missing).absolutePath();
  if (!QFileInfo(folder).isDir())
    folder = m_document.filePath().isEmpty() ? panelFolder(kGroup) : QFileInfo(m_document.filePath()).absolutePath();
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Locate %1").arg(QFileInfo(missing).fileName()), folder,
      tr("Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)"));
  if (path.isEmpty())
    return;  // declined: the video stays linked as it was
  rememberPanelFolder(kGroup, path);
  (void)locateVideo(m_current, path);
}

} // namespace mocap::ui
