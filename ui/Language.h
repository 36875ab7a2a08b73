#pragma once

#include <QString>

class QActionGroup;
class QObject;

namespace pf {

// Switches the interface language ("" follows the system, else "ko", "ja", "de", "en").
// False when there is no translation for it; English, with its plural forms, shows then.
bool installLanguage(const QString& code);

// The View ▸ Language entries, named "language.<code>" ("language." follows the system):
// choosing one installs it and remembers it in the settings; the remembered one is checked.
QActionGroup* createLanguageActions(QObject* parent);

} // namespace pf
