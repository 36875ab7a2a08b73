#include "RenderOptions.h"

#include <QStringList>

namespace pf {

namespace {

struct NamedOverlay {
    const char* name;
    Overlay bit;
};
constexpr NamedOverlay kOverlays[] = {
    {"springs", OverlaySpringKinds}, {"probability", OverlayBreakProbability},
    {"strain", OverlayStrain},       {"breaks", OverlayRecentBreaks},
    {"wireframe", OverlayWireframe},
};

} // namespace

QString overlayNames() {
    QStringList names;
    for (const auto& o : kOverlays) names << QLatin1String(o.name);
    return names.join(QStringLiteral(", "));
}

std::optional<unsigned> overlaysFromNames(const QString& names, QString* error) {
    unsigned bits = 0;
    for (const QString& word : names.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString w = word.trimmed();
        if (w == QLatin1String("none")) continue;
        bool found = false;
        for (const auto& o : kOverlays)
            if (w == QLatin1String(o.name)) {
                bits |= o.bit;
                found = true;
            }
        if (!found) {
            if (error)
                *error = QStringLiteral("unknown overlay '%1' (known: %2)").arg(w, overlayNames());
            return std::nullopt;
        }
    }
    return bits;
}

} // namespace pf
