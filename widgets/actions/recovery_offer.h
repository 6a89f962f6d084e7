#pragma once

#include <QString>
#include <QVariantMap>

#include <functional>
#include <optional>

class QWidget;

namespace mocap::ui {

class Autosave;
class StudioSession;

/// A take brought back by offerRecovery.
struct RecoveredTake
{
  QString name;      ///< the file it was editing ("an untitled take" without one)
  QString problems;  ///< what of the session could not be restored, one a line; "" when all was
};

/// Offers, newest first, the takes that crashed sessions left unsaved (Autosave::leftovers): Yes
/// reads the take into the session's document as unsaved edits, restores the session state kept
/// beside it (StudioSession::restoreState: face mesh, binding, rig and weights, videos, layout
/// plan), hands the window's kept layout to `restoreWindow`, then writes our own recovery copy
/// before the old one goes (the edits are never only in memory); Discard deletes a leftover;
/// Ignore asks again next time. Without `ask` the newest is recovered as Yes would (scripts,
/// tests: `mocap-studio --recover`). Returns the recovered take, or none.
std::optional<RecoveredTake> offerRecovery(StudioSession& session, Autosave& autosave, QWidget& dialogParent,
                                           const std::function<void(const QVariantMap&)>& restoreWindow,
                                           bool ask = true);

} // namespace mocap::ui
