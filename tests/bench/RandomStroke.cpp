#include "RandomStroke.h"

#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QWidget>

namespace pf::bench {

namespace {

void sendMouse(QWidget* view, QEvent::Type type, const QPoint& p, Qt::MouseButton button,
               Qt::MouseButtons buttons) {
    QMouseEvent e(type, p, view->mapToGlobal(p), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(view, &e);
}

} // namespace

void randomStroke(QWidget* view, QRandomGenerator& rng, int moves,
                  const std::function<bool()>& stop, std::optional<QPoint> start) {
    const QPoint near = QPoint(rng.bounded(-150, 151), rng.bounded(-100, 101));
    QPoint p = start ? *start : view->rect().center() + near;
    const QPoint step(rng.bounded(-6, 7), rng.bounded(-6, 7));
    sendMouse(view, QEvent::MouseMove, p, Qt::NoButton, Qt::NoButton);
    QTest::qWait(30);
    sendMouse(view, QEvent::MouseButtonPress, p, Qt::LeftButton, Qt::LeftButton);
    for (int k = 0; k < moves && !(stop && stop()); ++k) {
        p += step;
        sendMouse(view, QEvent::MouseMove, p, Qt::NoButton, Qt::LeftButton);
        QTest::qWait(20);
    }
    sendMouse(view, QEvent::MouseButtonRelease, p, Qt::LeftButton, Qt::NoButton);
    QTest::qWait(20);
}

} // namespace pf::bench
