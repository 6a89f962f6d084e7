#include "dialogs/live_link_open_dialog.h"

#include "dialogs/retarget_map_chooser.h"
#include "document/remembered_folder.h"
#include "document/session_option.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace mocap::ui {

namespace {

const QString kGroup = QStringLiteral("liveLinkOpen/");  // the folder is "liveLinkOpen/folder"

/// The map chosen last (RetargetMapChooser::settingValue).
SessionOption<QString> mapOption()
{
  return {kGroup + QStringLiteral("map"), QString()};
}

} // namespace

LiveLinkOpenDialog::LiveLinkOpenDialog(QWidget* parent) : QDialog(parent)
{
  setWindowTitle(tr("Open Live Link Recording"));
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  auto* pathRow = new QHBoxLayout;
  m_path = new QLineEdit(this);
  m_path->setPlaceholderText(tr("The CSV the Live Link Face app recorded"));
  auto* browseButton = new QPushButton(tr("&Browse…"), this);
  pathRow->addWidget(m_path, 1);
  pathRow->addWidget(browseButton);
  auto* pathLabel = new QLabel(tr("&Recording:"), this);
  pathLabel->setBuddy(m_path);
  form->addRow(pathLabel, pathRow);
  m_map = new RetargetMapChooser(tr("By name (arkit_to_ict for ICT names)"), this);
  auto* mapLabel = new QLabel(tr("&Map onto the rig:"), this);
  mapLabel->setBuddy(m_map);
  form->addRow(mapLabel, m_map);
  layout->addLayout(form);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, this);
  layout->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &LiveLinkOpenDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(browseButton, &QPushButton::clicked, this, &LiveLinkOpenDialog::browse);
  m_map->restoreSettingValue(mapOption().get());
  resize(560, 120);
}

QString LiveLinkOpenDialog::recordingPath() const
{
  return m_path->text().trimmed();
}

void LiveLinkOpenDialog::setRecordingPath(const QString& path)
{
  m_path->setText(path);
}

std::optional<std::string> LiveLinkOpenDialog::map() const
{
  return m_map->map();
}

void LiveLinkOpenDialog::setMap(const QString& nameOrPath)
{
  m_map->setMap(nameOrPath);
}

void LiveLinkOpenDialog::accept()
{
  if (recordingPath().isEmpty() || m_map->lacksFile())
    return;
  rememberFolder(kGroup, recordingPath());
  mapOption().set(m_map->settingValue());
  QDialog::accept();
}

void LiveLinkOpenDialog::browse()
{
  QString folder = rememberedFolder(kGroup);
  if (folder.isEmpty())
    folder = QDir::homePath();
  const QString path = QFileDialog::getOpenFileName(this, tr("Open Live Link Recording"),
                                                    recordingPath().isEmpty() ? folder : recordingPath(),
                                                    tr("Live Link Face CSV (*.csv);;All files (*)"));
  if (!path.isEmpty())
    m_path->setText(path);
}

} // namespace mocap::ui
