#include "panels/reference_video_panel.h"

#include "dialogs/remembered_file_dialog.h"
#include "document/reference_video.h"
#include "document/reference_videos.h"
#include "document/remembered_folder.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/flow_layout.h"
#include "panels/status_line.h"
#include "views/video_view.h"

#include "mocap/video/video_sync.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
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

} // namespace

ReferenceVideoPanel::ReferenceVideoPanel(StudioSession& session, QWidget* parent)
    : QWidget(parent),
      m_document(session.document()),
      m_videos(session.referenceVideos()),
      m_none(new ReferenceVideo(session.document(), this))
{
  m_none->setActive(false);
  auto* layout = new QVBoxLayout(this);
  m_choice = new QComboBox(this);
  m_choice->setToolTip(tr("The take's reference videos: the one picked here is shown"));
  m_choice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_choice->setMinimumContentsLength(12);
  connect(m_choice, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0 && index != m_videos.currentIndex())
      setCurrentIndex(index);
  });
  layout->addWidget(m_choice);
  auto* add = new QPushButton(tr("Add Reference Video…"), this);
  add->setToolTip(tr("A video of the session (MP4, MOV, AVI, MKV) shown at the take's current frame"));
  connect(add, &QPushButton::clicked, this, &ReferenceVideoPanel::openDialog);
  m_locate = new QPushButton(tr("Locate…"), this);
  m_locate->setToolTip(tr("Find a video that is no longer where the take remembers it"));
  connect(m_locate, &QPushButton::clicked, this, &ReferenceVideoPanel::locateDialog);
  m_remove = new QPushButton(tr("Remove"), this);
  m_remove->setToolTip(tr("Remove the shown video from the take"));
  connect(m_remove, &QPushButton::clicked, this, [this] { removeVideo(m_videos.currentIndex()); });
  auto* files = new FlowLayout;  // wraps in a narrow dock
  files->addWidget(add);
  files->addWidget(m_locate);
  files->addWidget(m_remove);
  layout->addLayout(files);
  m_info = new QLabel(this);
  m_info->setWordWrap(true);
  layout->addWidget(m_info);

  // Each row's buttons wrap under its box in a narrow dock.
  auto* sync = new QFormLayout;
  auto* offsetRow = new FlowLayout;
  m_offset = new QDoubleSpinBox(this);
  m_offset->setRange(-86400.0, 86400.0);
  m_offset->setDecimals(3);
  m_offset->setSingleStep(0.001);
  m_offset->setSuffix(tr(" s"));
  m_offset->setToolTip(tr("Video time at the take's first frame: video time = (take frame − first) / take rate + offset"));
  connect(m_offset, &QDoubleSpinBox::valueChanged, this, [this](double seconds) { video().setOffset(seconds); });
  offsetRow->addWidget(m_offset);
  auto* earlier = new QPushButton(tr("−1 frame"), this);
  earlier->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Comma));
  earlier->setToolTip(tr("Show the video one of its frames earlier (Alt+,)"));
  connect(earlier, &QPushButton::clicked, this, [this] { nudgeOrStep(-1); });
  auto* later = new QPushButton(tr("+1 frame"), this);
  later->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Period));
  later->setToolTip(tr("Show the video one of its frames later (Alt+.)"));
  connect(later, &QPushButton::clicked, this, [this] { nudgeOrStep(1); });
  offsetRow->addWidget(earlier);
  offsetRow->addWidget(later);
  sync->addRow(tr("Offset:"), offsetRow);

  auto* frameRow = new FlowLayout;
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
  frameRow->addWidget(m_frame);
  m_syncHere = new QPushButton(tr("Sync here"), this);
  m_syncHere->setToolTip(tr("Set the offset so the held video frame shows at the take's current frame"));
  connect(m_syncHere, &QPushButton::clicked, this, &ReferenceVideoPanel::syncHere);
  m_follow = new QPushButton(tr("Follow take"), this);
  m_follow->setToolTip(tr("Stop holding the video: show the frame for the take's current frame again"));
  connect(m_follow, &QPushButton::clicked, this, [this] { video().hold(std::nullopt); });
  frameRow->addWidget(m_syncHere);
  frameRow->addWidget(m_follow);
  sync->addRow(tr("Video frame:"), frameRow);

  auto* eventRow = new FlowLayout;
  m_eventChoice = new QComboBox(this);
  m_eventChoice->setToolTip(tr("The take's events (C3D EVENT parameters); a sync event is picked first"));
  eventRow->addWidget(m_eventChoice);
  m_syncEvent = new QPushButton(tr("Sync to event"), this);
  m_syncEvent->setToolTip(tr("Set the offset so the event shows the video's first frame, or the held one"));
  connect(m_syncEvent, &QPushButton::clicked, this, [this] {
    const int index = m_eventChoice->currentIndex();
    if (index >= 0 && static_cast<std::size_t>(index) < m_events.size())
      (void)syncToEvent(m_events[static_cast<std::size_t>(index)]);
  });
  eventRow->addWidget(m_syncEvent);
  sync->addRow(tr("Event:"), eventRow);
  layout->addLayout(sync);

  m_stack = new QStackedWidget(this);
  m_noneView = new VideoView(*m_none, m_stack);
  m_stack->addWidget(m_noneView);
  layout->addWidget(m_stack, 1);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);

  connect(&m_videos, &ReferenceVideos::videoInserted, this, &ReferenceVideoPanel::videoInserted);
  connect(&m_videos, &ReferenceVideos::videoAboutToBeRemoved, this, &ReferenceVideoPanel::videoAboutToBeRemoved);
  connect(&m_videos, &ReferenceVideos::currentChanged, this, &ReferenceVideoPanel::currentChanged);
  connect(&m_videos, &ReferenceVideos::videoChanged, this, [this](int index) {
    if (index == m_videos.currentIndex())
      updateInfo();
  });
  connect(&m_videos, &ReferenceVideos::restored, this, &ReferenceVideoPanel::restored);
  connect(&m_videos, &ReferenceVideos::saveFailed, this, [this](const QString& error) {
    showStatusLine(*m_status, error, true);
  });
  connect(&m_document, &TakeDocument::currentFrameChanged, this, [this] {
    if (m_videos.currentIndex() >= 0)
      updateInfo();
  });
  for (int i = 0; i < m_videos.count(); ++i)
    videoInserted(i);
  updateEvents();
  currentChanged(m_videos.currentIndex());
}

