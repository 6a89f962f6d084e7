#include "dialogs/review_export_dialog.h"

#include "document/remembered_folder.h"
#include "document/session_option.h"
#include "document/take_document.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("reviewExport/");  // the folder is "reviewExport/folder"

SessionOption<QSize> sizeOption()
{
  return {kGroup + QStringLiteral("size"), QSize(1280, 720)};
}

} // namespace

ReviewExportDialog::ReviewExportDialog(const TakeDocument& document, const QString& videoPath, double videoOffset,
                                       QWidget* parent)
    : QDialog(parent), m_document(document), m_videoPath(videoPath), m_videoOffset(videoOffset)
{
  setWindowTitle(tr("Export Review Video"));
  const Take& take = document.take();
  const QFileInfo takeFile(document.filePath());
  QString folder = rememberedFolder(kGroup);
  if (folder.isEmpty())
    folder = takeFile.absolutePath();
  const QString stem = takeFile.completeBaseName().isEmpty() ? QStringLiteral("take") : takeFile.completeBaseName();

  m_output = new QLineEdit(QDir(folder).filePath(stem + QStringLiteral(".review.mp4")), this);
  m_output->setMinimumWidth(m_output->fontMetrics().horizontalAdvance(QLatin1Char('x')) * 48);
  auto* browse = new QPushButton(tr("Browse…"), this);
  connect(browse, &QPushButton::clicked, this, &ReviewExportDialog::browse);
  auto* outputRow = new QHBoxLayout;
  outputRow->addWidget(m_output, 1);
  outputRow->addWidget(browse);

  m_size = new QComboBox(this);
  for (const QSize size : {QSize(1280, 720), QSize(1920, 1080), QSize(960, 540), QSize(640, 360)})
    m_size->addItem(tr("%1 × %2").arg(size.width()).arg(size.height()), size);
  m_size->setCurrentIndex(std::max(0, m_size->findData(sizeOption().get())));

  const auto first = static_cast<int>(take.firstFrame());
  const auto last = static_cast<int>(take.firstFrame() + take.frameCount() - 1);
  m_first = new QSpinBox(this);
  m_last = new QSpinBox(this);
  for (QSpinBox* box : {m_first, m_last})
    box->setRange(first, last);
  m_first->setValue(document.hasRange() ? first + static_cast<int>(document.rangeFirst()) : first);
  m_last->setValue(document.hasRange() ? first + static_cast<int>(document.rangeLast()) : last);
  auto* framesRow = new QHBoxLayout;
  framesRow->addWidget(m_first);
  framesRow->addWidget(new QLabel(tr("to"), this));
  framesRow->addWidget(m_last);

  m_withVideo = new QCheckBox(tr("Reference video beside the 3D view"), this);
  m_withVideo->setEnabled(!videoPath.isEmpty());
  m_withVideo->setChecked(!videoPath.isEmpty());
  if (videoPath.isEmpty())
    m_withVideo->setToolTip(tr("Add a reference video in the Reference Video dock to draw it beside the view."));

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
  connect(buttons, &QDialogButtonBox::accepted, this, &ReviewExportDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* form = new QFormLayout(this);
  form->addRow(tr("File:"), outputRow);
  form->addRow(tr("Size:"), m_size);
  form->addRow(tr("Frames:"), framesRow);
  form->addRow(m_withVideo);
  form->addRow(buttons);
}

void ReviewExportDialog::browse()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Export Review Video"), m_output->text(),
                                                    tr("MP4 video (*.mp4);;Motion JPEG AVI (*.avi)"));
  if (!path.isEmpty())
    m_output->setText(path);
}

void ReviewExportDialog::accept()
{
  const QFileInfo output(m_output->text());
  const QString suffix = output.suffix().toLower();
  if (suffix != QStringLiteral("mp4") && suffix != QStringLiteral("avi")) {
    QMessageBox::warning(this, windowTitle(), tr("Name the video .mp4 or .avi."));
    return;
  }
  if (m_first->value() > m_last->value()) {
    QMessageBox::warning(this, windowTitle(), tr("The first frame comes after the last."));
    return;
  }
  if (output.exists() &&
      QMessageBox::question(this, windowTitle(), tr("%1 exists. Replace it?").arg(output.fileName())) != QMessageBox::Yes)
    return;
  rememberFolder(kGroup, output.filePath());
  sizeOption().set(m_size->currentData().toSize());
  QDialog::accept();
}

ReviewRequest ReviewExportDialog::request() const
{
  ReviewRequest request;
  request.output = m_output->text().toStdString();
  request.size = m_size->currentData().toSize();
  const auto first = static_cast<int>(m_document.take().firstFrame());
  request.first = m_first->value() - first;
  request.last = m_last->value() - first;
  if (m_withVideo->isChecked()) {
    request.video = m_videoPath;
    request.videoOffset = m_videoOffset;
  }
  const QString stem = QFileInfo(m_document.filePath()).completeBaseName();
  request.takeName = (stem.isEmpty() ? tr("untitled take") : stem).toStdString();
  return request;
}

} // namespace mocap::ui
