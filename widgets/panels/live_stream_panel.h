#pragma once

#include <QElapsedTimer>
#include <QString>
#include <QTimer>
#include <QWidget>

#include <cstdint>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace mocap::ui {

class LiveStream;
class StudioSession;

/// The Live Stream dock (View ▸ Live Stream): where the session's live stream goes (protocol —
/// Live Link Face or VMC —, host, port, Live Link subject name), what it sends (solved weights,
/// markers), at which rate (the take's, or another), Start/Stop (Ctrl+Shift+L), and while it runs
/// the datagrams per second, how many went out or were refused, and the last error. Settings are
/// remembered. The stream itself belongs to the session (LiveStream); this dock edits and shows it.
class LiveStreamPanel final : public QWidget
{
  Q_OBJECT

public:
  explicit LiveStreamPanel(StudioSession& session, QWidget* parent = nullptr);

  /// Start with the dock's settings, or Stop when running.
  void toggle();
  /// What the status line reads (tests, and the dock's tooltip).
  [[nodiscard]] QString statusText() const;
  /// Sets the destination fields (tests and scripts): host and port.
  void setDestination(const QString& host, int port);
  void setProtocol(const QString& name);  ///< "livelink" or "vmc"
  void setSendMarkers(bool markers);

private:
  void buildUi();
  void readSettings();
  void writeSettings() const;
  void protocolChanged();
  /// Markers only over VMC, a subject only for Live Link, a rate of one's own only when asked.
  void enableFieldsOfProtocol();
  void showRunning();
  void showStats();
  void showError(const QString& message);

  LiveStream& m_stream;
  QComboBox* m_protocol = nullptr;
  QLineEdit* m_host = nullptr;
  QSpinBox* m_port = nullptr;
  QLineEdit* m_subject = nullptr;
  QCheckBox* m_weights = nullptr;
  QCheckBox* m_markers = nullptr;
  QCheckBox* m_takeRate = nullptr;
  QDoubleSpinBox* m_rate = nullptr;
  QPushButton* m_start = nullptr;
  QLabel* m_status = nullptr;
  QTimer m_poll;  // refreshes the counts while the stream runs
  QElapsedTimer m_sinceStats;
  std::int64_t m_lastSent = 0;
  std::int64_t m_lastFailed = 0;
  bool m_hasError = false;
};

} // namespace mocap::ui
