#include "SheetStats.h"

#include <cmath>
#include <cstring>

namespace pf {

double totalMass(const Sheet& sheet) {
    double m = 0.0;
    for (double mi : sheet.verts.m) m += mi;
    return m;
}

Vec3 centreOfMass(const Sheet& sheet) {
    Vec3 c = Vec3::Zero();
    for (Index i = 0; i < sheet.verts.size(); ++i) c += sheet.verts.m[i] * sheet.verts.x[i];
    return c / totalMass(sheet);
}

SheetStats computeStats(const Sheet& sheet) {
    SheetStats st;
    const auto& S = sheet.springs;
    const auto& x = sheet.verts.x;
    st.vertices = sheet.verts.size();
    st.springs = S.size();
    st.triangles = sheet.triangleCount();
    for (const auto& ev : sheet.events) {
        if (ev.kind != EventKind::Break) continue;
        (ev.active ? st.breaks : st.recoveries) += 1;
    }
    double sum2 = 0.0, stretch2 = 0.0;
    Index structural = 0;
    for (Index s = 0; s < S.size(); ++s) {
        if (S.kind[s] == SpringKind::Hinge) ++st.hinges;
        if (S.kind[s] != SpringKind::Structural) continue;
        const double signedStrain = (x[S.a[s]] - x[S.b[s]]).norm() / S.rest[s] - 1.0;
        const double strain = std::abs(signedStrain);
        st.maxStrain = std::max(st.maxStrain, strain);
        sum2 += strain * strain;
        const double stretch = std::max(signedStrain, 0.0);
        st.maxStretch = std::max(st.maxStretch, stretch);
        stretch2 += stretch * stretch;
        st.maxCompression = std::max(st.maxCompression, -signedStrain);
        ++structural;
    }
    st.rmsStrain = structural > 0 ? std::sqrt(sum2 / structural) : 0.0;
    st.rmsStretch = structural > 0 ? std::sqrt(stretch2 / structural) : 0.0;
    st.totalMass = totalMass(sheet);
    return st;
}

std::uint64_t stateHash(const Sheet& sheet) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    auto mix = [&h](const Vec3& p) {
        unsigned char bytes[3 * sizeof(double)];
        std::memcpy(bytes, p.data(), sizeof bytes);
        for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
    };
    for (const Vec3& p : sheet.verts.x) mix(p);
    for (const Vec3& p : sheet.verts.v) mix(p);
    return h;
}

Index breaksSince(const Sheet& sheet, std::int64_t firstStep) {
    Index count = 0;
    // The log is in step order: only its tail can be recent.
    for (auto it = sheet.events.rbegin(); it != sheet.events.rend() && it->step >= firstStep; ++it)
        if (it->kind == EventKind::Break && it->active) ++count;
    return count;
}

std::uint64_t editedStateHash(const Sheet& sheet) {
    std::uint64_t h = stateHash(sheet);
    for (std::uint8_t pinned : sheet.verts.pinned) h = (h ^ pinned) * 0x100000001b3ULL;
    return h;
}

} // namespace pf
