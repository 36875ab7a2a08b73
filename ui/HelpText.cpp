#include "HelpText.h"

#include <QMessageBox>

namespace pf {

void HelpText::showMouseAndKeys(QWidget* parent) {
    QMessageBox::information(
        parent, tr("Mouse and Keys"),
        tr("<table>"
           "<tr><td><b>Move the mouse</b></td><td>the sphere follows the cursor over the "
           "sheet</td></tr>"
           "<tr><td><b>Left drag</b></td><td>push the sphere into the paper (one undo step per "
           "stroke)</td></tr>"
           "<tr><td><b>Ctrl + wheel</b></td><td>sphere radius</td></tr>"
           "<tr><td><b>Right drag</b>, arrow keys</td><td>orbit the camera</td></tr>"
           "<tr><td><b>Middle drag</b>, Shift + right drag</td><td>pan</td></tr>"
           "<tr><td><b>Wheel</b>, + and −</td><td>zoom</td></tr>"
           "<tr><td><b>1</b>, <b>2</b>, <b>3</b>, <b>F</b></td><td>top, front, isometric view; fit "
           "to sheet</td></tr>"
           "<tr><td><b>Space</b>, <b>Ctrl+.</b>, <b>Ctrl+R</b></td><td>play/pause, single step, "
           "reset</td></tr>"
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
