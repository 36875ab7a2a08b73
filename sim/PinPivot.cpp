#include "PinPivot.h"

namespace pf {

Pivot pivotOf(const Vertices& V) {
    const Index nv = V.size();
    Index first = 0;
    while (first < nv && !V.pinned[first]) ++first;
    Pivot p;
    if (first == nv) return p;
    p.kind = Pivot::Kind::Point;
    p.point = V.x[first];
    Index far = first;
    for (Index i = first; i < nv; ++i)
        if (V.pinned[i] && (V.x[i] - p.point).squaredNorm() > (V.x[far] - p.point).squaredNorm())
            far = i;
    const Vec3 span = V.x[far] - p.point;
    if (!(span.norm() > kPinsApart)) return p;
    const Vec3 axis = span.normalized();
    for (Index i = first; i < nv; ++i) {
        if (!V.pinned[i]) continue;
        const Vec3 d = V.x[i] - p.point;
        if ((d - d.dot(axis) * axis).norm() > kPinsApart) {
            p.kind = Pivot::Kind::Held;
            return p;
        }
    }
    p.kind = Pivot::Kind::Axis;
    p.axis = axis;
    return p;
}

} // namespace pf
