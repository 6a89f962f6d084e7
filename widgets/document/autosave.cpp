#include "document/autosave.h"

#include "document/job_runner.h"
#include "document/take_document.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include "mocap/base/file_io.h"
#include "mocap/io/take_io.h"

#include <algorithm>

namespace mocap::ui {

namespace {

constexpr int kDefaultIntervalMs = 60 * 1000;

// The recovery take's description: an INI file beside it (QSettings writes it atomically enough
// for a few keys, and a missing or broken one only loses the original's name).
QString descriptionPath(const QString& recoveryPath)
{
  return recoveryPath + QStringLiteral(".ini");
}

// The session's state beside the recovery take.
QString statePath(const QString& recoveryPath)
{
  return recoveryPath + QStringLiteral(".session");
}

// The recovery take and the session state beside it, on any thread; an error message or "".
// The state goes first, so the take on disk is never newer than the state beside it.
QString writeRecovery(const Take& take, const std::optional<SessionState>& state, const QString& path)
{
  try {
    if (state)
      writeFileAtomically(statePath(path).toStdString(), encodeSessionState(*state).toStdString());
    else
      QFile::remove(statePath(path));
    writeTake(take, path.toStdString());
    return {};
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

// The state a recovery file written before session states existed keeps in its description: the
// face mesh's file and its binding (as "session/mesh" and "session/binding"); none without a mesh.
std::optional<SessionState> stateInDescription(const QVariantMap& session)
{
  const QString mesh = session.value(QStringLiteral("mesh")).toString();
  if (mesh.isEmpty())
    return std::nullopt;
  SessionState state;
  state.meshPath = mesh;
  state.binding = session.value(QStringLiteral("binding")).toString().toStdString();
  return state;
}

// Whether the process that writes `fileName` (take-PID.c3d) still runs, so its file is not a
// leftover. Only Linux's /proc tells; elsewhere every other file counts as left over.
bool ownerIsRunning(const QString& fileName)
{
  bool ok = false;
  const qint64 pid = fileName.mid(5, fileName.size() - 9).toLongLong(&ok);
  return ok && QFileInfo::exists(QStringLiteral("/proc/1")) &&
         QFileInfo::exists(QStringLiteral("/proc/%1").arg(pid));
}

} // namespace

Autosave::Autosave(TakeDocument& document, QString folder, QObject* parent)
    : QObject(parent), m_document(document), m_folder(folder.isEmpty() ? defaultFolder() : std::move(folder)),
      m_write(new JobRunner(this))
{
  m_timer.setInterval(kDefaultIntervalMs);
  connect(&m_timer, &QTimer::timeout, this, &Autosave::saveInBackground);
  m_timer.start();
  // Saved, or a different take opened: the recovery copy is stale.
  connect(&document, &TakeDocument::modifiedChanged, this, [this](bool modified) {
    if (!modified)
      discard();
  });
  connect(&document, &TakeDocument::takeReset, this, &Autosave::discard);
}

Autosave::~Autosave()
{
  waitForWrite();
  discard();  // a clean shutdown leaves nothing to recover
}

void Autosave::setInterval(int milliseconds)
{
  m_timer.setInterval(std::max(milliseconds, 1000));
}

QString Autosave::defaultFolder()
{
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

QString Autosave::recoveryPath() const
{
  return m_folder + QStringLiteral("/take-%1.c3d").arg(QCoreApplication::applicationPid());
}

QString Autosave::prepare()
{
  if (!QDir().mkpath(m_folder))
    return tr("Cannot create the recovery folder %1").arg(m_folder);
  QSettings description(descriptionPath(recoveryPath()), QSettings::IniFormat);
  description.setValue(QStringLiteral("original"), m_document.filePath());
  description.setValue(QStringLiteral("written"), QDateTime::currentDateTime());
  description.remove(QStringLiteral("session"));
  if (m_session) {
    const QVariantMap session = m_session();
    for (auto it = session.begin(); it != session.end(); ++it)
      description.setValue(QStringLiteral("session/") + it.key(), it.value());
  }
  description.sync();
  return {};
}

QString Autosave::saveNow()
{
  waitForWrite();
  if (!m_document.hasTake() || !m_document.isModified())
    return {};
  if (const QString error = prepare(); !error.isEmpty())
    return error;
  return writeRecovery(m_document.take(), m_state ? std::optional<SessionState>(m_state()) : std::nullopt,
                       recoveryPath());
}

void Autosave::saveInBackground()
{
  if (m_write->running() || !m_document.hasTake() || !m_document.isModified())
    return;
  if (const QString error = prepare(); !error.isEmpty()) {
    emit failed(error);
    return;
  }
  // The copies are the only work on the UI thread (the samples, the session's weights); encoding
  // and the atomic writes happen on the worker.
  m_write->start(
      [take = m_document.take(), state = m_state ? std::optional<SessionState>(m_state()) : std::nullopt,
       path = recoveryPath()](const JobControl&) { return writeRecovery(take, state, path); },
      [this](const QString& error) { onWriteFinished(error); });
}

void Autosave::waitForWrite()
{
  m_write->wait();
}

void Autosave::onWriteFinished(const QString& error)
{
  if (!error.isEmpty())
    emit failed(error);
  else if (m_document.isModified())
    emit written();
  else
    discard();  // saved while the copy was being written: the copy is stale
}

void Autosave::discard()
{
  waitForWrite();
  QFile::remove(recoveryPath());
  QFile::remove(descriptionPath(recoveryPath()));
  QFile::remove(statePath(recoveryPath()));
}

std::vector<RecoveryFile> Autosave::leftovers(QString folder)
{
  if (folder.isEmpty())
    folder = defaultFolder();
  std::vector<RecoveryFile> files;
  const QString own = QStringLiteral("take-%1.c3d").arg(QCoreApplication::applicationPid());
  for (const QFileInfo& info : QDir(folder).entryInfoList({QStringLiteral("take-*.c3d")}, QDir::Files)) {
    if (info.fileName() == own || ownerIsRunning(info.fileName()))
      continue;
    RecoveryFile file;
    file.path = info.absoluteFilePath();
    const QSettings description(descriptionPath(file.path), QSettings::IniFormat);
    file.originalPath = description.value(QStringLiteral("original")).toString();
    file.written = description.value(QStringLiteral("written"), info.lastModified()).toDateTime();
    for (const QString& key : description.allKeys())
      if (key.startsWith(QStringLiteral("session/")))
        file.session.insert(key.mid(8), description.value(key));
    if (QFileInfo::exists(statePath(file.path)))
      file.statePath = statePath(file.path);
    files.push_back(std::move(file));
  }
  std::sort(files.begin(), files.end(),
            [](const RecoveryFile& a, const RecoveryFile& b) { return a.written > b.written; });
  return files;
}

void Autosave::remove(const RecoveryFile& file)
{
  QFile::remove(file.path);
  QFile::remove(descriptionPath(file.path));
  QFile::remove(statePath(file.path));
}

std::optional<SessionState> Autosave::readState(const RecoveryFile& file)
{
  if (file.statePath.isEmpty())
    return stateInDescription(file.session);
  const std::string path = file.statePath.toStdString();
  return decodeSessionState(QByteArray::fromStdString(readFileBytes(path)), path);
}

} // namespace mocap::ui
