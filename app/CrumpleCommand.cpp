#include "CrumpleCommand.h"

#include "CommandLine.h"
#include "CreaseNetwork.h"
#include "CrumpleCycles.h"
#include "OutputFile.h"
#include "PngFile.h"
#include "Scenes.h"

#include <QDir>
#include <QPainter>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace pf::cli {

namespace {

constexpr int kMapWidth = 210, kMapHeight = 297, kMapCaption = 36, kMapsPerRow = 5;

// The crease edges of `sheet` drawn on the flat paper at 1 px per mm, as a crumpled
// sheet flattened on a scanner shows its creases.
void drawCreaseMap(QPainter& painter, const QRect& area, const Sheet& sheet) {
    double minX = 1e9, maxX = -1e9, minZ = 1e9, maxZ = -1e9;
    for (const Vec2& X : sheet.verts.X) {
        minX = std::min(minX, X.x());
        maxX = std::max(maxX, X.x());
        minZ = std::min(minZ, X.y());
        maxZ = std::max(maxZ, X.y());
    }
    const double scale =
        std::min((area.width() - 8) / (maxX - minX), (area.height() - 8) / (maxZ - minZ));
    const auto point = [&](const Vec2& X) {
        return QPointF(area.center().x() + (X.x() - 0.5 * (minX + maxX)) * scale,
                       area.center().y() + (X.y() - 0.5 * (minZ + maxZ)) * scale);
    };
    const auto at = [&](Index i) { return point(sheet.verts.X[i]); };
    painter.setPen(QPen(QColor(170, 170, 170), 1));
    painter.setBrush(QColor(250, 248, 240));
    painter.drawRect(QRectF(point(Vec2(minX, minZ)), point(Vec2(maxX, maxZ))));
    painter.setPen(QPen(QColor(30, 30, 90), 1));
    for (const CreaseEdge& e : creaseEdges(sheet)) painter.drawLine(at(e.a), at(e.b));
}

// Bins √2 apart from 1 mm: crease runs are about log-normal (Andresen et al. 2007), so
// equal steps of ln length.
QString histogramCsv(const std::vector<double>& segments) {
    QString csv;
    QTextStream table(&csv);
    table << "from_mm,to_mm,runs\n";
    if (segments.empty()) return csv;
    const double longest = 1e3 * *std::max_element(segments.begin(), segments.end());
    for (double from = 1.0; from <= longest; from *= std::sqrt(2.0)) {
        const double to = from * std::sqrt(2.0);
        const auto runs = std::count_if(segments.begin(), segments.end(),
                                        [&](double s) { return 1e3 * s >= from && 1e3 * s < to; });
        table << QString::number(from, 'f', 3) << ',' << QString::number(to, 'f', 3) << ',' << runs
              << '\n';
    }
    return csv;
}

} // namespace

