#include "Hinges.h"

#include <cmath>

namespace pf {

int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step) {
    int inserted = 0;
    const Index count = sheet.springs.size();
    const double threshold2 = params.hingeThreshold * params.hingeThreshold;
    for (Index s = 0; s < count; ++s) {
        const auto& S = sheet.springs;
        if (S.kind[s] != SpringKind::Structural || S.hinged[s]) continue;
        const Index t1 = S.faces[s][0], t2 = S.faces[s][1];
        if (t1 == kNone || t2 == kNone) continue;
        const Index r = sheet.oppositeVertex(t1, S.a[s], S.b[s]);
        const Index l = sheet.oppositeVertex(t2, S.a[s], S.b[s]);
        const auto& V = sheet.verts;
        const double d2 = (V.x[r] - V.x[l]).squaredNorm();
        const double rest2 = (V.X[r] - V.X[l]).squaredNorm();
        if (!(d2 < threshold2 * rest2)) continue;

        sheet.paper.meshChanged();
        const Index hinge = sheet.addSpring(r, l, std::sqrt(d2), SpringKind::Hinge, false);
        DamageEvent ev;
        ev.kind = EventKind::Hinge;
        ev.step = step;
        ev.edge = s;
        ev.springs = {hinge, kNone, kNone, kNone};
        sheet.events.push_back(ev);
        sheet.springs.event[hinge] = static_cast<Index>(sheet.events.size()) - 1;
        sheet.springs.hinged[s] = 1;
        ++inserted;
    }
    return inserted;
}

} // namespace pf
