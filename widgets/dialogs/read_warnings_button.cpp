#include "dialogs/read_warnings_button.h"

#include "dialogs/read_warnings_dialog.h"
#include "document/take_document.h"

#include <QFileInfo>

#include <string>
#include <vector>

namespace mocap::ui {

ReadWarningsButton::ReadWarningsButton(const TakeDocument& document, QWidget* parent)
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
  setVisible(!warnings.empty());
  setText(m_document.isIncomplete() ? tr("⚠ Incomplete: %n warning(s)", nullptr, static_cast<int>(warnings.size()))
                                    : tr("⚠ %n warning(s)", nullptr, static_cast<int>(warnings.size())));
  setToolTip(tr("Show every warning from reading the file"));
  if (askToAcknowledge)
    openList();
}

void ReadWarningsButton::openList()
{
  auto toList = [](const std::vector<std::string>& texts) {
    QStringList list;
    for (const std::string& text : texts)
      list << QString::fromStdString(text);
    return list;
  };
  ReadWarningsDialog dialog(QFileInfo(m_document.readFilePath()).fileName(), toList(m_document.loadWarnings()),
                            toList(m_document.dataLossWarnings()), window());
  dialog.exec();
}

} // namespace mocap::ui
