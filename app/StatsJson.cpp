#include "StatsJson.h"

#include "BuildTuning.h"
#include "SheetStats.h"

namespace pf::cli {

QJsonObject statsJson(const World& w, double wallSeconds, long long steps) {
    const SheetStats st = computeStats(w.sheet);
    QJsonObject o;
    o[QStringLiteral("scene")] = QString::fromStdString(w.scene);
    o[QStringLiteral("integrator")] = QString::fromStdString(w.params.integrator);
    o[QStringLiteral("iterations")] = w.params.iterations;
    o[QStringLiteral("dt")] = w.params.dt;
    // xpbd's paper and sub-steps (the other integrators read neither).
    o[QStringLiteral("material")] = QString::fromStdString(w.params.material.name);
    o[QStringLiteral("substeps")] = w.params.substeps;
    o[QStringLiteral("seed")] = QString::number(w.seed);
    o[QStringLiteral("steps")] = steps;
    o[QStringLiteral("vertices")] = st.vertices;
    o[QStringLiteral("springs")] = st.springs;
    o[QStringLiteral("triangles")] = st.triangles;
    o[QStringLiteral("breaks")] = st.breaks;
    o[QStringLiteral("recoveries")] = st.recoveries;
    o[QStringLiteral("hinges")] = st.hinges;
    o[QStringLiteral("total_mass")] = st.totalMass;
    o[QStringLiteral("max_strain")] = st.maxStrain;
    o[QStringLiteral("rms_strain")] = st.rmsStrain;
    o[QStringLiteral("max_stretch")] = st.maxStretch;
    o[QStringLiteral("rms_stretch")] = st.rmsStretch;
    o[QStringLiteral("max_compression")] = st.maxCompression;
    // Hex text: a 64-bit hash does not survive JSON's double-precision numbers.
    o[QStringLiteral("state_hash")] =
        QStringLiteral("%1").arg(stateHash(w.sheet), 16, 16, QLatin1Char('0'));
    o[QStringLiteral("sim_time")] = w.time;
    o[QStringLiteral("wall_seconds")] = wallSeconds;
    o[QStringLiteral("steps_per_second")] = wallSeconds > 0.0 ? steps / wallSeconds : 0.0;
    o[QStringLiteral("build_tuning")] = QString::fromStdString(buildTuning());
    return o;
}

} // namespace pf::cli
