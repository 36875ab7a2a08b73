#include "ScalingBench.h"

#include "BuildTuning.h"
#include "CommandLine.h"
#include "OutputFile.h"
#include "PngFile.h"
#include "Scenes.h"
#include "Simulation.h"
#include "WorkerPool.h"

#include <QChart>
#include <QChartView>
#include <QDir>
#include <QElapsedTimer>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <vector>

namespace pf::cli {

namespace {

// What the sheet is doing while it is timed.
enum class Load { Pressed, Swinging, Resting };

const char* loadName(Load l) {
    switch (l) {
    case Load::Pressed:
        return "press (tool crumpling)";
    case Load::Swinging:
        return "drape (swinging)";
    case Load::Resting:
        return "at rest on the desk";
    }
    return "?";
}

struct Sample {
    Load load = Load::Pressed;
    int threads = 1;
    int resolution = 0;
    Index vertices = 0;
    double springs = 0;        // mean over the timed steps (breaks add springs)
    double stepsPerSecond = 0; // median of the repeats
    double nsPerSpring = 0;    // per step
};

// The editor's settings (gravity outside the filter) with the integrator asked for.
World sceneFor(Load load, int resolution, const QString& integrator) {
    SceneOptions o;
    o.resolution = resolution;
    World w = *makeScene(load == Load::Swinging ? "drape" : "press", o);
    w.params.gravityOutsideFilter = true;
    w.params.integrator = integrator.toStdString();
    if (load == Load::Resting) {
        // The press sheet without its sphere: a flat sheet lying on the desk.
        w.script.sphereKeys.clear();
        w.sphere.active = false;
    }
    return w;
}

// Steps a second of simulated time the editor and the scenes run at (1/dt).
double realTimeRate(const QString& integrator) {
    return 1.0 / sceneFor(Load::Resting, 13, integrator).params.dt;
}

// `warmup` steps untimed, then up to `timed` steps timed, fewer on a sheet so large that
// they would take more than kTimedSeconds of wall time (at the warm-up's pace).
constexpr double kTimedSeconds = 3.0;

Sample measure(Load load, int resolution, const QString& integrator, int threads, int warmup,
               int timed, int repeats) {
    Sample s;
    s.load = load;
    s.threads = threads;
    s.resolution = resolution;
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) {
        Simulation sim(sceneFor(load, resolution, integrator));
        sim.setThreads(threads);
        QElapsedTimer clock;
        clock.start();
        for (int k = 0; k < warmup; ++k)
            if (sim.step() != StepStatus::Ok) return s;
        const double warmupRate = warmup / (static_cast<double>(clock.nsecsElapsed()) * 1e-9);
        const int steps = std::clamp(static_cast<int>(warmupRate * kTimedSeconds), 30, timed);
        const double before = static_cast<double>(sim.world().sheet.springs.size());
        clock.restart();
        for (int k = 0; k < steps; ++k)
            if (sim.step() != StepStatus::Ok) return s;
        const double seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
        rates.push_back(steps / seconds);
        s.vertices = sim.world().sheet.verts.size();
        s.springs = 0.5 * (before + static_cast<double>(sim.world().sheet.springs.size()));
    }
    std::sort(rates.begin(), rates.end());
    s.stepsPerSecond = rates[rates.size() / 2];
    s.nsPerSpring = 1e9 / (s.stepsPerSecond * s.springs);
    return s;
}

QImage drawChart(const std::vector<Sample>& samples, const QString& integrator,
                 const std::vector<int>& threadCounts) {
    auto* chart = new QChart;
    chart->setTitle(QStringLiteral("%1: cost of a step per spring against the sheet's size "
                                   "(log–log; the work of all threads, per wall-clock second)")
                        .arg(integrator));
    auto* x = new QLogValueAxis;
    x->setTitleText(QStringLiteral("springs"));
    x->setLabelFormat(QStringLiteral("%.0f"));
    auto* y = new QLogValueAxis;
    y->setTitleText(QStringLiteral("ns per spring per step"));
    y->setLabelFormat(QStringLiteral("%.3g"));
    // Powers of two: a cost that changes by less than ten times still gets labels.
    y->setBase(2.0);
    x->setMinorTickCount(8);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {0, 0};
    const QColor colours[] = {QColor(200, 60, 40), QColor(40, 110, 200), QColor(60, 150, 70)};
    for (int threads : threadCounts)
        for (Load load : {Load::Pressed, Load::Swinging, Load::Resting}) {
            auto* series = new QLineSeries;
            series->setName(QStringLiteral("%1, %2 thread%3")
                                .arg(QLatin1String(loadName(load)))
                                .arg(threads)
                                .arg(threads == 1 ? QString() : QStringLiteral("s")));
            series->setPointsVisible(true);
            QPen pen(colours[static_cast<int>(load)]);
            pen.setWidthF(2.0);
            if (threads > 1) pen.setStyle(Qt::DashLine);
            series->setPen(pen);
            for (const Sample& s : samples) {
                if (s.load != load || s.threads != threads || !(s.nsPerSpring > 0)) continue;
                series->append(s.springs, s.nsPerSpring);
                lo[0] = std::min(lo[0], s.springs);
                hi[0] = std::max(hi[0], s.springs);
                lo[1] = std::min(lo[1], s.nsPerSpring);
                hi[1] = std::max(hi[1], s.nsPerSpring);
            }
            chart->addSeries(series);
            series->attachAxis(x);
            series->attachAxis(y);
        }
    // Log axes do not follow the data by themselves.
    if (hi[0] > 0) {
        x->setRange(lo[0] / 1.5, hi[0] * 1.5);
        y->setRange(lo[1] / 2, hi[1] * 2);
    }
    chart->legend()->setAlignment(Qt::AlignBottom);
    QChartView view(chart);
    view.setRenderHint(QPainter::Antialiasing);
    view.resize(1000, 700);
    return view.grab().toImage();
}

} // namespace

