#include "panels/live_stream_panel.h"

#include "document/live_stream.h"
#include "document/session_option.h"
#include "document/studio_session.h"
#include "document/take_document.h"
#include "panels/status_line.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QShortcut>
#include <QSpinBox>
#include <QVBoxLayout>

namespace mocap::ui {

namespace {

constexpr int kPollMs = 500;

QString settingKey(const char* name)
{
  return QStringLiteral("liveStream/") + QLatin1String(name);
}

/// The dock's remembered settings, typed ("liveStream/…").
struct LiveStreamSettings
{
  static constexpr int kProtocolsPort = 0;  // not remembered: the protocol's default port

  SessionOption<QString> protocol{settingKey("protocol"), QStringLiteral("livelink")};
  SessionOption<QString> host{settingKey("host"), QStringLiteral("127.0.0.1")};
  SessionOption<int> port{settingKey("port"), kProtocolsPort};
  SessionOption<QString> subject{settingKey("subject"), QString::fromStdString(StreamSettings{}.subject)};
  SessionOption<bool> weights{settingKey("weights"), true};
  SessionOption<bool> markers{settingKey("markers"), false};
  SessionOption<bool> takeRate{settingKey("takeRate"), true};
  SessionOption<double> rate{settingKey("rate"), 60.0};
};

} // namespace

LiveStreamPanel::LiveStreamPanel(StudioSession& session, QWidget* parent)
    : QWidget(parent), m_stream(session.liveStream())
{
  buildUi();
  readSettings();
  m_poll.setInterval(kPollMs);
  connect(&m_poll, &QTimer::timeout, this, &LiveStreamPanel::showStats);
  connect(&m_stream, &LiveStream::started, this, &LiveStreamPanel::showRunning);
  connect(&m_stream, &LiveStream::stopped, this, &LiveStreamPanel::showRunning);
  connect(&m_stream, &LiveStream::failed, this, &LiveStreamPanel::showError);
  // While the take's rate is used, the rate box shows it (the start for a rate of one's own).
  TakeDocument& document = session.document();
  const auto showTakeRate = [this, &document] {
    if (m_takeRate->isChecked() && document.take().frameRate() > 0.0)
      m_rate->setValue(document.take().frameRate());
  };
  connect(&document, &TakeDocument::takeReset, this, showTakeRate);
  connect(m_takeRate, &QCheckBox::toggled, this, showTakeRate);
  showTakeRate();
  showRunning();
}

void LiveStreamPanel::buildUi()
{
  m_protocol = new QComboBox(this);
  m_protocol->addItem(tr("Live Link Face (Unreal, MetaHuman)"), QStringLiteral("livelink"));
  m_protocol->addItem(tr("VMC / OSC (VSeeFace, Blender add-ons)"), QStringLiteral("vmc"));
  m_protocol->setToolTip(tr("Live Link Face: the datagrams Epic's iPhone app sends, the 52 ARKit curves and the "
                            "head's turn.\nVMC: OSC bundles of the weights under ARKit names, and the markers as "
                            "trackers."));
  m_host = new QLineEdit(QStringLiteral("127.0.0.1"), this);
  m_host->setToolTip(tr("The computer the engine runs on: a name or an address"));
  m_port = new QSpinBox(this);
  m_port->setRange(1, 65535);
  m_subject = new QLineEdit(QString::fromStdString(StreamSettings{}.subject), this);
  m_subject->setToolTip(tr("The Live Link subject name the engine lists"));
  m_weights = new QCheckBox(tr("Solved weights"), this);
  m_weights->setToolTip(tr("The Blendshape Solve dock's weights on ARKit's 52 curves (ICT FaceKit names by the "
                           "shipped ict_to_arkit map)"));
  m_markers = new QCheckBox(tr("Markers (VMC)"), this);
  m_markers->setToolTip(tr("Each marker as a VMC tracker, in metres; a missing sample is not sent"));
  m_takeRate = new QCheckBox(tr("The take's rate"), this);
  m_rate = new QDoubleSpinBox(this);
  m_rate->setRange(1.0, kMaxStreamRate);
  m_rate->setSuffix(tr(" Hz"));
  m_rate->setToolTip(tr("Datagrams per second; each carries the frame shown at that moment"));
  m_start = new QPushButton(this);
  m_start->setToolTip(tr("Start or stop the stream (Ctrl+Shift+L)"));
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* form = new QFormLayout;
  form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  form->addRow(tr("Protocol"), m_protocol);
  form->addRow(tr("Host"), m_host);
  form->addRow(tr("Port"), m_port);
  form->addRow(tr("Subject"), m_subject);
  auto* what = new QHBoxLayout;
  what->addWidget(m_weights);
  what->addWidget(m_markers);
  what->addStretch();
  form->addRow(tr("Send"), what);
  auto* rate = new QHBoxLayout;
  rate->addWidget(m_takeRate);
  rate->addWidget(m_rate);
  rate->addStretch();
  form->addRow(tr("Rate"), rate);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(m_start);
  layout->addWidget(m_status);
  layout->addStretch();

  connect(m_protocol, &QComboBox::currentIndexChanged, this, &LiveStreamPanel::protocolChanged);
  connect(m_takeRate, &QCheckBox::toggled, m_rate, &QWidget::setDisabled);
  connect(m_start, &QPushButton::clicked, this, &LiveStreamPanel::toggle);
  auto* shortcut = new QShortcut(QKeySequence(tr("Ctrl+Shift+L")), this);
  shortcut->setContext(Qt::ApplicationShortcut);
  connect(shortcut, &QShortcut::activated, this, &LiveStreamPanel::toggle);
}

void LiveStreamPanel::readSettings()
{
  const LiveStreamSettings settings;
  m_protocol->setCurrentIndex(std::max(0, m_protocol->findData(settings.protocol.get())));
  m_host->setText(settings.host);
  const int defaultPort = defaultStreamPort(parseStreamProtocol(m_protocol->currentData().toString().toStdString())
                                                .value_or(StreamProtocol::LiveLink));
  m_port->setValue(settings.port == LiveStreamSettings::kProtocolsPort ? defaultPort : settings.port.get());
  m_subject->setText(settings.subject);
  m_weights->setChecked(settings.weights);
  m_markers->setChecked(settings.markers);
  m_takeRate->setChecked(settings.takeRate);
  m_rate->setValue(settings.rate);
  enableFieldsOfProtocol();
}

void LiveStreamPanel::writeSettings() const
{
  LiveStreamSettings settings;
  settings.protocol = m_protocol->currentData().toString();
  settings.host = m_host->text();
  settings.port = m_port->value();
  settings.subject = m_subject->text();
  settings.weights = m_weights->isChecked();
  settings.markers = m_markers->isChecked();
  settings.takeRate = m_takeRate->isChecked();
  settings.rate = m_rate->value();
}

void LiveStreamPanel::protocolChanged()
{
  const bool vmc = m_protocol->currentData() == QStringLiteral("vmc");
  // A port still at the other protocol's default follows the protocol; one the user typed stays.
  const int other = defaultStreamPort(vmc ? StreamProtocol::LiveLink : StreamProtocol::Vmc);
  if (m_port->value() == other)
    m_port->setValue(defaultStreamPort(vmc ? StreamProtocol::Vmc : StreamProtocol::LiveLink));
  enableFieldsOfProtocol();
}

void LiveStreamPanel::enableFieldsOfProtocol()
{
  const bool vmc = m_protocol->currentData() == QStringLiteral("vmc");
  m_markers->setEnabled(vmc);
  m_subject->setEnabled(!vmc);
  m_rate->setDisabled(m_takeRate->isChecked());
}

void LiveStreamPanel::setDestination(const QString& host, int port)
{
  m_host->setText(host);
  m_port->setValue(port);
}

void LiveStreamPanel::setProtocol(const QString& name)
{
  m_protocol->setCurrentIndex(std::max(0, m_protocol->findData(name)));
}

void LiveStreamPanel::setSendMarkers(bool markers)
{
  m_markers->setChecked(markers);
}

void LiveStreamPanel::toggle()
{
  if (m_stream.running() || m_stream.starting()) {
    m_stream.stop();
    showRunning();
    return;
  }
  writeSettings();
  StreamSettings settings;
  settings.protocol = parseStreamProtocol(m_protocol->currentData().toString().toStdString()).value();
  settings.destination = {m_host->text().trimmed().toStdString(), m_port->value()};
  settings.subject = m_subject->text().toStdString();
  settings.sendWeights = m_weights->isChecked();
  settings.sendMarkers = settings.protocol == StreamProtocol::Vmc && m_markers->isChecked();
  settings.rate = m_takeRate->isChecked() ? 0.0 : m_rate->value();
  m_hasError = false;
  showStatusLine(*m_status, tr("Connecting to %1…").arg(m_host->text()), false);
  m_start->setText(tr("Stop"));
  m_stream.start(settings);
}

void LiveStreamPanel::showRunning()
{
  const bool running = m_stream.running();
  m_start->setText(running ? tr("Stop") : tr("Start"));
  for (QWidget* field :
       std::initializer_list<QWidget*>{m_protocol, m_host, m_port, m_subject, m_weights, m_markers, m_takeRate, m_rate})
    field->setDisabled(running);
  if (!running)
    enableFieldsOfProtocol();
  if (running) {
    m_lastSent = 0;
    m_lastFailed = 0;
    m_sinceStats.start();
    m_poll.start();
    showStats();
  } else {
    m_poll.stop();
    if (!m_hasError)
      showStatusLine(*m_status, tr("Not streaming."), false);
  }
}

void LiveStreamPanel::showStats()
{
  const StreamStats stats = m_stream.stats();
  const double seconds = std::max(1e-3, static_cast<double>(m_sinceStats.restart()) / 1000.0);
  const double perSecond = static_cast<double>(stats.sent - m_lastSent) / seconds;
  m_lastSent = stats.sent;
  const StreamSettings& settings = m_stream.settings();
  QString text = tr("Streaming to %1: %2 datagrams/s, %3 sent")
                     .arg(QString::fromStdString(describeDestination(settings.destination)))
                     .arg(perSecond, 0, 'f', 0)
                     .arg(stats.sent);
  // Red only while refusals keep coming: one from a receiver that started late is history.
  const bool refusing = stats.failed > m_lastFailed;
  m_lastFailed = stats.failed;
  if (stats.failed > 0)
    text += tr(", %1 refused: %2").arg(stats.failed).arg(QString::fromStdString(stats.lastError));
  showStatusLine(*m_status, text, refusing);
}

void LiveStreamPanel::showError(const QString& message)
{
  m_hasError = true;
  showRunning();
  showStatusLine(*m_status, tr("Cannot stream: %1").arg(message), true);
}

QString LiveStreamPanel::statusText() const
{
  return m_status->text();
}

} // namespace mocap::ui
