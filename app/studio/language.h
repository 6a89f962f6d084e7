// UI language of the studio: the translations built in under ":/i18n" and switching between them.
#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;

namespace mocap::studio {

/// Codes of the languages the studio speaks, the source language "en" first.
QStringList availableLanguages();

/// The language's name in that language ("Deutsch"), so users find theirs whatever the UI shows;
/// empty for an unknown code.
QString languageName(const QString& code);

/// The names of availableLanguages(), in that order.
QStringList availableLanguageNames();

/// The first of the system's preferred UI languages that the studio speaks, else "en".
QString defaultLanguage();

/// Replaces the translators this function installed before with those for `code`: the studio's
/// ":/i18n/mocap_studio_<code>.qm" and, when the system has it, Qt's own qtbase catalogue (standard
/// dialogs and key names). "en" needs no file and just removes them. Returns false, keeping the current
/// language, for an unknown code or a missing studio catalogue. Call from the GUI thread.
bool installLanguage(QCoreApplication& app, const QString& code);

} // namespace mocap::studio
