#include "actions/recovery_offer.h"

#include "document/autosave.h"
#include "document/studio_session.h"
#include "document/take_document.h"

#include "mocap/io/take_io.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>

namespace mocap::ui {

/// The translation context of the offer's texts.
class RecoveryOffer
{
  Q_DECLARE_TR_FUNCTIONS(RecoveryOffer)
};

namespace {

/// The session state kept beside `file` restored onto the recovered take: "" or what was not.
QString restoreKeptState(StudioSession& session, const RecoveryFile& file)
{
  try {
    const std::optional<SessionState> state = Autosave::readState(file);
    return state ? session.restoreState(*state) : QString();
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  }
}

} // namespace

std::optional<RecoveredTake> offerRecovery(StudioSession& session, Autosave& autosave, QWidget& dialogParent,
                                           const std::function<void(const QVariantMap&)>& restoreWindow, bool ask)
{
  TakeDocument& document = session.document();
  for (const RecoveryFile& file : Autosave::leftovers()) {
    const QString name = file.originalPath.isEmpty() ? RecoveryOffer::tr("an untitled take") : QFileInfo(file.originalPath).fileName();
    const auto answer =
        !ask ? QMessageBox::Yes
             : QMessageBox::question(
                   &dialogParent, RecoveryOffer::tr("Recover unsaved edits?"),
                   RecoveryOffer::tr("Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?")
                       .arg(name, QLocale().toString(file.written, QLocale::ShortFormat)),
                   QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Ignore, QMessageBox::Yes);
    if (answer == QMessageBox::Ignore)
      continue;  // ask again next time
    if (answer == QMessageBox::Discard) {
      Autosave::remove(file);
      continue;
    }
    try {
      document.setTake(readTake(file.path.toStdString()), file.originalPath);
    } catch (const std::exception& e) {
      QMessageBox::critical(&dialogParent, RecoveryOffer::tr("Cannot recover"), QString::fromStdString(e.what()));
      continue;
    }
    document.markModified();
    RecoveredTake recovered{name, restoreKeptState(session, file)};
    restoreWindow(file.session);
    // Our own recovery copy first, then the old one goes: the edits are never only in memory.
    if (autosave.saveNow().isEmpty())
      Autosave::remove(file);
    return recovered;
  }
  return std::nullopt;
}

} // namespace mocap::ui
