#include "dialogs/export_dialog.h"

#include "document/job_runner.h"
#include "document/remembered_folder.h"
#include "document/session_option.h"
#include "document/take_document.h"

#include "mocap/io/take_io.h"
#include "mocap/model/take_slice.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStringList>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("export/");  // the folder is "export/folder"
constexpr double kDefaultReduceMm = 0.1;
constexpr int kTakeUnits = -1;  // the units combo's "as the take" entry

/// The dialog's remembered choices, typed ("export/…").
struct ExportSettings
{
  SessionOption<int> format{kGroup + QStringLiteral("format"), 0};
  SessionOption<int> fbxUp{kGroup + QStringLiteral("fbxUp"), static_cast<int>(FbxUpAxis::Z)};
  SessionOption<bool> fbxReduce{kGroup + QStringLiteral("fbxReduce"), false};
  SessionOption<double> fbxReduceMm{kGroup + QStringLiteral("fbxReduceMm"), kDefaultReduceMm};
  /// BVH and FBX: the LengthUnit the markers are written in, or -1 for the take's own.
  SessionOption<int> markerUnits{kGroup + QStringLiteral("markerUnits"), kTakeUnits};
};

// The output file's extension for `format`; an OBJ sequence is a folder, which has none.
QString extensionOf(AnimationFormat format)
{
  switch (format) {
  case AnimationFormat::Bvh: return QStringLiteral(".bvh");
  case AnimationFormat::Fbx: return QStringLiteral(".fbx");
  case AnimationFormat::ObjPlusPc2: return QStringLiteral(".pc2");
  case AnimationFormat::ObjSequence: break;
  }
  return {};
}

// `path` with the extension `format` needs, keeping its folder and base name.
QString pathForFormat(const QString& path, AnimationFormat format)
{
  const QFileInfo info(path);
  const QString suffix = info.suffix().toLower();
  const bool known = suffix == QStringLiteral("bvh") || suffix == QStringLiteral("pc2") || suffix == QStringLiteral("fbx");
  const QString base = known ? info.completeBaseName() : info.fileName();
  return QDir(info.path()).filePath(base + extensionOf(format));
}

bool meshFormat(AnimationFormat format)
{
  return !markerFormat(format);
}