int runCrumple(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Crumple an A4 sheet of office paper repeatedly (the crumple-cycles scene: the rim "
        "gathered in to half its size and pulled out flat again) and measure it as "
        "experiments on real paper do: total crease length after each cycle, with the fit "
        "L(n) = a + b ln n; crumple_cycles.csv, crease_runs.csv (histogram of crease run "
        "lengths) and crease_maps.png (each cycle's creases on the flat sheet). The "
        "paper's jacobi integrator, gravity outside the filter."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("crumple"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("output-dir"), QStringLiteral("Folder to write into (default: crumple)."),
         QStringLiteral("dir"), QStringLiteral("crumple")},
        {QStringLiteral("cycles"),
         QStringLiteral("Cycles to run, 2-%1 (default %1).").arg(kCrumpleCycles),
         QStringLiteral("n")},
        {QStringLiteral("seed"),
         QStringLiteral("Seed of the breaks and the crumpling (default 1)."), QStringLiteral("n")},
        {QStringLiteral("resolution"),
         QStringLiteral("Vertices across the sheet's width, %1-%2 (default 19; the time grows "
                        "with the square).")
             .arg(kMinResolution)
             .arg(kMaxResolution),
         QStringLiteral("n")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    const int cycles =
        static_cast<int>(integerOption(parser, QStringLiteral("cycles"), 2, kCrumpleCycles)
                             .value_or(kCrumpleCycles));
    SceneOptions scene;
    scene.seed = seedOption(parser, QStringLiteral("seed")).value_or(1);
    scene.resolution = static_cast<int>(
        integerOption(parser, QStringLiteral("resolution"), kMinResolution, kMaxResolution)
            .value_or(0));
    const QDir dir =
        requireFolder(QStringLiteral("output-dir"), parser.value(QStringLiteral("output-dir")));
    const QString cyclesPath = dir.filePath(QStringLiteral("crumple_cycles.csv"));
    const QString runsPath = dir.filePath(QStringLiteral("crease_runs.csv"));
    const QString mapsPath = dir.filePath(QStringLiteral("crease_maps.png"));
    for (const QString& path : {cyclesPath, runsPath, mapsPath})
        requireWritable(QStringLiteral("output-dir"), path);

    QTextStream out(stdout), err(stderr);
    World world = *makeScene("crumple-cycles", scene);
    // The paper's integrator, as the editor ran it before xpbd became the default: the
    // crease-length measurement was made and documented with it (docs/model.md).
    world.params.integrator = "jacobi";
    world.params.gravityOutsideFilter = true;
    const int rows = (cycles + kMapsPerRow - 1) / kMapsPerRow;
    QImage maps(std::min(cycles, kMapsPerRow) * kMapWidth, rows * (kMapHeight + kMapCaption),
                QImage::Format_RGB32);
    maps.fill(Qt::white);
    QPainter painter(&maps);
    QFont font = painter.font();
    font.setPixelSize(13);
    painter.setFont(font);
    out << "cycle  vertices  breaks  crease length (m)  added (m)\n";
    double previous = 0.0;
    // Each cycle's map is drawn as it ends, from the sheet as it is then.
    const auto drawn = [&](const CrumpleCycle& c, const Sheet& sheet) {
        const int k = c.cycle - 1;
        const QRect area((k % kMapsPerRow) * kMapWidth,
                         (k / kMapsPerRow) * (kMapHeight + kMapCaption), kMapWidth, kMapHeight);
        drawCreaseMap(painter, area, sheet);
        painter.setPen(Qt::black);
        painter.drawText(
            QRect(area.left(), area.bottom(), kMapWidth, kMapCaption), Qt::AlignCenter,
            QStringLiteral("cycle %1: %2 m").arg(c.cycle).arg(c.creaseLength, 0, 'f', 2));
        out << QStringLiteral("%1  %2  %3  %4  %5\n")
                   .arg(c.cycle, 5)
                   .arg(c.vertices, 8)
                   .arg(c.breaks, 6)
                   .arg(c.creaseLength, 17, 'f', 3)
                   .arg(c.creaseLength - previous, 9, 'f', 3);
        out.flush();
        previous = c.creaseLength;
    };
    const CrumpleReport report = runCrumpleCycles(std::move(world), cycles, drawn);
    painter.end();
    if (!report.error.empty()) {
        err << "paperfold: the simulation diverged (" << QString::fromStdString(report.error)
            << ")\n";
        return 3;
    }
    const LogarithmicFit& fit = report.fit;
    out << QStringLiteral("fit: L(n) = %1 + %2 ln n m, R² = %3\n")
               .arg(fit.a, 0, 'f', 3)
               .arg(fit.b, 0, 'f', 3)
               .arg(fit.r2, 0, 'f', 3);
    if (!report.segments.empty()) {
        double mean = 0.0, square = 0.0;
        for (double s : report.segments) mean += std::log(1e3 * s);
        mean /= report.segments.size();
        for (double s : report.segments) square += std::pow(std::log(1e3 * s) - mean, 2);
        out << QStringLiteral("crease runs: %1, ln(length / mm) mean %2, sd %3 (median %4 mm)\n")
                   .arg(report.segments.size())
                   .arg(mean, 0, 'f', 2)
                   .arg(std::sqrt(square / report.segments.size()), 0, 'f', 2)
                   .arg(1e3 * report.segments[report.segments.size() / 2], 0, 'f', 1);
    }

    QString csv;
    QTextStream table(&csv);
    table << "cycle,vertices,breaks,crease_length_m,fit_m\n";
    for (const CrumpleCycle& c : report.cycles)
        table << c.cycle << ',' << c.vertices << ',' << c.breaks << ','
              << QString::number(c.creaseLength, 'g', 10) << ','
              << QString::number(fit.a + fit.b * std::log(double(c.cycle)), 'g', 10) << '\n';
    QString error;
    if (!writeOutputFile(cyclesPath, csv.toUtf8(), &error) ||
        !writeOutputFile(runsPath, histogramCsv(report.segments).toUtf8(), &error) ||
        !writePng(maps, mapsPath, &error)) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    out << "wrote " << cyclesPath << ", " << runsPath << " and " << mapsPath << '\n';
    return 0;
}

} // namespace pf::cli
