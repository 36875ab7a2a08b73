#include "FiguresCommand.h"

#include "Camera.h"
#include "CommandLine.h"
#include "OffscreenRenderer.h"
#include "OutputFile.h"
#include "PngFile.h"
#include "Scenes.h"
#include "SheetSnapshot.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <QDir>
#include <QPainter>
#include <QTextStream>
#include <vector>

namespace pf::cli {

namespace {

enum class Varied { Phi, Psi, Sigma };

// One of the paper's figures: a scene, the parameter it varies (the paper's values) and
// the other parameters held as the caption says.
struct Figure {
    QString file, title;
    const char* scene;
    Varied varied;
    std::vector<double> values;
    double phi, psi;
};

const std::vector<Figure>& figures() {
    static const std::vector<Figure> all{
        {QStringLiteral("fig10_phi"),
         QStringLiteral("Fig. 10: φ, with ψ = 1 (press)"),
         "press",
         Varied::Phi,
         {0.0, 0.5, 0.75, 1.0},
         0.0,
         1.0},
        {QStringLiteral("fig11_psi_press"),
         QStringLiteral("Fig. 11: ψ, with φ = 0.5 (press)"),
         "press",
         Varied::Psi,
         {0.0, 0.25, 0.75, 1.0},
         0.5,
         0.0},
        {QStringLiteral("fig11_psi_compress"),
         QStringLiteral("Fig. 11: ψ, with φ = 0.5 (compress)"),
         "compress",
         Varied::Psi,
         {0.0, 0.25, 0.75, 1.0},
         0.5,
         0.0},
        {QStringLiteral("fig12_sigma"),
         QStringLiteral("Fig. 12: σ, with φ = 0.5, ψ = 0.25 (press)"),
         "press",
         Varied::Sigma,
         {0.0, 0.5, 1.0},
         0.5,
         0.25},
    };
    return all;
}

QString symbol(Varied v) {
    return v == Varied::Phi   ? QStringLiteral("φ")
           : v == Varied::Psi ? QStringLiteral("ψ")
                              : QStringLiteral("σ");
}

// What a run left: the counts Fig. 10 and 11 are about.
struct Counts {
    Index breaks = 0, inserted = 0;
    Index splitHalves = 0; // breaks of an edge that an earlier break made
};

Counts countDamage(const Sheet& s, Index startVertices, Index startSprings) {
    Counts c;
    c.inserted = s.verts.size() - startVertices;
    for (const DamageEvent& ev : s.events) {
        if (!ev.active || ev.kind != EventKind::Break) continue;
        ++c.breaks;
        // Springs are only appended while a scene runs, so a spring past the starting
        // ones was made by a break or a hinge; only a break's halves can break.
        if (ev.edge >= startSprings) ++c.splitHalves;
    }
    return c;
}

struct Run {
    bool ok = false;
    SheetSnapshot snapshot;
    Counts counts;
};

// The figure's scene for `seed` with the varied parameter at `value` (σ is only a look),
// in the paper's integrator, after `steps` steps.
Run simulateFigure(const Figure& f, int seed, double value, int steps) {
    SceneOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    World w = *makeScene(f.scene, o);
    // The paper's figures, in the paper's integrator (as the editor ran it before xpbd
    // became the default): xpbd's free sheet slides from the sphere and hardly breaks.
    w.params.integrator = "jacobi";
    w.params.gravityOutsideFilter = true;
    w.params.phi = f.varied == Varied::Phi ? value : f.phi;
    w.params.psi = f.varied == Varied::Psi ? value : f.psi;
    const Index v0 = w.sheet.verts.size(), s0 = w.sheet.springs.size();
    Simulation sim(std::move(w));
    Run run;
    for (int k = 0; k < steps; ++k)
        if (sim.step() != StepStatus::Ok) return run;
    run.ok = true;
    run.snapshot = makeSnapshot(sim);
    run.counts = countDamage(sim.world().sheet, v0, s0);
    return run;
}

constexpr int kCellWidth = 320, kCellHeight = 200, kCaption = 38, kLabelWidth = 90, kTitle = 34;

} // namespace

int runFigures(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Reproduce the paper's Fig. 10 (φ), Fig. 11 (ψ, in press and compress) and Fig. 12 (σ) "
        "headless: one contact sheet per figure, a row per parameter value and a column per "
        "seed, with the breaks counted under each picture; and figures.csv with every count. "
        "The paper's jacobi integrator, gravity outside the filter."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("figures"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("output-dir"), QStringLiteral("Folder to write into (default: figures)."),
         QStringLiteral("dir"), QStringLiteral("figures")},
        {QStringLiteral("seeds"), QStringLiteral("Seeds per value, 1-8 (default 3)."),
         QStringLiteral("n")},
        {QStringLiteral("steps"),
         QStringLiteral("Steps each run is simulated before its picture (default 480: 2 s)."),
         QStringLiteral("n")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    const int seeds =
        static_cast<int>(integerOption(parser, QStringLiteral("seeds"), 1, 8).value_or(3));
    const int steps =
        static_cast<int>(integerOption(parser, QStringLiteral("steps"), 1, 100'000).value_or(480));
    const QDir dir =
        requireFolder(QStringLiteral("output-dir"), parser.value(QStringLiteral("output-dir")));
    const QString csvPath = dir.filePath(QStringLiteral("figures.csv"));
    requireWritable(QStringLiteral("output-dir"), csvPath);
    for (const Figure& f : figures())
        requireWritable(QStringLiteral("output-dir"),
                        dir.filePath(f.file + QStringLiteral(".png")));

    QTextStream out(stdout), err(stderr);
    QString error;
    auto renderer = OffscreenRenderer::create(kCellWidth, kCellHeight, &error);
    if (!renderer) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    QString csv;
    QTextStream table(&csv);
    table << "figure,scene,parameter,value,seed,breaks,inserted_vertices,split_halves\n";
    for (const Figure& f : figures()) {
        const int rows = static_cast<int>(f.values.size());
        QImage sheet(kLabelWidth + seeds * kCellWidth, kTitle + rows * (kCellHeight + kCaption),
                     QImage::Format_RGB32);
        sheet.fill(Qt::white);
        QPainter painter(&sheet);
        QFont font = painter.font();
        font.setPixelSize(15);
        painter.setFont(font);
        painter.setPen(Qt::black);
        painter.drawText(QRect(8, 0, sheet.width() - 16, kTitle), Qt::AlignVCenter, f.title);
        out << f.title << '\n';
        // Fig. 12 varies only the look: each seed is simulated once and drawn at each σ.
        std::vector<Run> sigmaRuns;
        if (f.varied == Varied::Sigma)
            for (int seed = 1; seed <= seeds; ++seed)
                sigmaRuns.push_back(simulateFigure(f, seed, 0.0, steps));
        for (int row = 0; row < rows; ++row) {
            const double value = f.values[row];
            const int top = kTitle + row * (kCellHeight + kCaption);
            painter.drawText(QRect(0, top, kLabelWidth, kCellHeight), Qt::AlignCenter,
                             QStringLiteral("%1 = %2").arg(symbol(f.varied)).arg(value));
            long totalBreaks = 0, totalInserted = 0;
            for (int seed = 1; seed <= seeds; ++seed) {
                const Run run = f.varied == Varied::Sigma ? sigmaRuns[seed - 1]
                                                          : simulateFigure(f, seed, value, steps);
                if (!run.ok) {
                    err << "paperfold: the simulation diverged (" << f.file << ", "
                        << symbol(f.varied) << " = " << value << ", seed " << seed << ")\n";
                    return 3;
                }
                RenderOptions options;
                options.sigma = f.varied == Varied::Sigma ? value : 1.0;
                options.legend = false;
                OrbitCamera camera = *namedView("iso");
                camera.fitPoints(run.snapshot.x, double(kCellWidth) / kCellHeight);
                const int left = kLabelWidth + (seed - 1) * kCellWidth;
                painter.drawImage(left, top, renderer->render(run.snapshot, camera, options));
                const Counts& c = run.counts;
                painter.drawText(QRect(left, top + kCellHeight, kCellWidth, kCaption),
                                 Qt::AlignCenter,
                                 QStringLiteral("%1 breaks, %2 inserted, %3 split halves")
                                     .arg(c.breaks)
                                     .arg(c.inserted)
                                     .arg(c.splitHalves));
                table << f.file << ',' << f.scene << ',' << symbol(f.varied) << ',' << value << ','
                      << seed << ',' << c.breaks << ',' << c.inserted << ',' << c.splitHalves
                      << '\n';
                totalBreaks += c.breaks;
                totalInserted += c.inserted;
            }
            out << QStringLiteral("  %1 = %2: mean %3 breaks, %4 inserted vertices\n")
                       .arg(symbol(f.varied))
                       .arg(value, -5)
                       .arg(double(totalBreaks) / seeds, 0, 'f', 1)
                       .arg(double(totalInserted) / seeds, 0, 'f', 1);
        }
        painter.end();
        const QString path = dir.filePath(f.file + QStringLiteral(".png"));
        if (!writePng(sheet, path, &error)) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
    }
    if (!writeOutputFile(csvPath, csv.toUtf8(), &error)) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    out << "wrote " << figures().size() << " contact sheets and " << csvPath << '\n';
    return 0;
}

} // namespace pf::cli