int runScalingBench(const ScalingOptions& options) {
    const std::vector<int> resolutions =
        options.quick ? std::vector<int>{13, 19, 27} : std::vector<int>{19, 27, 38, 54, 76, 108};
    // The press sphere ploughs the sheet from about 0.15 s to 0.75 s: the warm-up ends
    // as it bites and the timed steps end before it lifts off.
    const int warmup = 36, timed = options.quick ? 60 : 144, repeats = 3;
    std::vector<int> threadCounts{1};
    if (options.threads > 1) threadCounts.push_back(options.threads);
    const QDir dir = requireFolder(QStringLiteral("output-dir"), options.outputDir);
    const QString csvPath = dir.filePath(QStringLiteral("scaling.csv"));
    const QString pngPath = dir.filePath(QStringLiteral("scaling.png"));
    requireWritable(QStringLiteral("output-dir"), csvPath);
    requireWritable(QStringLiteral("output-dir"), pngPath);

    QTextStream out(stdout), err(stderr);
    out << "build: " << QString::fromStdString(buildTuning()) << '\n'
        << "integrator: " << options.integrator << " (the editor's settings)\n"
        << "threads: " << threadCounts.back() << " of the machine's "
        << WorkerPool::machineThreads() << "; each sheet is timed on "
        << (threadCounts.size() > 1 ? QStringLiteral("1 and %1").arg(threadCounts.back())
                                    : QStringLiteral("1"))
        << '\n'
        << QStringLiteral("%1 %2 %3 %4 %5 %6 %7\n")
               .arg(QStringLiteral("load"), -24)
               .arg(QStringLiteral("threads"), 7)
               .arg(QStringLiteral("resolution"), 10)
               .arg(QStringLiteral("vertices"), 9)
               .arg(QStringLiteral("springs"), 9)
               .arg(QStringLiteral("steps/s"), 9)
               .arg(QStringLiteral("ns/spring"), 10)
        << Qt::flush;
    std::vector<Sample> samples;
    for (Load load : {Load::Pressed, Load::Swinging, Load::Resting})
        for (int resolution : resolutions)
            for (int threads : threadCounts) {
                const Sample s =
                    measure(load, resolution, options.integrator, threads, warmup, timed, repeats);
                if (!(s.stepsPerSecond > 0)) {
                    err << "paperfold: the " << loadName(load) << " sheet at resolution "
                        << resolution << " blew up; it is left out\n";
                    continue;
                }
                samples.push_back(s);
                out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7\n")
                           .arg(QLatin1String(loadName(load)), -24)
                           .arg(threads, 7)
                           .arg(resolution, 10)
                           .arg(s.vertices, 9)
                           .arg(std::lround(s.springs), 9)
                           .arg(s.stepsPerSecond, 9, 'f', 0)
                           .arg(s.nsPerSpring, 10, 'f', 1)
                    << Qt::flush;
            }

    // The largest sheet measured that keeps up with real time, and where the limit lies:
    // the first sheet that did not keep up, scaled down by how far it fell short (the
    // cost per spring changes little between neighbouring sizes), or, if every sheet
    // kept up, the largest one scaled up.
    const double rate = realTimeRate(options.integrator);
    for (int threads : threadCounts)
        for (Load load : {Load::Pressed, Load::Swinging}) {
            double keptUp = 0, estimate = 0;
            for (const Sample& s : samples) { // by growing size
                if (s.load != load || s.threads != threads) continue;
                estimate = s.springs * s.stepsPerSecond / rate;
                if (s.stepsPerSecond < rate) break;
                keptUp = s.springs;
            }
            if (!(estimate > 0)) continue;
            out << QStringLiteral("largest real-time sheet (%1 steps/s), %2, %3 thread(s): %4 "
                                  "springs measured, about %5\n")
                       .arg(rate, 0, 'f', 0)
                       .arg(QLatin1String(loadName(load)))
                       .arg(threads)
                       .arg(std::lround(keptUp))
                       .arg(std::lround(std::max(estimate, keptUp)));
        }
    // Speed-up on more threads, sheet by sheet (the same sheet, timed side by side).
    if (threadCounts.size() > 1)
        for (const Sample& many : samples) {
            if (many.threads == 1) continue;
            for (const Sample& one : samples)
                if (one.threads == 1 && one.load == many.load && one.resolution == many.resolution)
                    out << QStringLiteral("speed-up on %1 threads, %2, resolution %3: %4\n")
                               .arg(many.threads)
                               .arg(QLatin1String(loadName(many.load)))
                               .arg(many.resolution)
                               .arg(many.stepsPerSecond / one.stepsPerSecond, 0, 'f', 2);
        }
    double active = 0, resting = 0;
    for (const Sample& s : samples) {
        if (s.resolution != resolutions.back() || s.threads != 1) continue;
        if (s.load == Load::Pressed) active = s.nsPerSpring;
        if (s.load == Load::Resting) resting = s.nsPerSpring;
    }
    if (active > 0 && resting > 0)
        out << QStringLiteral("at rest / crumpled, resolution %1: %2\n")
                   .arg(resolutions.back())
                   .arg(resting / active, 0, 'f', 3);

    QString csv;
    QTextStream c(&csv);
    c << "integrator,threads,load,resolution,vertices,springs,steps_per_second,ns_per_spring_"
         "step\n";
    for (const Sample& s : samples)
        c << options.integrator << ',' << s.threads << ',' << loadName(s.load) << ','
          << s.resolution << ',' << s.vertices << ',' << s.springs << ',' << s.stepsPerSecond << ','
          << s.nsPerSpring << '\n';
    c.flush();
    QString error;
    if (!writeOutputFile(csvPath, csv.toUtf8(), &error) ||
        !writePng(drawChart(samples, options.integrator, threadCounts), pngPath, &error)) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    out << "wrote " << csvPath << " and " << pngPath << '\n';
    return 0;
}

} // namespace pf::cli
