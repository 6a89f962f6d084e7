#include "dialogs/rig_export_dialog.h"

#include "dialogs/retarget_map_chooser.h"
#include "document/remembered_folder.h"
#include "document/session_option.h"

#include "mocap/base/length_unit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <array>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("rigExport/");
constexpr double kDefaultTolerance = 0.01;                     // the 0.01 weight units

QString key(const char* name)
{
  return kGroup + QLatin1String(name);
}

/// The dialog's remembered choices, typed ("rigExport/…"; the folder is "rigExport/folder").
struct RigExportSettings
{
  SessionOption<int> format{key("format"), static_cast<int>(RigExportFormat::Fbx)};
  SessionOption<QString> map{key("map"), QString()};  // RetargetMapChooser::settingValue
  SessionOption<bool> reduce{key("reduce"), false};
  SessionOption<double> tolerance{key("tolerance"), kDefaultTolerance};
  SessionOption<int> up{key("up"), static_cast<int>(FbxUpAxis::Y)};
  SessionOption<int> units{key("units"), static_cast<int>(LengthUnit::Centimetre)};
};

QString extensionOf(RigExportFormat format)
{
  switch (format) {
  case RigExportFormat::Fbx: return QStringLiteral("fbx");
  case RigExportFormat::Glb: return QStringLiteral("glb");
  case RigExportFormat::WeightsCsv:
  case RigExportFormat::LiveLinkCsv: break;
  }
  return QStringLiteral("csv");
}

bool hasKeys(RigExportFormat format)
{
  return format == RigExportFormat::Fbx || format == RigExportFormat::Glb;
}

/// `path` with `format`'s extension in place of a known one (or after its name).
QString pathForFormat(const QString& path, RigExportFormat format)
{
  const QFileInfo info(path);
  static const std::array<QString, 3> known{QStringLiteral("fbx"), QStringLiteral("glb"), QStringLiteral("csv")};
  const bool replace = std::find(known.begin(), known.end(), info.suffix().toLower()) != known.end();
  const QString base = replace ? info.completeBaseName() : info.fileName();
  return QDir(info.path()).filePath(base + QLatin1Char('.') + extensionOf(format));
}

} // namespace

WeightOutput rigExportOptions(const RigExportSource& source)
{
  WeightOutput options;
  options.firstFrame = source.firstFrame;
  options.frameRate = source.frameRate;
  options.startSeconds = source.startSeconds;  // writeWeightOutput sets the FBX's from it
  options.headRotation = source.headRotation;
  return options;
}

RigExportDialog::RigExportDialog(RigExportSource source, QWidget* parent) : QDialog(parent), m_source(std::move(source))
{
  setWindowTitle(tr("Export Rig"));
  buildLayout();
  restoreSettings();
  chooseSectionMap();  // the map the user is working on in the session comes first
}

RigExportDialog::~RigExportDialog() = default;

