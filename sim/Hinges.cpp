#include "Hinges.h"

#include <cmath>

namespace pf {

bool canHinge(const Sheet& sheet, Index spring) {
    const auto& S = sheet.springs;
    return S.kind[spring] == SpringKind::Structural && !S.hinged[spring] &&
           S.faces[spring][0] != kNone && S.faces[spring][1] != kNone;
}

Index insertHinge(Sheet& sheet, Index spring, double rest, std::int64_t step) {
    auto& S = sheet.springs;
    const Index r = sheet.oppositeVertex(S.faces[spring][0], S.a[spring], S.b[spring]);
    const Index l = sheet.oppositeVertex(S.faces[spring][1], S.a[spring], S.b[spring]);
    sheet.paper.meshChanged();
    const Index hinge = sheet.addSpring(r, l, rest, SpringKind::Hinge, false);
    DamageEvent ev;
    ev.kind = EventKind::Hinge;
    ev.step = step;
    ev.edge = spring;
    ev.springs = {hinge, kNone, kNone, kNone};
    sheet.events.push_back(ev);
    const Index event = static_cast<Index>(sheet.events.size()) - 1;
    S.event[hinge] = event;
    S.hinged[spring] = 1;
    return event;
}

int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step) {
    int inserted = 0;
    const Index count = sheet.springs.size();
    const double threshold2 = params.hingeThreshold * params.hingeThreshold;
    for (Index s = 0; s < count; ++s) {
        if (!canHinge(sheet, s)) continue;
        const auto& S = sheet.springs;
        const Index r = sheet.oppositeVertex(S.faces[s][0], S.a[s], S.b[s]);
        const Index l = sheet.oppositeVertex(S.faces[s][1], S.a[s], S.b[s]);
        const auto& V = sheet.verts;
        const double d2 = (V.x[r] - V.x[l]).squaredNorm();
        const double rest2 = (V.X[r] - V.X[l]).squaredNorm();
        // r on l (pins can hold them there) leaves a spring no direction and no positive
        // rest length: the fold gets its hinge once they part.
        if (!(d2 > 0.0 && d2 < threshold2 * rest2)) continue;

        insertHinge(sheet, s, std::sqrt(d2), step);
        ++inserted;
    }
    return inserted;
}

} // namespace pf
