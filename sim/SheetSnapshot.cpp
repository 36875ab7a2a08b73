#include "SheetSnapshot.h"

#include "Breaking.h"
#include "Normals.h"

#include <atomic>
#include <cmath>

namespace pf {

SheetSnapshot makeSnapshot(const World& world, double recentSeconds) {
    const Sheet& s = world.sheet;
    const auto& S = s.springs;
    const auto& x = s.verts.x;
    SheetSnapshot snap;
    snap.x = x;
    snap.tris = s.tris;
    snap.springKind = S.kind;
    snap.breakable = S.breakable;
    snap.springEnds.resize(static_cast<std::size_t>(S.size()));
    snap.breakProbability.assign(static_cast<std::size_t>(S.size()), 0.0f);
    snap.strain.resize(static_cast<std::size_t>(S.size()));
    snap.recentlyBroken.assign(static_cast<std::size_t>(S.size()), 0);
    snap.vertexStrain.assign(x.size(), 0.0f);

    std::vector<Vec3> normals;
    computeVertexNormals(s, normals);
    for (Index k = 0; k < S.size(); ++k) {
        const Index a = S.a[k], b = S.b[k];
        snap.springEnds[k] = {a, b};
        const double l = (x[a] - x[b]).norm();
        snap.strain[k] = static_cast<float>(l / S.rest[k] - 1.0);
        if (S.kind[k] == SpringKind::Structural) {
            const float e = std::abs(snap.strain[k]);
            snap.vertexStrain[a] = std::max(snap.vertexStrain[a], e);
            snap.vertexStrain[b] = std::max(snap.vertexStrain[b], e);
        }
        const Index t1 = S.faces[k][0], t2 = S.faces[k][1];
        if (!S.breakable[k] || t1 == kNone || t2 == kNone) continue;
        const Index r = s.oppositeVertex(t1, a, b), lv = s.oppositeVertex(t2, a, b);
        snap.breakProbability[k] = static_cast<float>(
            breakProbability(l, S.rest[k], (x[r] - x[lv]).norm(), normals[a].dot(normals[b]),
                             normals[r].dot(normals[lv]), world.params.phi));
    }
    const auto recentSteps = static_cast<std::int64_t>(std::ceil(recentSeconds / world.params.dt));
    for (const DamageEvent& ev : s.events) {
        if (!ev.active || ev.kind != EventKind::Break || world.stepCount - ev.step > recentSteps)
            continue;
        snap.recentlyBroken[ev.edge] = 1;
        snap.recentlyBroken[ev.springs[0]] = 1;
        snap.recentlyBroken[ev.springs[1]] = 1;
    }
    snap.sphere = world.sphere;
    snap.groundEnabled = world.groundEnabled;
    snap.groundHeight = world.groundHeight;
    snap.time = world.time;
    snap.step = world.stepCount;
    snap.sigma = world.params.sigma;
    static std::atomic<std::uint64_t> serials{0};
    snap.serial = ++serials;
    return snap;
}

} // namespace pf
