#include "CrumpleCycles.h"

#include "CLocaleNumber.h"
#include "CreaseNetwork.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <cmath>

namespace pf {

LogarithmicFit fitLogarithmic(const std::vector<double>& values) {
    LogarithmicFit fit;
    const double n = static_cast<double>(values.size());
    if (values.size() < 2) return fit;
    double mx = 0.0, my = 0.0;
    for (std::size_t k = 0; k < values.size(); ++k) {
        mx += std::log(k + 1.0);
        my += values[k];
    }
    mx /= n;
    my /= n;
    double sxx = 0.0, sxy = 0.0, syy = 0.0;
    for (std::size_t k = 0; k < values.size(); ++k) {
        const double dx = std::log(k + 1.0) - mx, dy = values[k] - my;
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    fit.b = sxy / sxx;
    fit.a = my - fit.b * mx;
    double residual = 0.0;
    for (std::size_t k = 0; k < values.size(); ++k) {
        const double e = values[k] - (fit.a + fit.b * std::log(k + 1.0));
        residual += e * e;
    }
    fit.r2 = syy > 0.0 ? 1.0 - residual / syy : 1.0;
    return fit;
}

CrumpleReport
runCrumpleCycles(World world, int cycles,
                 const std::function<void(const CrumpleCycle&, const Sheet&)>& progress) {
    CrumpleReport report;
    Simulation sim(std::move(world));
    std::vector<double> lengths;
    for (int k = 1; k <= cycles; ++k) {
        // Half a step's margin: the clock is a sum of steps, not a multiple of them.
        const double end = k * kCrumpleCycleSeconds - 0.5 * sim.world().params.dt;
        while (sim.world().time < end) {
            if (sim.step() != StepStatus::Ok) {
                report.error = "cycle " + std::to_string(k) + ": a step diverged at t = " +
                               cLocaleNumber(sim.world().time, std::chars_format::fixed, 4) + " s";
                return report;
            }
        }
        const Sheet& s = sim.world().sheet;
        CrumpleCycle c;
        c.cycle = k;
        c.vertices = s.verts.size();
        c.breaks = computeStats(s).breaks;
        c.creaseLength = measureCreases(s).totalLength;
        report.cycles.push_back(c);
        lengths.push_back(c.creaseLength);
        if (progress) progress(c, s);
    }
    report.fit = fitLogarithmic(lengths);
    report.segments = measureCreases(sim.world().sheet).segments;
    return report;
}

} // namespace pf
