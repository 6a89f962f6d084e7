#include "dialogs/read_warnings_dialog.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

namespace mocap::ui {

ReadWarningsDialog::ReadWarningsDialog(const QString& fileName, const QStringList& warnings,
                                       const QStringList& dataLoss, QWidget* parent)
    : QDialog(parent)
{
  setObjectName(QStringLiteral("readWarningsDialog"));
  const bool incomplete = !dataLoss.isEmpty();
  setWindowTitle(incomplete ? tr("%1 is incomplete").arg(fileName) : tr("Warnings reading %1").arg(fileName));
  auto* layout = new QVBoxLayout(this);
  auto* heading = new QLabel(this);
  heading->setWordWrap(true);
  if (incomplete) {
    heading->setText(tr("<b>Data is missing from %1.</b> The take opened with what could be read; the rest is "
                        "not in it. Saving writes only what was read.")
                         .arg(fileName.toHtmlEscaped()));
  } else {
    heading->setText(tr("%n warning(s) while reading %1. The take opened; these are quirks of the file that "
                        "were tolerated.",
                        nullptr, static_cast<int>(warnings.size()))
                         .arg(fileName.toHtmlEscaped()));
  }
  layout->addWidget(heading);
  m_list = new QListWidget(this);
  m_list->setWordWrap(true);
  const QIcon lossIcon = style()->standardIcon(QStyle::SP_MessageBoxCritical);
  const QIcon warningIcon = style()->standardIcon(QStyle::SP_MessageBoxWarning);
  for (const QString& text : dataLoss) {
    auto* item = new QListWidgetItem(lossIcon, text, m_list);
    QFont bold = item->font();
    bold.setBold(true);
    item->setFont(bold);
  }
  for (const QString& text : warnings)
    if (!dataLoss.contains(text))
      new QListWidgetItem(warningIcon, text, m_list);
  layout->addWidget(m_list);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok, this);
  buttons->button(QDialogButtonBox::Ok)->setText(incomplete ? tr("I understand") : tr("Close"));
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  layout->addWidget(buttons);
  resize(640, 360);
}

} // namespace mocap::ui
