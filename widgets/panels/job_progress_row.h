#pragma once

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace mocap::ui {

class JobRunner;

/// The progress bar, time-left estimate and Cancel button of a JobRunner's job: shown while it
/// runs (busy until the first progress report), hidden when it ends or is cancelled; Cancel (Esc
/// where the owner binds it) stops the computation itself.
class JobProgressRow final : public QWidget
{
  Q_OBJECT

public:
  explicit JobProgressRow(JobRunner& runner, QWidget* parent = nullptr);

  [[nodiscard]] QPushButton* cancelButton() const { return m_cancelButton; }
  /// The text of the time estimate ("about 12 s left"); empty until one is known. For tests.
  [[nodiscard]] QString estimateText() const;

private:
  void begin();
  void showProgress(double fraction, const QString& timeLeft);
  void finish();

  QProgressBar* m_bar = nullptr;
  QLabel* m_estimate = nullptr;
  QPushButton* m_cancelButton = nullptr;
};

} // namespace mocap::ui
