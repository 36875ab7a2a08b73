#include "BenchCommand.h"

#include "BuildTuning.h"
#include "CommandLine.h"
#include "Integrator.h"
#include "OutputFile.h"
#include "PngFile.h"
#include "ScalingBench.h"
#include "SheetStats.h"
#include "SolverMetrics.h"

#include <QChart>
#include <QChartView>
#include <QDir>
#include <QElapsedTimer>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace pf::cli {

namespace {

struct Config {
    QString family; // one chart series per family
    SimParams params;
};

struct Row {
    QString family, scene;
    double dt = 0, cost = 0, error = INFINITY, strain = 0, stretch = 0, fall = 0, energy = 0;
    int sweeps = 0, substeps = 0;
    bool stable = true, ownReference = false;
};

std::vector<Config> configurations(const std::vector<double>& steps, bool quick) {
    struct Family {
        const char* name;
        const char* integrator;
        int sweeps;
        bool outside;
        int substeps = 0;
    };
    std::vector<Family> families{{"jacobi K=0 (paper)", "jacobi", 0, false},
                                 {"jacobi K=1 (paper)", "jacobi", 1, false},
                                 {"jacobi K=1 + gravity outside", "jacobi", 1, true},
                                 {"jacobi K=4 + gravity outside", "jacobi", 4, true},
                                 {"symplectic Euler", "symplectic", 0, false},
                                 {"backward Euler (CG)", "backward-euler", 0, false},
                                 {"xpbd office paper (40 sub-steps)", "xpbd", 0, false, 40}};
    if (!quick) {
        families.push_back({"xpbd office paper (10 sub-steps)", "xpbd", 0, false, 10});
        families.insert(families.begin() + 2, {"jacobi K=4 (paper)", "jacobi", 4, false});
        families.push_back({"jacobi-scalar K=1 (paper)", "jacobi-scalar", 1, false});
        families.push_back({"jacobi-scalar K=1 + gravity outside", "jacobi-scalar", 1, true});
    }
    std::vector<Config> out;
    for (const Family& f : families)
        for (double dt : steps) {
            Config c;
            c.family = QLatin1String(f.name);
            c.params.integrator = f.integrator;
            c.params.iterations = f.sweeps;
            c.params.gravityOutsideFilter = f.outside;
            if (f.substeps > 0) c.params.substeps = f.substeps;
            c.params.dt = dt;
            out.push_back(c);
        }
    return out;
}

// Points no other point beats in both cost and error, by increasing cost.
std::vector<const Row*> paretoFront(const std::vector<Row>& rows) {
    std::vector<const Row*> ok;
    for (const Row& r : rows)
        if (r.stable && !r.ownReference && std::isfinite(r.error) && r.error > 0) ok.push_back(&r);
    std::sort(ok.begin(), ok.end(), [](const Row* a, const Row* b) { return a->cost < b->cost; });
    std::vector<const Row*> front;
    double best = INFINITY;
    for (const Row* r : ok)
        if (r->error < best) {
            front.push_back(r);
            best = r->error;
        }
    return front;
}

QImage drawChart(const std::vector<Row>& rows, const QString& scene) {
    auto* chart = new QChart;
    chart->setTitle(
        QStringLiteral("%1: cost against trajectory error (log–log; dashed: Pareto front)")
            .arg(scene) +
        QStringLiteral("; xpbd's error is against its own run at 1/16 of the smallest step"));
    auto* x = new QLogValueAxis;
    x->setTitleText(QStringLiteral("wall seconds per simulated second"));
    x->setLabelFormat(QStringLiteral("%.0e"));
    auto* y = new QLogValueAxis;
    y->setTitleText(QStringLiteral("trajectory error / sheet diagonal"));
    y->setLabelFormat(QStringLiteral("%.0e"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    std::map<QString, QScatterSeries*> series;
    std::vector<Row> sceneRows;
    for (const Row& r : rows) {
        if (r.scene != scene) continue;
        sceneRows.push_back(r);
        if (!r.stable || !std::isfinite(r.error) || r.error <= 0) continue;
        auto& s = series[r.family];
        if (!s) {
            s = new QScatterSeries;
            s->setName(r.family);
            s->setMarkerSize(11);
            // Another physics, another error: its own shape, whatever colour it gets.
            if (r.ownReference) s->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
            chart->addSeries(s);
            s->attachAxis(x);
            s->attachAxis(y);
        }
        s->append(r.cost, r.error);
    }
    auto* front = new QLineSeries;
    front->setName(QStringLiteral("Pareto front"));
    QPen pen(Qt::black);
    pen.setStyle(Qt::DashLine);
    front->setPen(pen);
    for (const Row* r : paretoFront(sceneRows)) front->append(r->cost, r->error);
    chart->addSeries(front);
    front->attachAxis(x);
    front->attachAxis(y);
    // Log axes do not follow the data by themselves.
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {0, 0};
    for (const Row& r : sceneRows) {
        if (!r.stable || !std::isfinite(r.error) || r.error <= 0) continue;
        lo[0] = std::min(lo[0], r.cost);
        hi[0] = std::max(hi[0], r.cost);
        lo[1] = std::min(lo[1], r.error);
        hi[1] = std::max(hi[1], r.error);
    }
    if (hi[0] > 0) {
        x->setRange(lo[0] / 2, hi[0] * 2);
        y->setRange(lo[1] / 2, hi[1] * 2);
    }
    chart->legend()->setAlignment(Qt::AlignRight);
    QChartView view(chart);
    view.setRenderHint(QPainter::Antialiasing);
    view.resize(1400, 800);
    return view.grab().toImage();
}

} // namespace

int runBench(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Speed against accuracy for every integrator configuration (method × sweeps × time "
        "step, i.e. sub-steps of a 60 Hz frame) on the canonical scenes. Prints a table and "
        "writes bench.csv and one chart per scene, bench_<scene>.png. With --scaling: the "
        "cost per spring against the sheet's size instead (scaling.csv, scaling.png)."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("bench"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("output-dir"),
         QStringLiteral("Folder for the CSV and charts (default: bench)."), QStringLiteral("dir"),
         QStringLiteral("bench")},
        {QStringLiteral("quick"),
         QStringLiteral("Fewer configurations on drape and drop: under a minute, for CI. With "
                        "--scaling: three small sheets.")},
        {QStringLiteral("scaling"),
         QStringLiteral("Instead: the cost per spring against the sheet's size, crumpled, "
                        "swinging and at rest, and the largest real-time sheet (scaling.csv, "
                        "scaling.png).")},
        {QStringLiteral("integrator"),
         QStringLiteral("With --scaling: the integrator measured (default: the default "
                        "integrator, %1).")
             .arg(QString::fromStdString(SimParams{}.integrator)),
         QStringLiteral("name"), QString::fromStdString(SimParams{}.integrator)},
    });
    addThreadsOption(parser);
    if (!parseCommand(parser, arguments)) return 0;
    const bool quick = parser.isSet(QStringLiteral("quick"));
    const int threads = threadsOption(parser);
    if (parser.isSet(QStringLiteral("scaling"))) {
        ScalingOptions scaling;
        scaling.quick = quick;
        scaling.integrator = QString::fromStdString(integratorOption(parser));
        scaling.outputDir = parser.value(QStringLiteral("output-dir"));
        scaling.threads = threads;
        return runScalingBench(scaling);
    }
    if (parser.isSet(QStringLiteral("integrator")))
        throw UsageError{QStringLiteral("--integrator: only with --scaling (the bench runs every "
                                        "integrator)")};
    const std::vector<double> steps = quick ? std::vector<double>{1.0 / 60, 1.0 / 240, 1.0 / 960}
                                            : std::vector<double>{1.0 / 60,  1.0 / 120, 1.0 / 240,
                                                                  1.0 / 480, 1.0 / 960, 1.0 / 1920};
    const std::vector<QString> scenes =
        quick ? std::vector<QString>{QStringLiteral("drape"), QStringLiteral("drop")}
              : std::vector<QString>{QStringLiteral("drape"), QStringLiteral("drop"),
                                     QStringLiteral("press"), QStringLiteral("compress")};
    const int resolution = 9;
    const double horizon = 0.25; // seconds of simulated time
    const int repeats = 3;
    const QDir dir =
        requireFolder(QStringLiteral("output-dir"), parser.value(QStringLiteral("output-dir")));

    const QString csvPath = dir.filePath(QStringLiteral("bench.csv"));
    auto chartPath = [&](const QString& scene) {
        return dir.filePath(QStringLiteral("bench_%1.png").arg(scene));
    };
    // Every target is checked before minutes of work, not after them.
    requireWritable(QStringLiteral("output-dir"), csvPath);
    for (const QString& scene : scenes)
        requireWritable(QStringLiteral("output-dir"), chartPath(scene));

    QTextStream out(stdout), err(stderr);
    std::vector<Row> rows;
    for (const QString& scene : scenes) {
        // References: backward Euler solved exactly at a step 64 times smaller than the
        // smallest benchmarked, and xpbd at 16 times smaller (its sub-steps are already
        // 40 times smaller again), each checked against twice its step.
        SimParams springs;
        springs.integrator = "backward-euler";
        springs.dt = steps.back() / 64;
        SimParams paper;
        paper.integrator = "xpbd";
        paper.dt = steps.back() / 16;
        World reference[2];
        for (int k = 0; k < 2; ++k) {
            SimParams ref = k == 0 ? springs : paper;
            reference[k] = labWorld(scene.toStdString(), resolution, ref);
            ref.dt *= 2;
            World coarser = labWorld(scene.toStdString(), resolution, ref);
            advanceFor(reference[k], horizon);
            advanceFor(coarser, horizon);
            const double refError = trajectoryError(coarser.sheet, reference[k].sheet);
            err << QStringLiteral("%1: %2 reference h = 1/%3, its own change at twice the "
                                  "step: %4\n")
                       .arg(scene, QLatin1String(ref.integrator.c_str()))
                       .arg(std::lround(1.0 / (ref.dt / 2)))
                       .arg(refError, 0, 'g', 3)
                << Qt::flush;
        }

        for (const Config& c : configurations(steps, quick)) {
            Row r;
            r.family = c.family;
            r.scene = scene;
            r.dt = c.params.dt;
            r.sweeps = c.params.iterations;
            // Paper with its real stiffness is a different physics from the paper's 100 N/m
            // springs: its error is against its own run at a far smaller step, and it is
            // charted beside the springs' Pareto front, not on it.
            r.ownReference = keepsEdgeLengths(c.params.integrator);
            r.substeps = r.ownReference ? c.params.substeps : 0;
            std::vector<double> times;
            World last;
            for (int k = 0; k < repeats; ++k) {
                World w = labWorld(scene.toStdString(), resolution, c.params);
                QElapsedTimer t;
                t.start();
                r.stable = advanceFor(w, horizon) && r.stable;
                times.push_back(t.nsecsElapsed() * 1e-9 / horizon);
                last = std::move(w);
                if (!r.stable) break;
            }
            std::sort(times.begin(), times.end());
            r.cost = times[times.size() / 2];
            if (r.stable) {
                r.error = trajectoryError(last.sheet, reference[r.ownReference ? 1 : 0].sheet);
                const SheetStats stats = computeStats(last.sheet);
                r.strain = stats.maxStrain;
                r.stretch = stats.maxStretch;
            }
            r.fall = freeFallRatio(c.params);
            // The undamped energy is the springs' (½ k (l − L)²): it has no meaning for
            // xpbd's constraints.
            r.energy = r.ownReference
                           ? NAN
                           : energyRatio(scene.toStdString(), resolution, c.params, horizon);
            rows.push_back(r);
        }
    }

    QString csv;
    QTextStream c(&csv);
    c << "scene,method,dt,substeps_per_60Hz_frame,sweeps,xpbd_substeps,cost_s_per_s,"
         "trajectory_error,reference,max_strain,max_stretch,free_fall_ratio,energy_ratio_undamped,"
         "stable\n";
    // Costs depend on what the compiler could assume about the processor.
    out << "build: " << QString::fromStdString(buildTuning()) << '\n';
    // The lab's sheets (9 × 9 vertices) are far below the size worth splitting.
    out << "threads: " << threads << " (the lab's sheets are small enough to run on one)\n";
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8\n")
               .arg(QStringLiteral("scene"), -9)
               .arg(QStringLiteral("method"), -36)
               .arg(QStringLiteral("h"), -7)
               .arg(QStringLiteral("cost s/s"), 10)
               .arg(QStringLiteral("error"), 10)
               .arg(QStringLiteral("strain"), 8)
               .arg(QStringLiteral("stretch"), 8)
               .arg(QStringLiteral("a/g"), 8);
    for (const Row& r : rows) {
        const long sub = std::lround((1.0 / 60) / r.dt);
        c << r.scene << ',' << r.family << ',' << r.dt << ',' << sub << ',' << r.sweeps << ','
          << r.substeps << ',' << r.cost << ',' << r.error << ','
          << (r.ownReference ? "xpbd" : "backward-euler") << ',' << r.strain << ',' << r.stretch
          << ',' << r.fall << ',' << r.energy << ',' << (r.stable ? 1 : 0) << '\n';
        out << QStringLiteral("%1 %2 1/%3 %4 %5 %6 %7 %8\n")
                   .arg(r.scene, -9)
                   .arg(r.family, -36)
                   .arg(std::lround(1.0 / r.dt), -5)
                   .arg(r.cost, 10, 'g', 3)
                   .arg(r.stable ? QString::number(r.error, 'g', 3) : QStringLiteral("unstable"),
                        10)
                   .arg(r.strain, 8, 'g', 3)
                   .arg(r.stretch, 8, 'g', 3)
                   .arg(r.fall, 8, 'f', 4);
    }
    c.flush();
    QString error;
    if (!writeOutputFile(csvPath, csv.toUtf8(), &error)) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    for (const QString& scene : scenes)
        if (!writePng(drawChart(rows, scene), chartPath(scene), &error)) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
    out << "wrote " << csvPath << " and the charts in " << dir.path() << '\n';
    return 0;
}

} // namespace pf::cli
