#include "StabilityCommand.h"

#include "CommandLine.h"
#include "OutputFile.h"
#include "PngFile.h"
#include "StabilityProbe.h"

#include <QDir>
#include <QImage>
#include <QPainter>
#include <QTextStream>
#include <vector>

namespace pf::cli {

namespace {

struct Method {
    const char* name;
    const char* integrator;
    int sweeps;
    bool clamp;
};

constexpr Method kMethods[] = {
    {"jacobi-0", "jacobi", 0, true},
    {"jacobi-0-unclamped", "jacobi", 0, false},
    {"jacobi-1", "jacobi", 1, true},
    {"jacobi-1-unclamped", "jacobi", 1, false},
    {"jacobi-2", "jacobi", 2, true},
    {"jacobi-scalar-1", "jacobi-scalar", 1, true},
    {"symplectic", "symplectic", 0, true},
    {"backward-euler", "backward-euler", 0, true},
    {"xpbd", "xpbd", 0, true},
};
constexpr const char* kScenes[] = {"drape", "press", "compress"};

QColor outcomeColor(StabilityOutcome o) {
    switch (o) {
    case StabilityOutcome::Stable:
        return QColor(60, 160, 90);
    case StabilityOutcome::Overstrained:
        return QColor(240, 170, 40);
    case StabilityOutcome::EnergyBlowup:
        return QColor(220, 90, 40);
    case StabilityOutcome::Diverged:
        return QColor(190, 30, 40);
    }
    return Qt::gray;
}

// One panel per scene: columns are time steps (large to small), rows stiffness scales.
QImage heatMap(const Method& m, const std::vector<double>& steps, const std::vector<double>& scales,
               const std::vector<std::vector<std::vector<StabilityResult>>>& results) {
    const int cell = 34, left = 70, top = 50, gap = 40;
    const int panelW = cell * static_cast<int>(steps.size()),
              panelH = cell * static_cast<int>(scales.size());
    QImage img(std::max(left + 3 * (panelW + gap), 780), top + panelH + 90, QImage::Format_RGB32);
    img.fill(Qt::white);
    QPainter p(&img);
    QFont f = p.font();
    f.setPixelSize(12);
    p.setFont(f);
    p.drawText(QRect(0, 5, img.width(), 20), Qt::AlignCenter,
               QStringLiteral("%1: where the run survives (1 s, resolution 7)")
                   .arg(QLatin1String(m.name)));
    for (int s = 0; s < 3; ++s) {
        const int x0 = left + s * (panelW + gap);
        p.drawText(QRect(x0, 28, panelW, 18), Qt::AlignCenter, QLatin1String(kScenes[s]));
        for (std::size_t r = 0; r < scales.size(); ++r)
            for (std::size_t c = 0; c < steps.size(); ++c) {
                const QRect box(x0 + static_cast<int>(c) * cell, top + static_cast<int>(r) * cell,
                                cell - 2, cell - 2);
                p.fillRect(box, outcomeColor(results[s][r][c].outcome));
            }
        for (std::size_t c = 0; c < steps.size(); ++c) {
            p.save();
            p.translate(x0 + static_cast<int>(c) * cell + cell / 2 + 4, top + panelH + 4);
            p.rotate(90);
            p.drawText(0, 0, QStringLiteral("1/%1").arg(std::lround(1.0 / steps[c])));
            p.restore();
        }
    }
    for (std::size_t r = 0; r < scales.size(); ++r)
        p.drawText(QRect(0, top + static_cast<int>(r) * cell, left - 6, cell),
                   Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("k×%1").arg(scales[r]));
    p.drawText(QRect(left, img.height() - 22, img.width() - left, 18), Qt::AlignLeft,
               QStringLiteral("columns: time step h (s)   green stable · orange strain > 50 % · "
                              "dark orange kinetic energy > 10 J · red diverged"));
    return img;
}

} // namespace

int runStability(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Map where each integrator fails: time step (1/30 to 1/7680 s) against stiffness "
        "(1× to 10⁴×) for every method on drape, press and compress. Writes CSV and one "
        "heat map per method."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("stability"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("output-dir"),
         QStringLiteral("Folder for stability.csv and the PNGs (default: stability)."),
         QStringLiteral("dir"), QStringLiteral("stability")},
        {QStringLiteral("quick"), QStringLiteral("A 3 × 3 grid, for CI.")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    const bool quick = parser.isSet(QStringLiteral("quick"));
    const std::vector<double> steps =
        quick ? std::vector<double>{1.0 / 30, 1.0 / 480, 1.0 / 7680}
              : std::vector<double>{1.0 / 30,  1.0 / 60,   1.0 / 120,  1.0 / 240, 1.0 / 480,
                                    1.0 / 960, 1.0 / 1920, 1.0 / 3840, 1.0 / 7680};
    const std::vector<double> scales =
        quick ? std::vector<double>{1, 100, 10000} : std::vector<double>{1, 10, 100, 1000, 10000};
    const QDir dir =
        requireFolder(QStringLiteral("output-dir"), parser.value(QStringLiteral("output-dir")));
    const QString csvPath = dir.filePath(QStringLiteral("stability.csv"));
    auto pngPath = [&](const Method& m) {
        return dir.filePath(QStringLiteral("stability_%1.png").arg(QLatin1String(m.name)));
    };
    // Every target is checked before the minute of work, not after it.
    requireWritable(QStringLiteral("output-dir"), csvPath);
    for (const Method& m : kMethods) requireWritable(QStringLiteral("output-dir"), pngPath(m));
    QString csv;
    QTextStream out(&csv), err(stderr);
    out << "method,scene,dt,stiffness_scale,a,outcome,steps,end_strain,peak_kinetic_J\n";
    for (const Method& m : kMethods) {
        std::vector<std::vector<std::vector<StabilityResult>>> results(3);
        int failures = 0;
        for (int s = 0; s < 3; ++s) {
            results[s].resize(scales.size());
            for (std::size_t r = 0; r < scales.size(); ++r)
                for (double dt : steps) {
                    StabilityCase c;
                    c.scene = kScenes[s];
                    c.integrator = m.integrator;
                    c.sweeps = m.sweeps;
                    c.clampCompressed = m.clamp;
                    c.dt = dt;
                    c.stiffnessScale = scales[r];
                    c.seconds = 1.0; // shorter horizons judge the start's transients
                    if (c.integrator == "backward-euler") c.maxSteps = quick ? 60 : 500;
                    const StabilityResult res = probeStability(c);
                    results[s][r].push_back(res);
                    failures += res.outcome != StabilityOutcome::Stable;
                    out << m.name << ',' << kScenes[s] << ',' << dt << ',' << scales[r] << ','
                        << res.a << ',' << outcomeName(res.outcome) << ',' << res.steps << ','
                        << res.endStrain << ',' << res.peakKinetic << '\n';
                }
        }
        const QString png = pngPath(m);
        QString error;
        if (!writePng(heatMap(m, steps, scales, results), png, &error)) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
        err << QStringLiteral("%1: %2 of %3 runs failed -> %4\n")
                   .arg(QLatin1String(m.name), -18)
                   .arg(failures)
                   .arg(3 * steps.size() * scales.size())
                   .arg(png)
            << Qt::flush;
    }
    out.flush();
    QString error;
    if (!writeOutputFile(csvPath, csv.toUtf8(), &error)) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    QTextStream(stdout) << "wrote " << csvPath << '\n';
    return 0;
}

} // namespace pf::cli
