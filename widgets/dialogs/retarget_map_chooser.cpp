#include "dialogs/retarget_map_chooser.h"

#include "mocap/io/shipped_retarget_maps.h"

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

#include <algorithm>

namespace mocap::ui {

namespace {

const QString kFileChoice = QStringLiteral("\x01file");  // the "Map file…" entry's data
const QString kFilePrefix = QStringLiteral("file:");     // a map file in settingValue()
const QString kLoadedChoice = QStringLiteral("\x01loaded");  // the caller's map in memory

} // namespace

RetargetMapChooser::RetargetMapChooser(const QString& noneText, QWidget* parent) : QWidget(parent)
{
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  m_choice = new QComboBox(this);
  m_choice->setObjectName(QStringLiteral("retargetMapChoice"));
  m_choice->addItem(noneText, QString());
  for (const std::string& name : shippedRetargetMapNames())
    m_choice->addItem(tr("%1 (shipped)").arg(QString::fromStdString(name)), QString::fromStdString(name));
  m_choice->addItem(tr("Map file…"), kFileChoice);
  m_choice->setToolTip(tr("Our shape names onto the target rig's channels, with gains, offsets and clamps "
                          "(as the command line's --map)"));
  m_file = new QLineEdit(this);
  m_file->setPlaceholderText(QStringLiteral("MAP.json"));
  m_browse = new QPushButton(tr("Br&owse…"), this);
  row->addWidget(m_choice);
  row->addWidget(m_file, 1);
  row->addWidget(m_browse);
  setFocusProxy(m_choice);
  connect(m_choice, qOverload<int>(&QComboBox::currentIndexChanged), this, &RetargetMapChooser::onChoice);
  connect(m_file, &QLineEdit::editingFinished, this, &RetargetMapChooser::changed);
  connect(m_browse, &QPushButton::clicked, this, &RetargetMapChooser::browse);
  onChoice();
}

std::optional<std::string> RetargetMapChooser::map() const
{
  const QString choice = m_choice->currentData().toString();
  if (choice.isEmpty() || choice == kLoadedChoice)
    return std::nullopt;
  return (choice == kFileChoice ? m_file->text().trimmed() : choice).toStdString();
}

void RetargetMapChooser::offerLoadedMap(const QString& text)
{
  int index = m_choice->findData(kLoadedChoice);
  if (index < 0) {
    index = 1;
    m_choice->insertItem(index, text, kLoadedChoice);
  } else {
    m_choice->setItemText(index, text);
  }
  if (index == m_choice->currentIndex())
    emit changed();
  else
    m_choice->setCurrentIndex(index);
}

bool RetargetMapChooser::loadedMapChosen() const
{
  return m_choice->currentData().toString() == kLoadedChoice;
}

void RetargetMapChooser::setMap(const QString& nameOrPath)
{
  const int shipped = nameOrPath.isEmpty() ? 0 : m_choice->findData(nameOrPath);
  if (shipped < 0)
    m_file->setText(nameOrPath);
  const int index = shipped >= 0 ? shipped : m_choice->findData(kFileChoice);
  if (index == m_choice->currentIndex())
    emit changed();
  else
    m_choice->setCurrentIndex(index);
}

bool RetargetMapChooser::lacksFile() const
{
  return m_choice->currentData().toString() == kFileChoice && m_file->text().trimmed().isEmpty();
}

QString RetargetMapChooser::settingValue() const
{
  const QString choice = m_choice->currentData().toString();
  return choice == kFileChoice ? kFilePrefix + m_file->text().trimmed() : choice;
}

void RetargetMapChooser::restoreSettingValue(const QString& value)
{
  if (value.startsWith(kFilePrefix)) {
    const QString file = value.mid(kFilePrefix.size());
    m_file->setText(file);
    m_choice->setCurrentIndex(m_choice->findData(kFileChoice));
  } else {
    m_choice->setCurrentIndex(std::max(0, m_choice->findData(value)));  // a map no longer shipped: none
  }
}

void RetargetMapChooser::onChoice()
{
  // The file's field only when a file is chosen: a narrow dock keeps room for the choice.
  const bool file = m_choice->currentData().toString() == kFileChoice;
  m_file->setVisible(file);
  m_browse->setVisible(file);
  emit changed();
}

void RetargetMapChooser::browse()
{
  const QString path = QFileDialog::getOpenFileName(this, tr("Retarget map"), m_file->text(),
                                                    tr("Retarget maps (*.json);;All files (*)"));
  if (path.isEmpty())
    return;
  m_file->setText(path);
  emit changed();
}

} // namespace mocap::ui
