#include "Normals.h"

namespace pf {

void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals) {
    computeVertexNormals(sheet.verts.x, sheet.tris, normals);
}

void computeVertexNormals(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                          std::vector<Vec3>& normals) {
    normals.assign(x.size(), Vec3::Zero());
    for (const Triangle& t : tris) {
        const Vec3 n = (x[t.v[1]] - x[t.v[0]]).cross(x[t.v[2]] - x[t.v[0]]);
        for (Index w : t.v) normals[w] += n;
    }
    for (Vec3& n : normals) {
        const double len = n.norm();
        n = len > 0.0 ? Vec3(n / len) : Vec3::UnitY();
    }
}

} // namespace pf
