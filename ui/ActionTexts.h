#pragma once

#include <QCoreApplication>

class QObject;

namespace pf {

// The words on the editor's actions (menu entries, tool buttons and their tips), in the
// current language. The actions are found by object name among `window`'s children.
class ActionTexts {
    Q_DECLARE_TR_FUNCTIONS(pf::ActionTexts)

  public:
    static void apply(const QObject* window);
    // `text` (a file's name, say) as a menu entry shows it: a '&' is a shortcut mark
    // to a menu unless doubled ("a & b.paper" read "a _b.paper").
    static QString literal(QString text) {
        return text.replace(QLatin1Char('&'), QStringLiteral("&&"));
    }
    // A menu entry's `text` as words beside no menu (a tool button, a tip, the History):
    // without its shortcut mark, also where a language writes the key after the words
    // ("折る(&F)" read "折る(F)" on the Fold button, whose key is L).
    static QString withoutMnemonic(const QString& text);
};

} // namespace pf
