#include "Legend.h"

#include "HeatColor.h"
#include "Params.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QLocale>
#include <algorithm>
#include <vector>

namespace pf {

namespace {

QColor heat(double t) {
    const auto c = heatColor(t);
    return QColor::fromRgbF(c[0], c[1], c[2]);
}

} // namespace

LegendContent legendContent(const RenderOptions& options) {
    LegendContent content;
    const QLocale locale;
    const auto top = [&](double range, const QString& unit) {
        return QStringLiteral("≥ %1%2").arg(locale.toString(range, 'g', 3), unit);
    };
    // Eq. 10's P is drawn per growth of an edge's contraction by the reference amount
    // (docs/model.md, "Breaking"), no longer per 1/60 s. A file may carry its own
    // reference; the editor and the command line make none but the default.
    if (options.overlays & OverlayBreakProbability)
        content.bars.push_back(
            {QCoreApplication::translate("Legend",
                                         "Break probability P (Eq. 10, per %1 % more contraction)")
                 .arg(locale.toString(100.0 * SimParams{}.breakReferenceContraction)),
             top(options.probabilityRange, QString())});
    // Compression too: a user read the red of a fold's compressed creases as stretched
    // paper, while the Solver dock said the stretch was 0.07 %.
    if (options.overlays & OverlayStrain)
        content.bars.push_back(
            {QCoreApplication::translate("Legend", "Strain |l/l0 - 1|, stretched or compressed"),
             top(options.strainRange * 100.0, QStringLiteral("%"))});
    auto& swatches = content.swatches;
    if (options.overlays & OverlaySpringKinds) {
        swatches.push_back({QColor::fromRgbF(0.10, 0.30, 0.95),
                            QCoreApplication::translate("Legend", "breakable spring")});
        swatches.push_back({QColor::fromRgbF(0.45, 0.65, 1.00),
                            QCoreApplication::translate("Legend", "unbreakable spring")});
        swatches.push_back({QColor::fromRgbF(0.90, 0.10, 0.10),
                            QCoreApplication::translate("Legend", "crease (broken)")});
        swatches.push_back(
            {QColor::fromRgbF(0.10, 0.70, 0.20), QCoreApplication::translate("Legend", "hinge")});
    }
    if (options.overlays & OverlayWireframe)
        swatches.push_back({QColor::fromRgbF(0.12, 0.12, 0.14),
                            QCoreApplication::translate("Legend", "simulation mesh (edges)")});
    if (options.overlays & OverlayRecentBreaks)
        swatches.push_back({QColor::fromRgbF(1.0, 0.0, 0.75),
                            QCoreApplication::translate("Legend", "broken in the last second")});
    return content;
}

void drawLegend(QPainter& painter, const QRect& area, const RenderOptions& options) {
    const LegendContent content = legendContent(options);
    const auto& bars = content.bars;
    const auto& swatches = content.swatches;
    if (bars.empty() && swatches.empty()) return;

    const double scale = std::max(1.0, area.height() / 720.0);
    QFont font = painter.font();
    font.setPixelSize(static_cast<int>(13 * scale));
    painter.setFont(font);
    const int line = static_cast<int>(18 * scale), pad = static_cast<int>(10 * scale);
    const int barW = static_cast<int>(220 * scale), barH = static_cast<int>(12 * scale);
    const int height = pad * 2 + static_cast<int>(bars.size()) * (line * 2 + barH) +
                       static_cast<int>(swatches.size()) * line;
    // As wide as its longest line (a title in German is half as long again as the bar).
    const QFontMetrics metrics(font);
    const int swatchW = static_cast<int>(32 * scale);
    int textW = barW + static_cast<int>(110 * scale);
    for (const LegendContent::Bar& b : bars)
        textW = std::max(textW, metrics.horizontalAdvance(b.title));
    for (const LegendContent::Swatch& s : swatches)
        textW = std::max(textW, swatchW + metrics.horizontalAdvance(s.label));
    const int width = std::min(textW + pad * 2, area.width() - 2 * pad);
    const QRect box(area.left() + pad, area.bottom() - height - pad, width, height);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRoundedRect(box, 6 * scale, 6 * scale);

    int y = box.top() + pad;
    painter.setPen(QColor(30, 30, 30));
    for (const LegendContent::Bar& b : bars) {
        painter.drawText(QRect(box.left() + pad, y, width - 2 * pad, line),
                         Qt::AlignLeft | Qt::AlignVCenter, b.title);
        y += line;
        QLinearGradient g(box.left() + pad, 0, box.left() + pad + barW, 0);
        for (int k = 0; k <= 8; ++k) g.setColorAt(k / 8.0, heat(k / 8.0));
        painter.fillRect(QRect(box.left() + pad, y, barW, barH), g);
        y += barH;
        painter.drawText(QRect(box.left() + pad, y, barW, line), Qt::AlignLeft | Qt::AlignVCenter,
                         QStringLiteral("0"));
        painter.drawText(QRect(box.left() + pad, y, barW, line), Qt::AlignRight | Qt::AlignVCenter,
                         b.top);
        y += line;
    }
    for (const LegendContent::Swatch& s : swatches) {
        painter.fillRect(QRect(box.left() + pad, y + line / 2 - 2, static_cast<int>(24 * scale),
                               static_cast<int>(4 * scale)),
                         s.color);
        painter.drawText(QRect(box.left() + pad + swatchW, y, width - swatchW - 2 * pad, line),
                         Qt::AlignLeft | Qt::AlignVCenter, s.label);
        y += line;
    }
}

} // namespace pf
