#include "document/autosave.h"

#include "document/take_document.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

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
    : QObject(parent), m_document(document), m_folder(folder.isEmpty() ? defaultFolder() : std::move(folder))
{
  m_timer.setInterval(kDefaultIntervalMs);
  connect(&m_timer, &QTimer::timeout, this, [this] {
    const QString error = saveNow();
    if (!error.isEmpty())
      emit failed(error);
  });
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

QString Autosave::saveNow()
{
  if (!m_document.hasTake() || !m_document.isModified())
    return {};
  if (!QDir().mkpath(m_folder))
    return tr("Cannot create the recovery folder %1").arg(m_folder);
  const QString path = recoveryPath();
  const QString error = m_document.save(path, false);
  if (!error.isEmpty())
    return error;
  QSettings description(descriptionPath(path), QSettings::IniFormat);
  description.setValue(QStringLiteral("original"), m_document.filePath());
  description.setValue(QStringLiteral("written"), QDateTime::currentDateTime());
  description.sync();
  return {};
}

void Autosave::discard()
{
  QFile::remove(recoveryPath());
  QFile::remove(descriptionPath(recoveryPath()));
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
}

} // namespace mocap::ui
