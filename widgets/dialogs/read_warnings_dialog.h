#pragma once

#include <QDialog>
#include <QStringList>

class QLabel;
class QListWidget;
class QPushButton;

namespace mocap {
struct DataLossKinds;
}

namespace mocap::ui {

/// The kind of data loss in a few words, for titles and the status bar: "incomplete" (data is
/// missing), "wrong data" (samples are not what was captured) or both; empty for none.
[[nodiscard]] QString dataLossInWords(const DataLossKinds& kinds);

/// Every warning the reader gave for a file, listed in full. When some mean data is missing (a
/// truncated file) or wrong (coordinates that wrapped round, a misread layout), the dialog leads
/// with them in bold under a title saying which, and the user must confirm having read it: a take
/// that opened incomplete or with wrong samples is never shown as if it were sound. Findings not
/// yet acknowledged can be (Acknowledge: acknowledgeRequested(), then the dialog closes), so that
/// later reads of a saved copy no longer raise them; acknowledged ones are listed as such.
class ReadWarningsDialog final : public QDialog
{
  Q_OBJECT

public:
  /// `acknowledged`: the texts of `dataLoss` a person acknowledged already.
  ReadWarningsDialog(const QString& fileName, const QStringList& warnings, const QStringList& dataLoss,
                     const QStringList& acknowledged = {}, QWidget* parent = nullptr);

  [[nodiscard]] QListWidget* list() const { return m_list; }
  /// The heading above the list (what kind of problem the file has).
  [[nodiscard]] QString heading() const;
  /// Acknowledge, shown while a finding is not acknowledged; null when there is none.
  [[nodiscard]] QPushButton* acknowledgeButton() const { return m_acknowledge; }

signals:
  /// The user acknowledged the data loss listed (the dialog then closes).
  void acknowledgeRequested();

private:
  QListWidget* m_list = nullptr;
  QLabel* m_heading = nullptr;
  QPushButton* m_acknowledge = nullptr;
};

} // namespace mocap::ui
