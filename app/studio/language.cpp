#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QPointer>
#include <QTranslator>

#include <memory>
#include <vector>

namespace mocap::studio {

namespace {

struct Language {
  const char* code;
  const char16_t* nativeName;
};

// Fixed names rather than QLocale::nativeLanguageName(), which says "中文" without the script.
constexpr Language kLanguages[] = {
    {"en", u"English"},
    {"de", u"Deutsch"},
    {"zh_CN", u"简体中文"},
};

constexpr char kSourceLanguage[] = "en";

// Translators are parented to the application, so QPointer notices when it deletes them first.
std::vector<QPointer<QTranslator>>& installedTranslators()
{
  static std::vector<QPointer<QTranslator>> translators;
  return translators;
}

} // namespace

QStringList availableLanguages()
{
  QStringList codes;
  for (const Language& language : kLanguages)
    codes.append(QString::fromLatin1(language.code));
  return codes;
}

QString languageName(const QString& code)
{
  for (const Language& language : kLanguages) {
    if (code == QLatin1String(language.code))
      return QString::fromUtf16(language.nativeName);
  }
  return {};
}

QStringList availableLanguageNames()
{
  QStringList names;
  for (const QString& code : availableLanguages())
    names << languageName(code);
  return names;
}

QString defaultLanguage()
{
  // Language and script, not the country: de_AT gets German, zh_TW (Traditional) does not get zh_CN.
  const QStringList codes = availableLanguages();
  for (const QString& name : QLocale::system().uiLanguages()) {
    const QLocale wanted(name);
    for (const QString& code : codes) {
      const QLocale offered(code);
      if (offered.language() == wanted.language() && offered.script() == wanted.script())
        return code;
    }
  }
  return QString::fromLatin1(kSourceLanguage);
}

bool installLanguage(QCoreApplication& app, const QString& code)
{
  if (!availableLanguages().contains(code))
    return false;

  // Load everything before touching the installed set, so a failure leaves the current language.
  std::vector<std::unique_ptr<QTranslator>> loaded;
  if (code != QLatin1String(kSourceLanguage)) {
    // Qt's catalogue is optional (Debian: qt6-translations-l10n); without it only Qt's own texts
    // stay English. Installed first because the last installed translator is searched first.
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(QLocale(code), QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
      loaded.push_back(std::move(qt));
    auto studio = std::make_unique<QTranslator>();
    if (!studio->load(QStringLiteral(":/i18n/mocap_studio_%1.qm").arg(code)))
      return false;
    loaded.push_back(std::move(studio));
  }

  std::vector<QPointer<QTranslator>>& installed = installedTranslators();
  for (const QPointer<QTranslator>& translator : installed) {
    if (translator) {
      QCoreApplication::removeTranslator(translator);
      delete translator.data();
    }
  }
  installed.clear();
  for (std::unique_ptr<QTranslator>& translator : loaded) {
    translator->setParent(&app);
    QCoreApplication::installTranslator(translator.get());
    installed.emplace_back(translator.release());
  }
  return true;
}

} // namespace mocap::studio
