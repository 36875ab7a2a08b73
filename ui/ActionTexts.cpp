#include "ActionTexts.h"

#include <QAction>
#include <QRegularExpression>

namespace pf {

QString ActionTexts::withoutMnemonic(const QString& text) {
    static const QRegularExpression keyAfter(QStringLiteral("\\s*[(（]&[^&][)）]"));
    QString words = text;
    words.remove(keyAfter);
    // "&&" is a '&' shown; a lone '&' marks the key.
    words.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    words.remove(QLatin1Char('&'));
    words.replace(QLatin1Char('\x01'), QLatin1Char('&'));
    return words;
}

void ActionTexts::apply(const QObject* window) {
    auto action = [window](const char* name) {
        return window->findChild<QAction*>(QLatin1String(name));
    };
    auto set = [&](const char* name, const QString& text, const QString& tip = QString()) {
        QAction* a = action(name);
        a->setText(text);
        a->setIconText(withoutMnemonic(text));
        a->setToolTip(tip.isEmpty() ? withoutMnemonic(text) : tip);
    };
    set("new.press", tr("&Press (sphere on a sheet)"));
    set("new.drape", tr("&Drape (hanging sheet)"));
    set("new.compress", tr("&Compress (edges pushed together)"));
    set("new.drop", tr("D&rop (tilted sheet falls)"));
    set("new.fold", tr("&Fold (one edge turned over onto the other)"));
    set("new.crumple-cycles", tr("Cr&umple Cycles (crumpled and pulled flat, ten times)"));
    set("open", tr("&Open…"));
    set("save", tr("&Save"));
    set("saveAs", tr("Save &As…"));
    set("saveRecording", tr("Save &Recording…"),
        tr("Save everything done since New or Open; paperfold replay does it again"));
    set("exportImage", tr("Export &Image…"));
    set("exportMesh", tr("Export &Mesh…"));
    set("quit", tr("&Quit"));
    set("play", action("play")->isChecked() ? tr("&Pause") : tr("&Play"),
        tr("Play or pause the simulation (Space)"));
    set("step", tr("S&tep"), tr("Advance one step"));
    set("settle", tr("Sett&le"),
        tr("Let the sheet come to rest without new breaks and keep it so until the next edit "
           "(Ctrl+K)"));
    set("reset", tr("&Reset"), tr("Start the current scene again (Edit ▸ Undo gives it back)"));
    set("tool.push", tr("&Push"),
        tr("Push: the left button presses the sphere into the sheet and ploughs it (P)"));
    set("tool.grab", tr("&Grab"),
        tr("Grab: pick up a point of the sheet and drag it; the wheel lifts or lowers it "
           "while held; release lets it fall (G)"));
    set("tool.pin", tr("P&in"),
        tr("Pin: a click pins the paper around the point, or frees it if it is pinned; "
           "Ctrl + wheel sizes the region (I)"));
    set("tool.fold", tr("&Fold"),
        tr("Fold: draw a line across the paper; the lighter side (or the side without pins) is "
           "carried round it, "
           "pressed flat, opened to the angle set in the Parameters panel and let go (L)"));
    set("overlay.springs", tr("&Spring kinds"));
    set("overlay.probability", tr("&Break probability"));
    set("overlay.strain", tr("S&train"));
    set("overlay.breaks", tr("&Recent breaks"));
    set("overlay.wireframe", tr("Simulation &wireframe"));
    set("view.top", tr("&Top"));
    set("view.front", tr("&Front"));
    set("view.iso", tr("&Isometric"));
    set("view.fit", tr("Fit to &sheet"));
    set("view.creases", tr("&Crease Lines"),
        tr("The paper's creases drawn as fine lines a shade darker than the paper, as the "
           "damaged fibres of a crease show, also once the paper is pulled flat"));
    set("help", tr("&Mouse and Keys"));
    set("about", tr("&About PaperFold"));
    set("language.", tr("System language"));
    set("language.en", QStringLiteral("English"));
    set("language.de", QStringLiteral("Deutsch"));
    set("language.ja", QStringLiteral("日本語"));
    set("language.ko", QStringLiteral("한국어"));
    action("undo")->setText(tr("&Undo"));
    action("redo")->setText(tr("&Redo"));
}

} // namespace pf