int clampToInt(qint64 value)
{
  return static_cast<int>(std::clamp<qint64>(value, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

} // namespace

ExportDialog::ExportDialog(const TakeDocument& document, QWidget* parent)
    : QDialog(parent), m_document(document), m_jobs(new JobRunner(this))
{
  setWindowTitle(tr("Export Animation"));
  buildLayout();
  connect(m_jobs, &JobRunner::progressed, this, &ExportDialog::showProgress);
  connect(m_jobs, &JobRunner::cancelled, this, [this] { showStatus(tr("Cancelling…"), false); });
  restoreSettings();
}

ExportDialog::~ExportDialog() = default;  // the runner cancels the job (it holds its own copies) and awaits it

void ExportDialog::buildLayout()
{
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  m_format = new QComboBox(this);
  m_format->addItem(tr("BVH of the markers (.bvh)"), static_cast<int>(AnimationFormat::Bvh));
  m_format->addItem(tr("FBX of the markers as animated nulls (.fbx)"), static_cast<int>(AnimationFormat::Fbx));
  m_format->addItem(tr("OBJ sequence of the deformed mesh (folder)"), static_cast<int>(AnimationFormat::ObjSequence));
  m_format->addItem(tr("OBJ + PC2 point cache of the deformed mesh (.pc2)"),
                    static_cast<int>(AnimationFormat::ObjPlusPc2));
  form->addRow(tr("&Format:"), m_format);
  auto* fbxLabel = new QLabel(tr("FB&X:"), this);
  form->addRow(fbxLabel, buildFbxRow());
  fbxLabel->setBuddy(m_up);
  m_units = new QComboBox(this);
  m_units->setToolTip(tr("The units of the markers' positions in the file (as mocap convert --units): Maya and "
                         "MotionBuilder work in centimetres, Blender, Unreal and Unity read the declared units"));
  auto* unitsLabel = new QLabel(tr("&Units:"), this);
  unitsLabel->setBuddy(m_units);
  form->addRow(unitsLabel, m_units);

  auto* pathRow = new QHBoxLayout;
  m_path = new QLineEdit(this);
  m_browse = new QPushButton(tr("&Browse…"), this);
  pathRow->addWidget(m_path, 1);
  pathRow->addWidget(m_browse);
  auto* outputLabel = new QLabel(tr("&Output:"), this);  // a row of a layout gets no buddy by itself
  outputLabel->setBuddy(m_path);
  form->addRow(outputLabel, pathRow);

  m_range = new QComboBox(this);
  m_range->setObjectName(QStringLiteral("frameRangeChoice"));
  auto* rangeLabel = new QLabel(tr("R&ange:"), this);
  rangeLabel->setBuddy(m_range);
  form->addRow(rangeLabel, m_range);
  auto* rangeRow = new QHBoxLayout;
  m_first = new QSpinBox(this);
  m_last = new QSpinBox(this);
  rangeRow->addWidget(m_first);
  rangeRow->addWidget(new QLabel(tr("to"), this));
  rangeRow->addWidget(m_last);
  rangeRow->addStretch();
  auto* framesLabel = new QLabel(tr("F&rames:"), this);
  framesLabel->setBuddy(m_first);
  form->addRow(framesLabel, rangeRow);
  layout->addLayout(form);

  m_progressBar = new QProgressBar(this);
  m_progressBar->setRange(0, 1000);
  m_progressBar->setValue(0);
  layout->addWidget(m_progressBar);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_status);

  auto* buttons = new QHBoxLayout;
  m_export = new QPushButton(tr("&Export"), this);
  m_export->setDefault(true);
  m_cancel = new QPushButton(tr("Cancel"), this);
  buttons->addStretch();
  buttons->addWidget(m_export);
  buttons->addWidget(m_cancel);
  layout->addLayout(buttons);

  connect(m_format, qOverload<int>(&QComboBox::currentIndexChanged), this, &ExportDialog::onFormatChanged);
  connect(m_range, qOverload<int>(&QComboBox::currentIndexChanged), this, &ExportDialog::onRangeChoiceChanged);
  connect(m_first, &QSpinBox::valueChanged, this, &ExportDialog::onFramesEdited);
  connect(m_last, &QSpinBox::valueChanged, this, &ExportDialog::onFramesEdited);
  connect(m_browse, &QPushButton::clicked, this, &ExportDialog::browse);
  connect(m_export, &QPushButton::clicked, this, &ExportDialog::startExport);
  connect(m_cancel, &QPushButton::clicked, this, &ExportDialog::reject);
  setMeshSource({}, {}, {});  // disables the mesh formats until a caller provides a mesh
  resize(560, 220);
}

QLayout* ExportDialog::buildFbxRow()
{
  auto* row = new QHBoxLayout;
  m_up = new QComboBox(this);
  m_up->addItem(tr("Z up"), static_cast<int>(FbxUpAxis::Z));
  m_up->addItem(tr("Y up"), static_cast<int>(FbxUpAxis::Y));
  m_up->setToolTip(tr("The take's up axis, declared in the file so the importer turns the scene upright"));
  m_reduce = new QCheckBox(tr("Keep the fewest keys within"), this);
  m_reduce->setToolTip(tr("Each marker keeps the fewest keys whose linear interpolation stays within this "
                          "distance of every frame (as mocap convert --reduce); otherwise every frame is a key"));
  m_reduceMm = new QDoubleSpinBox(this);
  m_reduceMm->setDecimals(3);
  m_reduceMm->setRange(0.0, 1000.0);
  m_reduceMm->setSingleStep(0.05);
  m_reduceMm->setSuffix(tr(" mm"));
  row->addWidget(m_up);
  row->addWidget(m_reduce);
  row->addWidget(m_reduceMm);
  row->addStretch();
  connect(m_reduce, &QCheckBox::toggled, this, &ExportDialog::onFormatChanged);
  return row;
}

void ExportDialog::fillUnits(LengthUnit takeUnits)
{
  const auto name = [](LengthUnit unit) {
    const std::string_view text = unitName(unit);
    return QString::fromUtf8(text.data(), static_cast<int>(text.size()));
  };
  m_units->clear();
  m_units->addItem(tr("As the take (%1)").arg(name(takeUnits)), kTakeUnits);
  for (const LengthUnit unit : {LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre})
    m_units->addItem(name(unit), static_cast<int>(unit));
}

void ExportDialog::setMarkerUnits(std::optional<LengthUnit> units)
{
  m_units->setCurrentIndex(std::max(0, m_units->findData(units ? static_cast<int>(*units) : kTakeUnits)));
}

void ExportDialog::setFbxOptions(FbxUpAxis up, std::optional<double> reduceMm)
{
  m_up->setCurrentIndex(m_up->findData(static_cast<int>(up)));
  m_reduce->setChecked(reduceMm.has_value());
  if (reduceMm)
    m_reduceMm->setValue(*reduceMm);
}

void ExportDialog::restoreSettings()
{
  const ExportSettings settings;
  const Take& take = m_document.take();
  const qint64 first = take.firstFrame();
  const qint64 last = first + std::max<Eigen::Index>(take.frameCount(), 1) - 1;
  for (QSpinBox* box : {m_first, m_last})
    box->setRange(clampToInt(first), clampToInt(last));
  // The whole take by default: a range once Shift-dragged on the curves is offered, not assumed.
  {
    const QSignalBlocker blocker(m_range);
    m_range->addItem(tr("Whole take (%1–%2)").arg(first).arg(last), static_cast<int>(RangeChoice::WholeTake));
    if (m_document.hasRange())
      m_range->addItem(tr("Selected range (%1–%2)")
                           .arg(first + m_document.rangeFirst())
                           .arg(first + m_document.rangeLast()),
                       static_cast<int>(RangeChoice::SelectedRange));
    m_range->addItem(tr("Custom"), static_cast<int>(RangeChoice::Custom));
  }
  setRangeChoice(RangeChoice::WholeTake);

  const QFileInfo takeFile(m_document.filePath());
  QString folder = rememberedFolder(kGroup);
  if (folder.isEmpty())
    folder = takeFile.filePath().isEmpty() ? QDir::homePath() : takeFile.absolutePath();
  const QString base = takeFile.completeBaseName().isEmpty() ? QStringLiteral("take") : takeFile.completeBaseName();
  m_path->setText(QDir(folder).filePath(base));
  const int remembered = settings.format;
  const bool known = remembered >= 0 && remembered <= static_cast<int>(AnimationFormat::Fbx);
  m_rememberedFormat = known ? static_cast<AnimationFormat>(remembered) : AnimationFormat::Bvh;
  m_up->setCurrentIndex(std::max(0, m_up->findData(settings.fbxUp.get())));
  fillUnits(take.units());
  m_units->setCurrentIndex(std::max(0, m_units->findData(settings.markerUnits.get())));
  m_reduce->setChecked(settings.fbxReduce);
  m_reduceMm->setValue(settings.fbxReduceMm);
  setFormat(m_rememberedFormat);
  onFormatChanged();  // the extension, even when the format did not change
}

void ExportDialog::setMeshSource(Mesh mesh, MeshFrameSource source, const QString& name)
{
  m_mesh = std::move(mesh);
  m_source = std::move(source);
  m_meshName = name.isEmpty() ? QStringLiteral("mesh") : name;
  auto* model = qobject_cast<QStandardItemModel*>(m_format->model());
  const bool available = static_cast<bool>(m_source) && m_mesh.vertexCount() > 0;
  for (const AnimationFormat format : {AnimationFormat::ObjSequence, AnimationFormat::ObjPlusPc2}) {
    QStandardItem* item = model->item(m_format->findData(static_cast<int>(format)));
    item->setEnabled(available);
    item->setToolTip(available ? QString() : tr("Load a face mesh first: these formats export the deformed mesh."));
  }
  if (!available && meshFormat(format()))
    setFormat(markerFormat(m_rememberedFormat) ? m_rememberedFormat : AnimationFormat::Bvh);
  else if (available)
    setFormat(m_rememberedFormat);
}

AnimationFormat ExportDialog::format() const
{
  return static_cast<AnimationFormat>(m_format->currentData().toInt());
}

void ExportDialog::setFormat(AnimationFormat format)
{
  const int index = m_format->findData(static_cast<int>(format));
  const auto* model = qobject_cast<QStandardItemModel*>(m_format->model());
  if (index >= 0 && model->item(index)->isEnabled())
    m_format->setCurrentIndex(index);
}

QString ExportDialog::outputPath() const
{
  return m_path->text();
}

void ExportDialog::setOutputPath(const QString& path)
{
  m_path->setText(path);
}

void ExportDialog::setFrameRange(qint64 first, qint64 last)
{
  {
    const QSignalBlocker blockFirst(m_first);
    const QSignalBlocker blockLast(m_last);
    m_first->setValue(clampToInt(first));
    m_last->setValue(clampToInt(last));
  }
  onFramesEdited();
}

qint64 ExportDialog::firstFrame() const
{
  return m_first->value();
}

qint64 ExportDialog::lastFrame() const
{
  return m_last->value();
}

ExportDialog::RangeChoice ExportDialog::rangeChoice() const
{
  return static_cast<RangeChoice>(m_range->currentData().toInt());
}

void ExportDialog::setRangeChoice(RangeChoice choice)
{
  const int index = m_range->findData(static_cast<int>(choice));
  if (index < 0)
    return;  // no selected range to offer
  if (index == m_range->currentIndex())
    onRangeChoiceChanged();
  else
    m_range->setCurrentIndex(index);
}

void ExportDialog::onRangeChoiceChanged()
{
  const Take& take = m_document.take();
  const qint64 first = take.firstFrame();
  const QSignalBlocker blockFirst(m_first);
  const QSignalBlocker blockLast(m_last);
  switch (rangeChoice()) {
  case RangeChoice::WholeTake:
    m_first->setValue(clampToInt(first));
    m_last->setValue(clampToInt(first + std::max<Eigen::Index>(take.frameCount(), 1) - 1));
    break;
  case RangeChoice::SelectedRange:
    m_first->setValue(clampToInt(first + m_document.rangeFirst()));
    m_last->setValue(clampToInt(first + m_document.rangeLast()));
    break;
  case RangeChoice::Custom:
    break;  // the frames as they are, for the user to type
  }
}

void ExportDialog::onFramesEdited()
{
  // Typed frames that are not the chosen range make it a custom one.
  const Take& take = m_document.take();
  const qint64 first = take.firstFrame();
  RangeChoice choice = RangeChoice::Custom;
  if (m_first->value() == first && m_last->value() == first + std::max<Eigen::Index>(take.frameCount(), 1) - 1)
    choice = RangeChoice::WholeTake;
  else if (m_document.hasRange() && m_first->value() == first + m_document.rangeFirst() &&
           m_last->value() == first + m_document.rangeLast())
    choice = RangeChoice::SelectedRange;
  const QSignalBlocker blocker(m_range);
  m_range->setCurrentIndex(std::max(0, m_range->findData(static_cast<int>(choice))));
}

bool ExportDialog::confirmReplacing(const AnimationExportJob& job)
{
  const std::vector<std::filesystem::path> replaced = filesReplacedBy(job);
  if (replaced.empty())
    return true;
  constexpr std::size_t kListed = 8;
  QStringList names;
  for (std::size_t i = 0; i < std::min(replaced.size(), kListed); ++i)
    names << QDir::toNativeSeparators(QString::fromStdString(replaced[i].string()));
  QString text = tr("Replace %n existing file(s)?", nullptr, static_cast<int>(replaced.size())) +
                 QStringLiteral("\n\n") + names.join(QLatin1Char('\n'));
  if (replaced.size() > kListed)
    text += QLatin1Char('\n') + tr("… and %n more", nullptr, static_cast<int>(replaced.size() - kListed));
  return QMessageBox::question(this, tr("Replace Files?"), text, QMessageBox::Yes | QMessageBox::No,
                               QMessageBox::No) == QMessageBox::Yes;
}

void ExportDialog::onFormatChanged()
{
  if (!m_path->text().isEmpty())
    m_path->setText(pathForFormat(m_path->text(), format()));
  const bool fbx = format() == AnimationFormat::Fbx;
  m_units->setEnabled(markerFormat(format()));
  m_up->setEnabled(fbx);
  m_reduce->setEnabled(fbx);
  m_reduceMm->setEnabled(fbx && m_reduce->isChecked());
}

void ExportDialog::browse()
{
  QString path;
  if (format() == AnimationFormat::ObjSequence)
    path = QFileDialog::getExistingDirectory(this, tr("Folder for the OBJ sequence"), m_path->text());
  else if (format() == AnimationFormat::Bvh)
    path = QFileDialog::getSaveFileName(this, tr("Export BVH"), m_path->text(), tr("BVH (*.bvh)"));
  else if (format() == AnimationFormat::Fbx)
    path = QFileDialog::getSaveFileName(this, tr("Export FBX"), m_path->text(), tr("FBX (*.fbx)"));
  else
    path = QFileDialog::getSaveFileName(this, tr("Export Point Cache"), m_path->text(), tr("PC2 point cache (*.pc2)"));
  if (!path.isEmpty())
    m_path->setText(format() == AnimationFormat::ObjSequence ? path : pathForFormat(path, format()));
}

QString ExportDialog::checkSettings() const
{
  if (!m_document.hasTake())
    return tr("Open a take first.");
  if (m_path->text().trimmed().isEmpty())
    return tr("Choose where to export.");
  if (meshFormat(format()) && !m_source)
    return tr("Load a face mesh first: this format exports the deformed mesh.");
  if (m_first->value() > m_last->value())
    return tr("The first frame (%1) is after the last (%2).").arg(m_first->value()).arg(m_last->value());
  const QFileInfo output(m_path->text());
  if (!QFileInfo(output.absolutePath()).isDir())
    return tr("The folder %1 does not exist.").arg(QDir::toNativeSeparators(output.absolutePath()));
  if (format() != AnimationFormat::ObjSequence && output.isDir())
    return tr("%1 is a folder; choose a file name.").arg(QDir::toNativeSeparators(output.filePath()));
  return {};
}

AnimationExportJob ExportDialog::makeJob() const
{
  const Take& take = m_document.take();
  AnimationExportJob job;
  job.format = format();
  job.output = m_path->text().trimmed().toStdString();
  job.begin = m_first->value() - take.firstFrame();
  job.end = m_last->value() - take.firstFrame() + 1;
  job.startFrame = static_cast<float>(m_first->value());
  if (markerFormat(job.format)) {
    job.markers = sliceFrames(take, job.begin, job.end);
    if (const int unit = m_units->currentData().toInt(); unit != kTakeUnits)
      job.markers.convertUnits(static_cast<LengthUnit>(unit));
    job.up = static_cast<FbxUpAxis>(m_up->currentData().toInt());
    if (m_reduce->isChecked())
      job.reduceMm = m_reduceMm->value();
  } else {
    job.mesh = m_mesh;
    job.source = m_source;
    job.meshName = m_meshName.toStdString();
  }
  return job;
}

bool ExportDialog::startExport()
{
  if (isRunning())
    return false;
  if (const QString problem = checkSettings(); !problem.isEmpty()) {
    showStatus(problem, true);
    return false;
  }
  AnimationExportJob job;
  try {
    job = makeJob();
  } catch (const std::exception& e) {  // e.g. the take changed under the range
    showStatus(QString::fromStdString(e.what()), true);
    return false;
  }
  if (!confirmReplacing(job)) {
    showStatus(tr("Not exported: the existing files are kept."), false);
    return false;
  }
  ExportSettings settings;
  const QFileInfo output(m_path->text().trimmed());
  rememberFolder(kGroup, output.filePath());
  settings.format = static_cast<int>(job.format);
  settings.fbxUp = m_up->currentData().toInt();
  settings.markerUnits = m_units->currentData().toInt();
  settings.fbxReduce = m_reduce->isChecked();
  settings.fbxReduceMm = m_reduceMm->value();
  m_rememberedFormat = job.format;

  m_total = job.frameCount();
  m_runningOutput = QDir::toNativeSeparators(output.absoluteFilePath());
  m_progressBar->setValue(0);
  m_runningText = tr("Exporting %n frame(s)…", nullptr, static_cast<int>(m_total));
  showStatus(m_runningText, false);
  setRunning(true);
  m_jobs->start([job = std::move(job)](const JobControl& control) { return runAnimationExport(job, control); },
                [this](const ExportOutcome& outcome) { onFinished(outcome); });
  return true;
}

void ExportDialog::cancelExport()
{
  m_jobs->cancel();  // the export removes what it wrote and ends Cancelled
}

void ExportDialog::reject()
{
  if (isRunning())
    cancelExport();
  else
    QDialog::reject();
}

bool ExportDialog::isRunning() const
{
  return m_jobs->running();
}

QString ExportDialog::statusText() const
{
  return m_status->text();
}

void ExportDialog::showProgress(double fraction, const QString& timeLeft)
{
  if (m_jobs->cancelling())
    return;  // "Cancelling…" stays
  m_progressBar->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
  showStatus(timeLeft.isEmpty() ? m_runningText : m_runningText + QLatin1Char(' ') + timeLeft, false);
}

void ExportDialog::onFinished(const ExportOutcome& outcome)
{
  setRunning(false);
  switch (outcome.status) {
  case ExportStatus::Done:
  {
    QString done = tr("Exported %n frame(s) to %1.", nullptr, static_cast<int>(m_total)).arg(m_runningOutput);
    if (markerFormat(format()))
      if (const std::string leftOut = leftOutOnWriting(
              m_document.take(), format() == AnimationFormat::Fbx ? TakeFormat::Fbx : TakeFormat::Bvh);
          !leftOut.empty())
        done += QLatin1Char(' ') + tr("Note: %1.").arg(QString::fromStdString(leftOut));
    if (outcome.keys)
      done += QLatin1Char(' ') + keysText(*outcome.keys);
    m_progressBar->setValue(m_progressBar->maximum());
    showStatus(done, false);
    break;
  }
  case ExportStatus::Cancelled:
    m_progressBar->setValue(0);
    showStatus(tr("Export cancelled; nothing was written."), false);
    break;
  case ExportStatus::Failed:
    m_progressBar->setValue(0);
    showStatus(tr("Export failed: %1").arg(QString::fromStdString(outcome.error)), true);
    break;
  }
  emit exportFinished(outcome.status == ExportStatus::Done);
}

void ExportDialog::setRunning(bool running)
{
  for (QWidget* input : std::initializer_list<QWidget*>{m_format, m_path, m_browse, m_range, m_first, m_last, m_export})
    input->setEnabled(!running);
  if (!running)
    onFormatChanged();  // the FBX options as the format allows
  else
    for (QWidget* input : std::initializer_list<QWidget*>{m_up, m_units, m_reduce, m_reduceMm})
      input->setEnabled(false);
  m_cancel->setText(running ? tr("Cancel") : tr("Close"));
}

QString ExportDialog::keysText(const KeyCount& keys) const
{
  const QLocale locale;
  const double share =
      keys.before > 0 ? 100.0 * static_cast<double>(keys.after) / static_cast<double>(keys.before) : 100.0;
  return tr("Kept %1 of %2 keys (%3 %), largest error %4 mm (tolerance %5 mm).")
      .arg(locale.toString(static_cast<qlonglong>(keys.after)), locale.toString(static_cast<qlonglong>(keys.before)),
           locale.toString(share, 'f', 1), locale.toString(keys.maxError, 'f', 3),
           locale.toString(m_reduceMm->value(), 'f', 3));
}

void ExportDialog::showStatus(const QString& text, bool error)
{
  m_status->setText(text);
  m_status->setStyleSheet(error ? QStringLiteral("color: #c0392b;") : QString());
}

} // namespace mocap::ui
