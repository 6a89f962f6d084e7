#include "actions/cleaning_preset_actions.h"

#include "document/take_document.h"
#include "views/status_timeout.h"

#include "mocap/base/file_io.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QMessageBox>

#include <string>
#include <utility>
#include <vector>

namespace mocap::ui {

namespace {
/// "a, b, c" for a message.
QString joinLabels(const std::vector<std::string>& labels)
{
  QStringList list;
  for (const std::string& label : labels)
    list << QString::fromStdString(label);
  return list.join(QStringLiteral(", "));
}
} // namespace

CleaningPresetActions::CleaningPresetActions(TakeDocument& document, QWidget& dialogParent, CleanOptionsSource source,
                                             QObject* parent)
    : QObject(parent), m_document(document), m_dialogParent(dialogParent), m_source(std::move(source))
{
}

QString CleaningPresetActions::save(const QString& path, bool withHeadMarkers)
{
  CleanOptions options = m_source.current();
  if (withHeadMarkers)
    options.stabilizeLabels = m_document.referenceLabels();
  try {
    writeFileAtomically(path.toStdString(), cleanPresetJson(options));
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

void CleaningPresetActions::saveWithDialog()
{
  QFileDialog dialog(&m_dialogParent, tr("Save Cleaning Preset"), QFileInfo(m_document.filePath()).absolutePath(),
                     tr("Cleaning presets (*.json)"));
  dialog.setAcceptMode(QFileDialog::AcceptSave);
  dialog.setDefaultSuffix(QStringLiteral("json"));
  dialog.setOption(QFileDialog::DontUseNativeDialog);  // a native dialog takes no extra box
  auto* withHeadMarkers = new QCheckBox(tr("Include this take's head markers (%1)")
                                            .arg(m_document.referenceMarkers().empty()
                                                     ? tr("none chosen")
                                                     : joinLabels(m_document.referenceLabels())),
                                        &dialog);
  withHeadMarkers->setObjectName(QStringLiteral("includeHeadMarkers"));
  withHeadMarkers->setToolTip(tr("A preset carries cleaning options; head markers belong to a take. Include them "
                                 "only when every take the preset is for names its head markers the same way: "
                                 "a take without them then fails with that reason."));
  withHeadMarkers->setEnabled(!m_document.referenceMarkers().empty());
  if (auto* grid = qobject_cast<QGridLayout*>(dialog.layout()))
    grid->addWidget(withHeadMarkers, grid->rowCount(), 0, 1, -1);
  if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
    return;
  const QString path = dialog.selectedFiles().front();
  const QString error = save(path, withHeadMarkers->isChecked());
  if (!error.isEmpty())
    QMessageBox::warning(&m_dialogParent, tr("Save Cleaning Preset"), tr("The preset was not saved: %1").arg(error));
  else
    emit message(tr("Saved the cleaning preset %1").arg(path), kStatusMessageMs);
}

QString CleaningPresetActions::load(const QString& path)
{
  CleanOptions options;
  try {
    options = readCleanPreset(path.toStdString());
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
  const QStringList off = m_source.load(options);
  emit loaded();
  QString text = tr("Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply")
                     .arg(QFileInfo(path).fileName());
  if (!off.isEmpty())
    text += tr("; it turns off %1 (left as they were)").arg(off.join(QStringLiteral(", ")));
  if (!options.stabilizeLabels.empty())
    text += tr("; its head markers (%1) are not this take's: the take keeps its own").arg(joinLabels(options.stabilizeLabels));
  emit message(text, 2 * kStatusMessageMs);
  return {};
}

void CleaningPresetActions::loadWithDialog()
{
  const QString path = QFileDialog::getOpenFileName(&m_dialogParent, tr("Load Cleaning Preset"),
                                                    QFileInfo(m_document.filePath()).absolutePath(),
                                                    tr("Cleaning presets (*.json);;All files (*)"));
  if (path.isEmpty())
    return;
  if (const QString error = load(path); !error.isEmpty())
    QMessageBox::warning(&m_dialogParent, tr("Load Cleaning Preset"), tr("The preset was not loaded: %1").arg(error));
}

} // namespace mocap::ui
