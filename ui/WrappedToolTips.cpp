#include "WrappedToolTips.h"

#include <QFontMetrics>
#include <QHelpEvent>
#include <QToolTip>
#include <QWidget>

namespace pf {

bool WrappedToolTips::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ToolTip) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget) return false;
    const QString tip = widget->toolTip();
    if (tip.size() < kWrapFrom || Qt::mightBeRichText(tip)) return false;
    const auto* help = static_cast<QHelpEvent*>(event);
    // As wide as some sixty characters of the tip's font (Qt's own choice for a
    // wrapped label was a narrow column of seven lines).
    const int width = QFontMetrics(QToolTip::font()).averageCharWidth() * kLineCharacters;
    QToolTip::showText(help->globalPos(),
                       QStringLiteral("<table width=\"%1\"><tr><td>%2</td></tr></table>")
                           .arg(width)
                           .arg(tip.toHtmlEscaped()),
                       widget, {}, widget->toolTipDuration());
    return true;
}

} // namespace pf