ReferenceVideoPanel::~ReferenceVideoPanel() = default;

ReferenceVideo& ReferenceVideoPanel::video() const
{
  ReferenceVideo* current = m_videos.current();
  return current ? *current : *m_none;
}

VideoView& ReferenceVideoPanel::view() const
{
  const int current = m_videos.currentIndex();
  return current >= 0 ? *m_views[static_cast<std::size_t>(current)] : *m_noneView;
}

void ReferenceVideoPanel::videoInserted(int index)
{
  auto* view = new VideoView(m_videos.at(index), m_stack);
  m_stack->addWidget(view);
  m_views.insert(m_views.begin() + index, view);
  const QSignalBlocker blocker(m_choice);
  m_choice->insertItem(index, QString());
}

void ReferenceVideoPanel::videoAboutToBeRemoved(int index)
{
  delete m_views[static_cast<std::size_t>(index)];  // it refers to the video going
  m_views.erase(m_views.begin() + index);
  const QSignalBlocker blocker(m_choice);
  m_choice->removeItem(index);
}

void ReferenceVideoPanel::currentChanged(int index)
{
  m_stack->setCurrentWidget(&view());
  {
    const QSignalBlocker blocker(m_choice);
    m_choice->setCurrentIndex(index);
  }
  updateInfo();
}

void ReferenceVideoPanel::setCurrentIndex(int index)
{
  m_videos.setCurrentIndex(index);
}

QString ReferenceVideoPanel::openVideo(const QString& path)
{
  const QString error = m_videos.open(path);
  showStatusLine(*m_status, error, !error.isEmpty());
  return error;
}

void ReferenceVideoPanel::removeVideo(int index)
{
  m_videos.remove(index);
  showStatusLine(*m_status, QString(), false);
}

QString ReferenceVideoPanel::locateVideo(int index, const QString& path)
{
  const QString error = m_videos.locate(index, path);
  showStatusLine(*m_status, error, !error.isEmpty());
  return error;
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
  const bool any = m_videos.currentIndex() >= 0;
  m_offset->setEnabled(any);
  m_frame->setEnabled(open);
  m_remove->setEnabled(any);
  m_locate->setEnabled(any && !open);
  m_syncHere->setEnabled(open && shown.heldFrame().has_value());
  m_follow->setEnabled(open && shown.heldFrame().has_value());
  m_syncEvent->setEnabled(open && !m_events.empty());
  m_choice->setEnabled(m_videos.count() > 0);
  for (int i = 0; i < m_videos.count(); ++i) {
    const ReferenceVideo& each = m_videos.at(i);
    const QString name = QFileInfo(each.path()).fileName();
    m_choice->setItemText(i, each.isOpen() ? name : tr("%1 (missing)").arg(name));
  }
  if (m_videos.count() == 0)
    m_choice->setPlaceholderText(tr("No reference video"));
  if (!open) {
    m_info->setText(any ? tr("%1 is not available").arg(QFileInfo(shown.path()).fileName())
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

void ReferenceVideoPanel::restored(int /*count*/, int missing, const QString& problem)
{
  updateEvents();
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
}

void ReferenceVideoPanel::openDialog()
{
  const QString path = openFileOfGroup(this, tr("Add reference video"), kGroup,
                                       tr("Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)"));
  if (!path.isEmpty())
    (void)openVideo(path);
}

void ReferenceVideoPanel::locateDialog()
{
  const int current = m_videos.currentIndex();
  if (current < 0)
    return;
  const QString missing = video().path();
  QString folder = QFileInfo(missing).absolutePath();
  if (!QFileInfo(folder).isDir())
    folder = m_document.filePath().isEmpty() ? rememberedFolder(kGroup) : QFileInfo(m_document.filePath()).absolutePath();
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Locate %1").arg(QFileInfo(missing).fileName()), folder,
      tr("Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)"));
  if (path.isEmpty())
    return;  // declined: the video stays linked as it was
  rememberFolder(kGroup, path);
  (void)locateVideo(current, path);
}

} // namespace mocap::ui
