#pragma once

#include <QDialog>
#include <QStringList>

class QListWidget;

namespace mocap::ui {

/// Every warning the reader gave for a file, listed in full. When some mean data is missing
/// (a truncated file), the dialog leads with them in bold under a title saying so, and the user
/// must acknowledge it: a take that opened incomplete is never shown as if it were whole.
class ReadWarningsDialog final : public QDialog
{
  Q_OBJECT

public:
  ReadWarningsDialog(const QString& fileName, const QStringList& warnings, const QStringList& dataLoss,
                     QWidget* parent = nullptr);

  [[nodiscard]] QListWidget* list() const { return m_list; }

private:
  QListWidget* m_list = nullptr;
};

} // namespace mocap::ui
