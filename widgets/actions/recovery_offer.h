#pragma once

#include <QString>
#include <QVariantMap>

#include <functional>
#include <optional>

class QWidget;

namespace mocap::ui {

class Autosave;
class TakeDocument;

/// Offers, newest first, the takes that crashed sessions left unsaved (Autosave::leftovers): Yes
/// reads the take into `document` as unsaved edits and hands its kept session (face mesh,
/// binding, window layout) to `restore`, then writes our own recovery copy before the old one
/// goes (the edits are never only in memory); Discard deletes a leftover; Ignore asks again next
/// time. Returns the recovered take's name ("an untitled take" without a file), or none.
std::optional<QString> offerRecovery(TakeDocument& document, Autosave& autosave, QWidget& dialogParent,
                                     const std::function<void(const QVariantMap&)>& restore);

} // namespace mocap::ui
