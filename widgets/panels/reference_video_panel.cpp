#include "panels/reference_video_panel.h"

#include "document/reference_video.h"
#include "document/take_document.h"
#include "panels/panel_folder.h"
#include "panels/status_line.h"
#include "views/video_view.h"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace mocap::ui {

namespace {
const QString kGroup = QStringLiteral("referenceVideo/");
} // namespace

ReferenceVideoPanel::ReferenceVideoPanel(TakeDocument& document, QWidget* parent)
    : QWidget(parent), m_document(document), m_video(new ReferenceVideo(document, this))
{
  auto* layout = new QVBoxLayout(this);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton(tr("Add Reference Video…"), this);
  add->setToolTip(tr("A video of the session (MP4, MOV, AVI, MKV) shown at the take's current frame"));
  connect(add, &QPushButton::clicked, this, &ReferenceVideoPanel::openDialog);
  m_remove = new QPushButton(tr("Remove"), this);
  connect(m_remove, &QPushButton::clicked, m_video, &ReferenceVideo::close);
  buttons->addWidget(add);
  buttons->addWidget(m_remove);
  buttons->addStretch();
  layout->addLayout(buttons);
  m_info = new QLabel(this);
  m_info->setWordWrap(true);
  layout->addWidget(m_info);

  auto* sync = new QHBoxLayout;
  sync->addWidget(new QLabel(tr("Offset:"), this));
  m_offset = new QDoubleSpinBox(this);
  m_offset->setRange(-86400.0, 86400.0);
  m_offset->setDecimals(3);
  m_offset->setSingleStep(0.001);
  m_offset->setSuffix(tr(" s"));
  m_offset->setToolTip(tr("Video time at the take's first frame: video time = (take frame − first) / take rate + offset"));
  connect(m_offset, &QDoubleSpinBox::valueChanged, m_video, &ReferenceVideo::setOffset);
  sync->addWidget(m_offset, 1);
  auto* earlier = new QPushButton(tr("−1 frame"), this);
  earlier->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Comma));
  earlier->setToolTip(tr("Move the video one of its frames earlier (Alt+,)"));
  connect(earlier, &QPushButton::clicked, this, [this] { m_video->nudge(-1); });
  auto* later = new QPushButton(tr("+1 frame"), this);
  later->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Period));
  later->setToolTip(tr("Move the video one of its frames later (Alt+.)"));
  connect(later, &QPushButton::clicked, this, [this] { m_video->nudge(1); });
  sync->addWidget(earlier);
  sync->addWidget(later);
  layout->addLayout(sync);

  m_view = new VideoView(*m_video, this);
  layout->addWidget(m_view, 1);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  layout->addWidget(m_status);
  connect(m_video, &ReferenceVideo::changed, this, &ReferenceVideoPanel::updateInfo);
  updateInfo();
}

ReferenceVideoPanel::~ReferenceVideoPanel() = default;

QString ReferenceVideoPanel::openVideo(const QString& path)
{
  const QString error = m_video->open(path);
  if (!error.isEmpty()) {
    showStatusLine(*m_status, tr("Cannot show %1: %2").arg(QFileInfo(path).fileName(), error), true);
    return m_status->text();
  }
  showStatusLine(*m_status, QString(), false);
  return {};
}

QString ReferenceVideoPanel::statusText() const
{
  return m_status->text();
}

void ReferenceVideoPanel::updateInfo()
{
  const QSignalBlocker blocker(m_offset);
  m_offset->setValue(m_video->offset());
  m_remove->setEnabled(m_video->isOpen());
  if (!m_video->isOpen()) {
    m_info->setText(tr("No reference video"));
    return;
  }
  const VideoInfo& info = m_video->info();
  m_info->setText(tr("%1: %2×%3, %4 fps, %5 frames (%6 s), %7")
                      .arg(QFileInfo(m_video->path()).fileName())
                      .arg(info.width)
                      .arg(info.height)
                      .arg(info.rate, 0, 'g', 5)
                      .arg(static_cast<qlonglong>(info.frames))
                      .arg(info.seconds(), 0, 'f', 2)
                      .arg(QString::fromStdString(info.codec)));
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

} // namespace mocap::ui
