#include "RenderCommand.h"

#include "CommandLine.h"
#include "ImageCompare.h"
#include "OffscreenRenderer.h"
#include "OutputPattern.h"
#include "PictureOptions.h"
#include "PngFile.h"
#include "ReferenceImage.h"
#include "SheetSnapshot.h"
#include "Simulation.h"
#include "WorldOptions.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>
#include <cmath>
#include <unistd.h>

namespace pf::cli {

int runRender(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Render a sheet to PNG with no display (OSMesa), as a still or an image sequence."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("render"), QStringLiteral("The subcommand."));
    addWorldOptions(parser);
    addThreadsOption(parser);
    addPictureOptions(parser);
    parser.addOptions({
        {QStringLiteral("steps"),
         QStringLiteral("Steps to simulate before the (first) image (default 0)."),
         QStringLiteral("n")},
        {QStringLiteral("output"),
         QStringLiteral("PNG to write; with --frames a pattern such as frame_%04d.png."),
         QStringLiteral("file")},
        {QStringLiteral("frames"), QStringLiteral("Write an image sequence of N frames."),
         QStringLiteral("n")},
        {QStringLiteral("every"), QStringLiteral("Steps between frames of a sequence (default 4)."),
         QStringLiteral("k")},
        {QStringLiteral("reference"),
         QStringLiteral("Compare with this PNG; exit 4 and write the output's name with .diff.png "
                        "in place of .png (a.png: a.diff.png) on a mismatch."),
         QStringLiteral("png")},
        {QStringLiteral("threshold"),
         QStringLiteral("Largest fraction of differing pixels that still matches (default 0.01)."),
         QStringLiteral("t")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    if (!parser.isSet(QStringLiteral("output")))
        throw UsageError{QStringLiteral("--output is required")};
    const QString output = parser.value(QStringLiteral("output"));

    refuseWithout(parser, {"every"}, "frames");
    refuseWithout(parser, {"threshold"}, "reference");
    const PictureSetup picture = pictureFromOptions(parser);
    const int width = picture.width, height = picture.height;
    RenderOptions options = picture.options;
    const long long steps =
        integerOption(parser, QStringLiteral("steps"), 0, 1'000'000'000).value_or(0);
    const int frames =
        static_cast<int>(integerOption(parser, QStringLiteral("frames"), 1, 100000).value_or(0));
    const int every =
        static_cast<int>(integerOption(parser, QStringLiteral("every"), 1, 1'000'000).value_or(4));
    const bool sequence = frames > 0;
    if (sequence && parser.isSet(QStringLiteral("reference")))
        throw UsageError{QStringLiteral("--reference compares a single image; leave out --frames")};
    QString patternError;
    const std::optional<OutputPattern> pattern = OutputPattern::parse(output, &patternError);
    if (!pattern) throw UsageError{QStringLiteral("--output: ") + patternError};
    if (sequence && frames > 1 && !pattern->hasField())
        throw UsageError{
            QStringLiteral("--output needs a pattern such as frame_%04d.png with --frames")};
    const double threshold =
        realOption(parser, QStringLiteral("threshold"), 0.0, 1.0).value_or(0.01);
    const int threads = threadsOption(parser);
    QStringList inputs = worldInputs(parser) + picture.lookInputs;
    const QString refPath = parser.value(QStringLiteral("reference"));
    if (parser.isSet(QStringLiteral("reference"))) inputs << refPath;
    // Every target is checked before any work, so a bad one fails at once.
    const int count = sequence ? frames : 1;
    for (int f = 0; f < count; ++f)
        requireWritable(QStringLiteral("output"), pattern->path(f), inputs);
    requireDistinctFrames(QStringLiteral("output"), *pattern, count);
    requirePngName(QStringLiteral("output"), pattern->path(0));
    const QString diffPath = QFileInfo(pattern->path(0)).path() + QLatin1Char('/') +
                             QFileInfo(pattern->path(0)).completeBaseName() +
                             QStringLiteral(".diff.png");
    QImage reference;
    if (parser.isSet(QStringLiteral("reference"))) {
        requireWritable(QStringLiteral("output"), diffPath, inputs + QStringList{output});
        QString error;
        reference = readReferenceImage(refPath, &error);
        if (reference.isNull()) throw UsageError{error};
    }

    Simulation sim(worldFromOptions(parser));
    sim.setThreads(threads);
    options.sigma = sim.world().params.sigma; // the sheet's own, or --sigma
    QTextStream out(stdout), err(stderr);
    auto advance = [&](long long n) {
        for (long long k = 0; k < n; ++k)
            if (sim.step() != StepStatus::Ok) return false;
        return true;
    };
    if (!advance(steps)) {
        err << "paperfold: the simulation diverged before the first image\n";
        return 3;
    }

    QString error;
    auto renderer = OffscreenRenderer::create(width, height, &error);
    if (!renderer) {
        err << "paperfold: " << error << '\n';
        return 2;
    }
    const SheetSnapshot first = makeSnapshot(sim);
    // The camera is framed on the first image and then held, so a sequence does not jitter.
    const OrbitCamera camera = frameCamera(first, parser, double(width) / height);
    const bool progress = isatty(fileno(stderr));
    QElapsedTimer timer;
    double renderSeconds = 0;
    for (int f = 0; f < count; ++f) {
        if (f > 0 && !advance(every)) {
            // Named by its file: "frame 3/10" counted from 1 and "before frame 3" from 0
            // read as one frame apart.
            err << "\npaperfold: the simulation diverged before " << pattern->path(f) << "; the "
                << f << (f == 1 ? " image" : " images") << " before it are written\n";
            return 3;
        }
        const SheetSnapshot snap = f == 0 ? first : makeSnapshot(sim);
        timer.start();
        const QImage image = renderer->render(snap, camera, options);
        renderSeconds += timer.nsecsElapsed() * 1e-9;
        const QString path = pattern->path(f);
        QString error;
        if (!writePng(image, path, &error, inputs)) {
            err << (sequence && progress ? "\n" : "") << "paperfold: " << error << '\n';
            return 2;
        }
        if (sequence && progress)
            err << QStringLiteral("\rframe %1/%2  t = %3 s")
                       .arg(f + 1)
                       .arg(count)
                       .arg(sim.world().time, 0, 'f', 3)
                << Qt::flush;
        else if (sequence && (f + 1) % std::max(1, count / 10) == 0)
            err << QStringLiteral("frame %1/%2\n").arg(f + 1).arg(count);
        if (!sequence && parser.isSet(QStringLiteral("reference"))) {
            // Images of different sizes have no pixels to compare: that is the news, not
            // "100 % of pixels differ" and a difference image never written.
            if (reference.size() != image.size()) {
                out << QStringLiteral("compared with %1: it is %2x%3, the image %4x%5\n")
                           .arg(refPath)
                           .arg(reference.width())
                           .arg(reference.height())
                           .arg(image.width())
                           .arg(image.height());
                err << "paperfold: the image does not match " << refPath
                    << ": the sizes differ (render it with --size " << reference.width() << 'x'
                    << reference.height() << ")\n";
                return 4;
            }
            const ImageDifference d = compareImages(reference, image);
            out << QStringLiteral("compared with %1: %2 % of pixels differ (threshold %3 %)\n")
                       .arg(refPath)
                       .arg(100.0 * d.differingFraction, 0, 'f', 3)
                       .arg(100.0 * threshold, 0, 'f', 3);
            if (d.differingFraction > threshold) {
                if (!d.map.isNull() && !writePng(d.map, diffPath, &error, inputs)) {
                    err << "paperfold: the image does not match " << refPath << "; " << error
                        << '\n';
                    return 4;
                }
                err << "paperfold: the image does not match " << refPath << "; differences in "
                    << diffPath << '\n';
                return 4;
            }
        }
    }
    if (sequence && progress) err << '\n';
    out << QStringLiteral("wrote %1 image%2 of %3x%4 (%5 s per image, %6)\n")
               .arg(count)
               .arg(count == 1 ? QString() : QStringLiteral("s"))
               .arg(width)
               .arg(height)
               .arg(renderSeconds / count, 0, 'f', 3)
               .arg(renderer->glVersion());
    return 0;
}

} // namespace pf::cli
