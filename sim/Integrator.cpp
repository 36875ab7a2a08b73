#include "Integrator.h"

#include "BackwardEulerIntegrator.h"
#include "JacobiIntegrator.h"
#include "SymplecticEulerIntegrator.h"
#include "XpbdIntegrator.h"

namespace pf {

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    if (name == "jacobi") return std::make_unique<JacobiIntegrator>(false);
    if (name == "jacobi-scalar") return std::make_unique<JacobiIntegrator>(true);
    if (name == "symplectic") return std::make_unique<SymplecticEulerIntegrator>();
    if (name == "backward-euler") return std::make_unique<BackwardEulerIntegrator>();
    if (name == "xpbd") return std::make_unique<XpbdIntegrator>();
    return nullptr;
}

bool keepsEdgeLengths(std::string_view integrator) {
    return integrator == "xpbd";
}

const std::vector<std::string>& integratorNames() {
    static const std::vector<std::string> names{"jacobi", "jacobi-scalar", "symplectic",
                                                "backward-euler", "xpbd"};
    return names;
}

void advancePositions(Sheet& sheet, double h, WorkerPool& pool) {
    auto& V = sheet.verts;
    pool.forRanges(V.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) V.x[i] += h * V.v[i];
    });
}

} // namespace pf
