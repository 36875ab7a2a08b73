#include "HelpText.h"

#include <QMessageBox>

namespace pf {

void HelpText::showMouseAndKeys(QWidget* parent) {
    QMessageBox::information(
        parent, tr("Mouse and Keys"),
        tr("<table cellspacing=\"2\" cellpadding=\"3\">"
           "<tr><td><b>P</b>, <b>G</b>, <b>I</b>, <b>L</b></td><td>tools: push, grab, pin, "
           "fold</td></tr>"
           "<tr><td><b>Left drag</b> (push)</td><td>press the sphere into the paper and plough "
           "it (one undo step per stroke)</td></tr>"
           "<tr><td><b>Left drag</b> (grab)</td><td>pick up the point under the cursor and "
           "drag it; the wheel lifts or lowers it while held; release lets it fall</td></tr>"
           "<tr><td><b>Click</b> (pin)</td><td>pin the paper around the point, or free it if "
           "it is pinned</td></tr>"
           "<tr><td><b>Left drag</b> (fold)</td><td>draw the fold line across the paper; the "
           "lighter side (or the side without pins) is carried round it (valley or mountain, and "
           "the angle, in the "
           "Parameters panel)</td></tr>"
           "<tr><td><b>Ctrl + wheel</b></td><td>sphere radius (and the pin region)</td></tr>"
           "<tr><td><b>Right drag</b>, arrow keys</td><td>orbit the camera</td></tr>"
           "<tr><td><b>Middle drag</b>, Shift + right drag</td><td>pan</td></tr>"
           "<tr><td><b>Wheel</b>, + and −</td><td>zoom</td></tr>"
           "<tr><td><b>1</b>, <b>2</b>, <b>3</b>, <b>F</b></td><td>top, front, isometric view; fit "
           "to sheet</td></tr>"
           "<tr><td><b>Space</b>, <b>Ctrl+.</b>, <b>Ctrl+K</b>, <b>Ctrl+R</b></td><td>play/pause, "
           "single step, settle, reset</td></tr>"
           "<tr><td><b>Alt+1…5</b></td><td>overlays: spring kinds, break probability, strain, "
           "recent breaks, wireframe</td></tr>"
           "<tr><td><b>Ctrl+Z</b>, <b>Ctrl+Shift+Z</b></td><td>undo, redo</td></tr>"
           "</table>"));
}

void HelpText::showAbout(QWidget* parent) {
    QMessageBox::about(parent, tr("About PaperFold"),
                       tr("<p><b>PaperFold %1</b></p><p>Crumple and fold virtual paper in real "
                          "time, after Kang &amp; Cho, <i>A Simple and Effective Model for "
                          "Interactive Paper Folding</i>.</p>")
                           .arg(QCoreApplication::applicationVersion()));
}

} // namespace pf
