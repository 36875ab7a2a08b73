#pragma once

#include <QCoreApplication>

class QWidget;

namespace pf {

// The Help menu's two boxes: the mouse and keys, and what PaperFold is.
class HelpText {
    Q_DECLARE_TR_FUNCTIONS(pf::HelpText)

  public:
    static void showMouseAndKeys(QWidget* parent);
    static void showAbout(QWidget* parent);
};

} // namespace pf
