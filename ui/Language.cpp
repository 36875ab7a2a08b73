#include "Language.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QEvent>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace pf {

namespace {

// Takes `current` out of the application and deletes it.
void uninstall(QTranslator*& current) {
    if (!current) return;
    QCoreApplication::removeTranslator(current);
    delete current;
    current = nullptr;
}

// Qt's own texts in the language: the modifier keys of the menus' shortcuts ("Strg+O",
// "Leertaste": a German user read "Ctrl+O" and "Space"), the standard dialogs' buttons.
// Debian's qt6-translations-l10n; without it those stay English.
void installQtsOwn(const QString& language) {
    static QTranslator* current = nullptr;
    uninstall(current);
    if (language.isEmpty() || language.startsWith(QLatin1String("en"))) return;
    auto* t = new QTranslator;
    if (!t->load(QStringLiteral("qtbase_") + language,
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        delete t;
        return;
    }
    QCoreApplication::installTranslator(t);
    current = t;
}

} // namespace

bool installLanguage(const QString& code) {
    static QTranslator* current = nullptr;
    uninstall(current);
    const QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    auto* t = new QTranslator;
    const bool found =
        t->load(locale, QStringLiteral("paperfold"), QStringLiteral("_"), QStringLiteral(":/i18n"));
    // English is the source language; its translation holds only the plural forms, and
    // is what a language without a translation (or the C locale) shows.
    if (!found && !t->load(QStringLiteral("paperfold_en"), QStringLiteral(":/i18n"))) {
        delete t;
        return false;
    }
    // Numbers as the language writes them ("0,31× Echtzeit", a spin box's "0,50"), but
    // without thousands separators, which the readouts never had. Before the translator:
    // installing it sends the LanguageChange at which the window says its numbers again.
    // The translation's own language: the system's may differ (a de_DE system whose
    // preferred UI language is English gets English words, so English digits).
    QLocale numbers = found && !t->language().isEmpty()
                          ? QLocale(t->language())
                          : QLocale(QLocale::English, QLocale::UnitedStates);
    numbers.setNumberOptions(QLocale::OmitGroupSeparator);
    QLocale::setDefault(numbers);
    // Every window that has no locale of its own takes the new one, floating docks and
    // dialogs included (QApplication hands it to each top-level widget).
    QEvent localeChange(QEvent::LocaleChange);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &localeChange);
    installQtsOwn(found ? t->language().section(QLatin1Char('_'), 0, 0) : QString());
    QCoreApplication::installTranslator(t);
    current = t;
    return found || code.isEmpty() || code == QLatin1String("en");
}

QActionGroup* createLanguageActions(QObject* parent) {
    auto* group = new QActionGroup(parent);
    const QString saved = QSettings().value(QStringLiteral("language")).toString();
    for (const char* c : {"", "en", "de", "ja", "ko"}) {
        const QString code = QString::fromLatin1(c);
        auto* a = new QAction(parent);
        a->setObjectName(QStringLiteral("language.") + code);
        a->setCheckable(true);
        a->setChecked(code == saved);
        a->setData(code);
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, parent, [code] {
            installLanguage(code);
            QSettings().setValue(QStringLiteral("language"), code);
        });
    }
    return group;
}

} // namespace pf