void RigExportDialog::buildLayout()
{
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  m_format = new QComboBox(this);
  m_format->addItem(tr("FBX rig with animated blend shapes (.fbx)"), static_cast<int>(RigExportFormat::Fbx));
  m_format->addItem(tr("glTF rig with animated morph targets (.glb)"), static_cast<int>(RigExportFormat::Glb));
  m_format->addItem(tr("Weight curves, one column per shape (.csv)"), static_cast<int>(RigExportFormat::WeightsCsv));
  m_format->addItem(tr("Live Link Face CSV (.csv)"), static_cast<int>(RigExportFormat::LiveLinkCsv));
  form->addRow(tr("&Format:"), m_format);

  auto* pathRow = new QHBoxLayout;
  m_path = new QLineEdit(this);
  m_browse = new QPushButton(tr("&Browse…"), this);
  pathRow->addWidget(m_path, 1);
  pathRow->addWidget(m_browse);
  auto* outputLabel = new QLabel(tr("&Output:"), this);
  outputLabel->setBuddy(m_path);
  form->addRow(outputLabel, pathRow);

  m_map = new RetargetMapChooser(tr("None (the rig's own names)"), this);
  m_map->setToolTip(tr("For Live Link Face, none means the default map for the rig's names"));
  auto* mapLabel = new QLabel(tr("Retarget &map:"), this);
  mapLabel->setBuddy(m_map);
  form->addRow(mapLabel, m_map);
  auto* reduceLabel = new QLabel(tr("&Keys:"), this);
  form->addRow(reduceLabel, buildReductionRow());
  reduceLabel->setBuddy(m_reduce);

  auto* axesRow = new QHBoxLayout;
  m_up = new QComboBox(this);
  m_up->addItem(tr("Y up"), static_cast<int>(FbxUpAxis::Y));
  m_up->addItem(tr("Z up"), static_cast<int>(FbxUpAxis::Z));
  m_units = new QComboBox(this);
  for (const LengthUnit unit : {LengthUnit::Centimetre, LengthUnit::Millimetre})  // as --units cm|mm
    m_units->addItem(QString::fromUtf8(unitName(unit).data(), static_cast<int>(unitName(unit).size())),
                     static_cast<int>(unit));
  m_units->setToolTip(tr("The units the rig's coordinates are in, declared in the FBX's global settings"));
  axesRow->addWidget(m_up);
  axesRow->addWidget(m_units);
  axesRow->addStretch();
  auto* axesLabel = new QLabel(tr("FBX &axes:"), this);
  axesLabel->setBuddy(m_up);
  form->addRow(axesLabel, axesRow);
  layout->addLayout(form);

  m_status = new QLabel(this);
  m_status->setObjectName(QStringLiteral("rigExportStatus"));
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(m_status);

  auto* buttons = new QHBoxLayout;
  m_export = new QPushButton(tr("&Export"), this);
  m_export->setDefault(true);
  auto* close = new QPushButton(tr("Close"), this);
  buttons->addStretch();
  buttons->addWidget(m_export);
  buttons->addWidget(close);
  layout->addLayout(buttons);

  connect(m_format, qOverload<int>(&QComboBox::currentIndexChanged), this, &RigExportDialog::onFormatChanged);
  connect(m_browse, &QPushButton::clicked, this, &RigExportDialog::browse);
  connect(m_export, &QPushButton::clicked, this, [this] { (void)exportNow(); });
  connect(close, &QPushButton::clicked, this, &QDialog::reject);
  for (QComboBox* box : {m_up, m_units})
    connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, &RigExportDialog::onOptionsChanged);
  connect(m_map, &RetargetMapChooser::changed, this, &RigExportDialog::onOptionsChanged);
  connect(m_reduce, &QCheckBox::toggled, this, &RigExportDialog::onOptionsChanged);
  connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, &RigExportDialog::onOptionsChanged);
  resize(620, 260);
}

QLayout* RigExportDialog::buildReductionRow()
{
  auto* row = new QHBoxLayout;
  m_reduce = new QCheckBox(tr("Keep the fewest keys within"), this);
  m_reduce->setToolTip(tr("Each curve keeps the fewest keys whose linear interpolation stays within the "
                          "tolerance of every frame (as mocap solve --reduce); otherwise every frame is a key"));
  m_tolerance = new QDoubleSpinBox(this);
  m_tolerance->setDecimals(4);
  m_tolerance->setRange(0.0, 1.0);
  m_tolerance->setSingleStep(0.005);
  m_tolerance->setValue(kDefaultTolerance);
  row->addWidget(m_reduce);
  row->addWidget(m_tolerance);
  row->addWidget(new QLabel(tr("weight units"), this));
  row->addStretch();
  return row;
}

