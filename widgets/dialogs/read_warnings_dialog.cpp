#include "dialogs/read_warnings_dialog.h"

#include "mocap/model/data_loss_record.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

#include <string>
#include <vector>

namespace mocap::ui {

namespace {

DataLossKinds kindsOf(const QStringList& dataLoss)
{
  std::vector<std::string> findings;
  for (const QString& text : dataLoss)
    findings.push_back(text.toStdString());
  return dataLossKinds(findings);
}

QString titleFor(const QString& fileName, const DataLossKinds& kinds)
{
  if (kinds.missing && kinds.wrong)
    return ReadWarningsDialog::tr("%1 is incomplete and has wrong data").arg(fileName);
  if (kinds.missing)
    return ReadWarningsDialog::tr("%1 is incomplete").arg(fileName);
  if (kinds.wrong)
    return ReadWarningsDialog::tr("%1 has wrong data").arg(fileName);
  return ReadWarningsDialog::tr("Warnings reading %1").arg(fileName);
}

/// What the file's problem is, in the dialog's first words: missing, wrong or both.
QString headingFor(const QString& fileName, const DataLossKinds& kinds, int warnings)
{
  const QString file = fileName.toHtmlEscaped();
  if (kinds.missing && kinds.wrong)
    return ReadWarningsDialog::tr("<b>Data is missing from %1, and some that was read is wrong.</b> The take opened "
                                  "with what could be read; the rest is not in it, and the samples named below are "
                                  "not what was captured. Saving writes only what was read, with these findings.")
        .arg(file);
  if (kinds.missing)
    return ReadWarningsDialog::tr("<b>Data is missing from %1.</b> The take opened with what could be read; the rest "
                                  "is not in it. Saving writes only what was read.")
        .arg(file);
  if (kinds.wrong)
    return ReadWarningsDialog::tr("<b>Some data in %1 is wrong.</b> The take opened with every sample as it was "
                                  "read, but the samples named below are not what was captured. Saving keeps them "
                                  "as they are, with this finding.")
        .arg(file);
  return ReadWarningsDialog::tr("%n warning(s) while reading %1. The take opened; these are quirks of the file "
                                "that were tolerated.",
                                nullptr, warnings)
      .arg(file);
}

} // namespace

QString dataLossInWords(const DataLossKinds& kinds)
{
  if (kinds.missing && kinds.wrong)
    return ReadWarningsDialog::tr("incomplete, wrong data");
  if (kinds.missing)
    return ReadWarningsDialog::tr("incomplete");
  if (kinds.wrong)
    return ReadWarningsDialog::tr("wrong data");
  return {};
}

ReadWarningsDialog::ReadWarningsDialog(const QString& fileName, const QStringList& warnings,
                                       const QStringList& dataLoss, const QStringList& acknowledged, QWidget* parent)
    : QDialog(parent)
{
  setObjectName(QStringLiteral("readWarningsDialog"));
  const DataLossKinds kinds = kindsOf(dataLoss);
  const int warningCount = static_cast<int>(warnings.size());
  setWindowTitle(titleFor(fileName, kinds));
  auto* layout = new QVBoxLayout(this);
  m_heading = new QLabel(headingFor(fileName, kinds, warningCount), this);
  m_heading->setWordWrap(true);
  layout->addWidget(m_heading);
  m_list = new QListWidget(this);
  m_list->setWordWrap(true);
  const QIcon lossIcon = style()->standardIcon(QStyle::SP_MessageBoxCritical);
  const QIcon acknowledgedIcon = style()->standardIcon(QStyle::SP_DialogApplyButton);
  const QIcon warningIcon = style()->standardIcon(QStyle::SP_MessageBoxWarning);
  bool open = false;  // a finding not acknowledged yet
  for (const QString& text : dataLoss) {
    const bool done = acknowledged.contains(text);
    open = open || !done;
    auto* item = new QListWidgetItem(done ? acknowledgedIcon : lossIcon,
                                     done ? tr("%1 (acknowledged)").arg(text) : text, m_list);
    QFont bold = item->font();
    bold.setBold(!done);
    item->setFont(bold);
  }
  for (const QString& text : warnings)
    if (!dataLoss.contains(text))
      new QListWidgetItem(warningIcon, text, m_list);
  layout->addWidget(m_list);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok, this);
  buttons->button(QDialogButtonBox::Ok)->setText(dataLoss.isEmpty() ? tr("Close") : tr("I understand"));
  if (open) {
    m_acknowledge = buttons->addButton(tr("Acknowledge"), QDialogButtonBox::AcceptRole);
    m_acknowledge->setObjectName(QStringLiteral("acknowledgeDataLoss"));
    m_acknowledge->setToolTip(tr("Record in the take's history that a person has seen these findings (undoable): "
                                 "they stay in the history and in mocap info, but reading a saved copy no longer "
                                 "raises them as warnings"));
    connect(m_acknowledge, &QPushButton::clicked, this, &ReadWarningsDialog::acknowledgeRequested);
  }
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  layout->addWidget(buttons);
  resize(640, 360);
}

QString ReadWarningsDialog::heading() const
{
  return m_heading->text();
}

} // namespace mocap::ui
