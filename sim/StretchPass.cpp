#include "StretchPass.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pf {

namespace {

// Constraints of a group taken together: enough independent square roots and
// divisions in flight to keep the divider busy, few enough to stay in registers and L1.
constexpr std::size_t kBlock = 16;

// out[i] = sqrt(in[i]) and q[i] = n[i] / d[i], two at a time where the processor can:
// correctly rounded either way, so the bits are those of std::sqrt and operator/.
void squareRoots(const double* in, double* out, std::size_t n) {
    std::size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= n; i += 2) _mm_storeu_pd(out + i, _mm_sqrt_pd(_mm_loadu_pd(in + i)));
#endif
    for (; i < n; ++i) out[i] = std::sqrt(in[i]);
}

void quotients(const double* num, const double* den, double* out, std::size_t n) {
    std::size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= n; i += 2)
        _mm_storeu_pd(out + i, _mm_div_pd(_mm_loadu_pd(num + i), _mm_loadu_pd(den + i)));
#endif
    for (; i < n; ++i) out[i] = num[i] / den[i];
}

} // namespace

void StretchPass::clear() {
    constraints_.clear();
    groups_.clear();
    lastColour_ = -1;
}

void StretchPass::add(const DistanceConstraint& k, int colour, bool shared) {
    if (groups_.empty() || colour != lastColour_)
        groups_.push_back({constraints_.size(), constraints_.size(), shared});
    constraints_.push_back(k);
    groups_.back().end = constraints_.size();
    lastColour_ = colour;
}

void StretchPass::relaxInOrder(std::size_t q, std::vector<Vec3>& x) const {
    const DistanceConstraint& k = constraints_[q];
    const Vec3 d = x[k.a] - x[k.b];
    const double len = d.norm();
    if (!(len > 1e-12)) return;
    const double dl = std::clamp((k.rest - len) * k.gain, k.lowest, k.highest);
    const Vec3 u = d * (dl / len);
    x[k.a] += k.wa * u;
    x[k.b] -= k.wb * u;
}

void StretchPass::relaxGroup(const Group& g, std::vector<Vec3>& x) const {
    Vec3 d[kBlock];
    double len2[kBlock], len[kBlock], dl[kBlock], s[kBlock];
    for (std::size_t begin = g.begin; begin < g.end; begin += kBlock) {
        const std::size_t n = std::min(kBlock, g.end - begin);
        const DistanceConstraint* k = constraints_.data() + begin;
        for (std::size_t i = 0; i < n; ++i) {
            d[i] = x[k[i].a] - x[k[i].b];
            len2[i] = d[i].squaredNorm();
        }
        squareRoots(len2, len, n);
        for (std::size_t i = 0; i < n; ++i)
            dl[i] = std::clamp((k[i].rest - len[i]) * k[i].gain, k[i].lowest, k[i].highest);
        quotients(dl, len, s, n);
        for (std::size_t i = 0; i < n; ++i) {
            if (!(len[i] > 1e-12)) continue;
            const Vec3 u = d[i] * s[i];
            x[k[i].a] += k[i].wa * u;
            x[k[i].b] -= k[i].wb * u;
        }
    }
}

void StretchPass::relax(std::vector<Vec3>& x) const {
    for (const Group& g : groups_) {
        if (!g.shared) {
            relaxGroup(g, x);
            continue;
        }
        for (std::size_t q = g.begin; q < g.end; ++q) relaxInOrder(q, x);
    }
    for (auto g = groups_.rbegin(); g != groups_.rend(); ++g) {
        if (!g->shared) {
            relaxGroup(*g, x);
            continue;
        }
        for (std::size_t q = g->end; q-- > g->begin;) relaxInOrder(q, x);
    }
}

} // namespace pf