void RigExportDialog::restoreSettings()
{
  m_restoring = true;
  const RigExportSettings settings;
  QString folder = rememberedFolder(kGroup);
  if (folder.isEmpty())
    folder = QDir::homePath();
  const QString base = m_source.baseName.isEmpty() ? QStringLiteral("rig") : m_source.baseName;
  m_path->setText(QDir(folder).filePath(base));
  const int format = settings.format;
  m_format->setCurrentIndex(std::max(0, m_format->findData(format)));
  m_map->restoreSettingValue(settings.map);
  m_reduce->setChecked(settings.reduce);
  m_tolerance->setValue(settings.tolerance);
  m_up->setCurrentIndex(std::max(0, m_up->findData(settings.up.get())));
  m_units->setCurrentIndex(std::max(
      0, m_units->findData(settings.units.get())));
  m_restoring = false;
  onFormatChanged();  // the extension and which options apply
}

void RigExportDialog::writeSettings() const
{
  RigExportSettings settings;
  rememberFolder(kGroup, m_path->text().trimmed());
  settings.format = static_cast<int>(format());
  if (!m_map->loadedMapChosen())  // the section's map is chosen anew whenever there is one
    settings.map = m_map->settingValue();
  settings.reduce = m_reduce->isChecked();
  settings.tolerance = m_tolerance->value();
  settings.up = m_up->currentData().toInt();
  settings.units = m_units->currentData().toInt();
}

RigExportFormat RigExportDialog::format() const
{
  return static_cast<RigExportFormat>(m_format->currentData().toInt());
}

void RigExportDialog::setFormat(RigExportFormat format)
{
  const int index = m_format->findData(static_cast<int>(format));
  if (index == m_format->currentIndex())
    onFormatChanged();
  else
    m_format->setCurrentIndex(index);
}

QString RigExportDialog::outputPath() const
{
  return m_path->text().trimmed();
}

void RigExportDialog::setOutputPath(const QString& path)
{
  m_path->setText(path);
}

std::optional<std::string> RigExportDialog::map() const
{
  return m_map->map();
}

void RigExportDialog::setMap(const QString& nameOrPath)
{
  m_map->setMap(nameOrPath);
}

bool RigExportDialog::sectionMapChosen() const
{
  return m_map->loadedMapChosen();
}

void RigExportDialog::chooseSectionMap()
{
  if (!m_source.sectionMap)
    return;
  const QString name = QFileInfo(m_source.sectionMapName).fileName();
  m_map->offerLoadedMap(m_source.sectionMapEdited ? tr("Retarget section's: %1, gains edited").arg(name)
                                                  : tr("Retarget section's: %1").arg(name));
}

std::optional<double> RigExportDialog::reduction() const
{
  if (!m_reduce->isChecked() || !hasKeys(format()))
    return std::nullopt;
  return m_tolerance->value();
}

void RigExportDialog::setReduction(std::optional<double> tolerance)
{
  m_reduce->setChecked(tolerance.has_value());
  if (tolerance)
    m_tolerance->setValue(*tolerance);
}

void RigExportDialog::setUpAxis(FbxUpAxis up)
{
  m_up->setCurrentIndex(m_up->findData(static_cast<int>(up)));
}

void RigExportDialog::setUnits(LengthUnit unit)
{
  m_units->setCurrentIndex(m_units->findData(static_cast<int>(unit)));
}

WeightOutput RigExportDialog::options() const
{
  WeightOutput options = rigExportOptions(m_source);
  options.map = map();
  if (m_map->loadedMapChosen())
    options.loadedMap = m_source.sectionMap;
  options.liveLink = format() == RigExportFormat::LiveLinkCsv;
  options.fbx.up = static_cast<FbxUpAxis>(m_up->currentData().toInt());
  options.fbx.unit = static_cast<LengthUnit>(m_units->currentData().toInt());
  options.reduce = reduction();
  return options;
}

void RigExportDialog::onFormatChanged()
{
  const RigExportFormat chosen = format();
  if (!m_path->text().isEmpty())
    m_path->setText(pathForFormat(m_path->text(), chosen));
  for (QWidget* keyOption : std::initializer_list<QWidget*>{m_reduce, m_tolerance})
    keyOption->setEnabled(hasKeys(chosen));
  for (QWidget* axisOption : std::initializer_list<QWidget*>{m_up, m_units})
    axisOption->setEnabled(chosen == RigExportFormat::Fbx);
  onOptionsChanged();
}

