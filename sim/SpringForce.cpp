#include "SpringForce.h"

namespace pf {

SpringEval evaluateSpring(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                          double rest, double stiffness, double damping, bool clampCompressed) {
    SpringEval out;
    const SpringTerms s = springTerms(xa, xb, va, vb, rest, stiffness, damping, clampCompressed);
    if (!s.valid) return out;
    const Mat3 uu = s.u * s.u.transpose();
    out.force = s.force * s.u;
    out.K = stiffness * (uu + s.transverse * (Mat3::Identity() - uu));
    out.C = damping * uu;
    return out;
}

} // namespace pf
