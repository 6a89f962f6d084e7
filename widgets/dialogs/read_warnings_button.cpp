#include "dialogs/read_warnings_button.h"

#include "commands/acknowledge_data_loss_command.h"
#include "dialogs/read_warnings_dialog.h"
#include "document/take_document.h"

#include "mocap/model/data_loss_record.h"

#include <QFileInfo>
#include <QUndoStack>

#include <string>
#include <vector>

namespace mocap::ui {

namespace {

QStringList toList(const std::vector<std::string>& texts)
{
  QStringList list;
  for (const std::string& text : texts)
    list << QString::fromStdString(text);
  return list;
}

/// The take's acknowledged findings in both words a read gives them: as found, and as carried.
QStringList acknowledgedTexts(const Take& take)
{
  QStringList texts;
  for (const DataLossRecord& record : dataLossRecords(take))
    if (record.acknowledged)
      texts << QString::fromStdString(record.finding) << QString::fromStdString(recordedFindingText(record));
  return texts;
}

} // namespace

ReadWarningsButton::ReadWarningsButton(TakeDocument& document, QWidget* parent)
    : QToolButton(parent), m_document(document)
{
  setObjectName(QStringLiteral("readWarningsButton"));
  setAutoRaise(true);
  hide();
  connect(this, &QToolButton::clicked, this, &ReadWarningsButton::openList);
}

void ReadWarningsButton::showWarnings(bool askToAcknowledge)
{
  const auto& warnings = m_document.loadWarnings();
  const int count = static_cast<int>(warnings.size());
  const DataLossKinds kinds = dataLossKinds(m_document.dataLossWarnings());
  setVisible(!warnings.empty());
  if (kinds.missing && kinds.wrong)
    setText(tr("⚠ Incomplete, wrong data: %n warning(s)", nullptr, count));
  else if (kinds.missing)
    setText(tr("⚠ Incomplete: %n warning(s)", nullptr, count));
  else if (kinds.wrong)
    setText(tr("⚠ Wrong data: %n warning(s)", nullptr, count));
  else
    setText(tr("⚠ %n warning(s)", nullptr, count));
  setToolTip(tr("Show every warning from reading the file"));
  if (askToAcknowledge)
    openList();
}

void ReadWarningsButton::openList()
{
  ReadWarningsDialog dialog(QFileInfo(m_document.readFilePath()).fileName(), toList(m_document.loadWarnings()),
                            toList(m_document.dataLossWarnings()), acknowledgedTexts(m_document.take()), window());
  connect(&dialog, &ReadWarningsDialog::acknowledgeRequested, this, [this] {
    if (QUndoCommand* command = makeAcknowledgeDataLoss(m_document))
      m_document.undoStack()->push(command);
  });
  dialog.exec();
}

} // namespace mocap::ui