void RigExportDialog::onOptionsChanged()
{
  m_tolerance->setEnabled(m_reduce->isEnabled() && m_reduce->isChecked());
  if (m_restoring)
    return;
  // The map is checked against the rig as it is chosen, before anything is written.
  const QString problem = checkSettings();
  showStatus(problem, !problem.isEmpty());
}

void RigExportDialog::browse()
{
  const RigExportFormat chosen = format();
  const QString filter = chosen == RigExportFormat::Fbx   ? tr("FBX (*.fbx)")
                         : chosen == RigExportFormat::Glb ? tr("glTF binary (*.glb)")
                                                          : tr("CSV (*.csv)");
  const QString path = QFileDialog::getSaveFileName(this, tr("Export Rig"), m_path->text(), filter);
  if (!path.isEmpty())
    m_path->setText(pathForFormat(path, chosen));
}

QString RigExportDialog::checkSettings() const
{
  if (!m_source.rig || m_source.weights.rows() == 0)
    return tr("Solve the take first.");
  if (m_map->lacksFile())
    return tr("Choose the map file.");
  try {
    checkWeightOutput(*m_source.rig, options());
  } catch (const std::exception& e) {
    return tr("The map cannot be used: %1").arg(QString::fromStdString(e.what()));
  }
  return {};
}

QString RigExportDialog::exportNow()
{
  QString problem = checkSettings();
  const QFileInfo output(outputPath());
  if (problem.isEmpty() && outputPath().isEmpty())
    problem = tr("Choose where to export.");
  else if (problem.isEmpty() && !QFileInfo(output.absolutePath()).isDir())
    problem = tr("The folder %1 does not exist.").arg(QDir::toNativeSeparators(output.absolutePath()));
  if (!problem.isEmpty()) {
    showStatus(problem, true);
    return problem;
  }
  if (output.exists() && isVisible() &&
      QMessageBox::question(this, tr("Replace File?"),
                            tr("Replace %1?").arg(QDir::toNativeSeparators(output.absoluteFilePath())),
                            QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes) {
    showStatus(tr("Not exported: the existing file is kept."), false);
    return {};
  }
  writeSettings();
  try {
    m_keys = writeWeightOutput(outputPath().toStdString(), *m_source.rig, m_source.weights, options());
  } catch (const std::exception& e) {
    m_keys.reset();
    const QString error = tr("Export failed: %1").arg(QString::fromStdString(e.what()));
    showStatus(error, true);
    return error;
  }
  showStatus(tr("Wrote %1.").arg(QDir::toNativeSeparators(output.absoluteFilePath())) + QLatin1Char(' ') +
                 keysText(m_keys),
             false);
  return {};
}

QString RigExportDialog::keysText(const std::optional<KeyCount>& keys) const
{
  if (!hasKeys(format()))
    return {};
  const QLocale locale;
  if (!keys)
    return tr("Every frame is a key: %1 frames.").arg(locale.toString(static_cast<qlonglong>(m_source.weights.rows())));
  const double share = keys->before > 0 ? 100.0 * static_cast<double>(keys->after) / static_cast<double>(keys->before)
                                        : 100.0;
  return tr("Kept %1 of %2 keys (%3 %), largest error %4 (tolerance %5).")
      .arg(locale.toString(static_cast<qlonglong>(keys->after)), locale.toString(static_cast<qlonglong>(keys->before)),
           locale.toString(share, 'f', 1), locale.toString(keys->maxError, 'f', 4),
           locale.toString(m_tolerance->value(), 'f', 4));
}

QString RigExportDialog::statusText() const
{
  return m_status->text();
}

void RigExportDialog::showStatus(const QString& text, bool error)
{
  m_status->setText(text);
  m_status->setStyleSheet(error ? QStringLiteral("color: #c0392b;") : QString());
}

} // namespace mocap::ui
