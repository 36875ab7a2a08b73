// `paperfold simulate`: the JSON contract and the handling of bad input.
#include "EditSession.h"
#include "JacobiScene.h"
#include "RecordingFile.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SheetStats.h"
#include "TestData.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

namespace {

struct Result {
    int exitCode;
    QByteArray out, err;
};

// `environment`: NAME=value settings on top of this process's environment.
Result runPaperfold(QStringList args, bool noDisplay = false, const QStringList& environment = {}) {
    // A new scene is stepped in the integrator the build can afford unless the test names
    // one: the commands' parsing, files and output are the same for every integrator.
    if (pf::test::kMachineryInJacobi && !args.isEmpty() &&
        args.front() == QLatin1String("simulate") && args.contains(QLatin1String("--scene")) &&
        !args.contains(QLatin1String("--integrator")))
        args << QStringLiteral("--integrator") << QStringLiteral("jacobi");
    QProcess p;
    if (noDisplay) {
        // Prove the headless path needs no X server and no Qt platform setting.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        p.setProcessEnvironment(env);
    }
    if (!environment.isEmpty()) {
        QProcessEnvironment env = p.processEnvironment().isEmpty()
                                      ? QProcessEnvironment::systemEnvironment()
                                      : p.processEnvironment();
        for (const QString& setting : environment)
            env.insert(setting.section(QLatin1Char('='), 0, 0),
                       setting.section(QLatin1Char('='), 1));
        p.setProcessEnvironment(env);
    }
    p.start(QStringLiteral(PAPERFOLD_EXE), args);
    // Sanitizer builds run the commands many times slower; the limit scales with it.
    if (!p.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN)) return {-1, {}, "timeout"};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

} // namespace

class TestSimulateCli : public QObject {
    Q_OBJECT

  private slots:
    // The paper's figures as contact sheets: one row per value, one column per seed, the
    // counts under each picture and in the CSV; φ = 1 cannot break a flat region.
    void figuresWritesTheContactSheetsAndTheirCounts() {
        QTemporaryDir dir;
        // A sanitized build renders through llvmpipe very slowly: one seed there.
        const int seeds = PAPERFOLD_TEST_SLOWDOWN > 1 ? 1 : 2;
        const Result r = runPaperfold({"figures", "--output-dir", dir.path(), "--seeds",
                                       QString::number(seeds), "--steps", "120"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QStringList sheets{"fig10_phi", "fig11_psi_press", "fig11_psi_compress",
                                 "fig12_sigma"};
        const int rows[] = {4, 4, 4, 3};
        for (int k = 0; k < sheets.size(); ++k) {
            const QImage image(dir.filePath(sheets[k] + QStringLiteral(".png")));
            QVERIFY2(!image.isNull(), qPrintable(sheets[k]));
            QCOMPARE(image.width(), 90 + seeds * 320);
            QCOMPARE(image.height(), 34 + rows[k] * (200 + 38));
        }
        QFile csv(dir.filePath(QStringLiteral("figures.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + seeds * (4 + 4 + 4 + 3));
        long breaksAtPhi0 = 0;
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(QLatin1Char(','));
            QCOMPARE(f.size(), 8);
            if (f[0] != QLatin1String("fig10_phi")) continue;
            if (f[3] == QLatin1String("1")) QCOMPARE(f[5], QStringLiteral("0"));
            if (f[3] == QLatin1String("0")) breaksAtPhi0 += f[5].toLong();
        }
        QVERIFY(breaksAtPhi0 > 0);
    }

    // Crumpled and flattened twice: a row per cycle whose crease length grows and matches
    // the printed table, a histogram that counts every crease run, and a map per cycle.
    void crumpleWritesCreaseLengthPerCycle() {
        QTemporaryDir dir;
        const Result r = runPaperfold({"crumple", "--output-dir", dir.path(), "--cycles", "2"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.out.contains("fit: L(n) = "));
        QFile csv(dir.filePath(QStringLiteral("crumple_cycles.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QStringLiteral("cycle,vertices,breaks,crease_length_m,fit_m"));
        const QStringList one = lines[1].split(QLatin1Char(',')),
                          two = lines[2].split(QLatin1Char(','));
        QVERIFY(one[3].toDouble() > 0.0);
        QVERIFY(two[3].toDouble() > one[3].toDouble());
        QVERIFY(two[2].toLong() > one[2].toLong());
        // Two points: the fit passes through both.
        QVERIFY(std::abs(two[4].toDouble() - two[3].toDouble()) < 1e-9);
        QVERIFY(r.out.contains(QByteArray::number(two[3].toDouble(), 'f', 3)));

        QFile runs(dir.filePath(QStringLiteral("crease_runs.csv")));
        QVERIFY(runs.open(QIODevice::ReadOnly));
        const QStringList bins =
            QString::fromUtf8(runs.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(bins[0], QStringLiteral("from_mm,to_mm,runs"));
        long counted = 0;
        for (const QString& bin : bins.mid(1)) counted += bin.split(QLatin1Char(','))[2].toLong();
        const QRegularExpression said(QStringLiteral("crease runs: (\\d+),"));
        const QRegularExpressionMatch m = said.match(QString::fromUtf8(r.out));
        QVERIFY(m.hasMatch());
        QCOMPARE(counted, m.captured(1).toLong());

        const QImage maps(dir.filePath(QStringLiteral("crease_maps.png")));
        QCOMPARE(maps.size(), QSize(2 * 210, 297 + 36));

        const Result bad = runPaperfold({"crumple", "--output-dir", dir.path(), "--cycles", "11"});
        QCOMPARE(bad.exitCode, 1);
        QVERIFY2(bad.err.contains("--cycles"), bad.err.constData());
        const Result coarse =
            runPaperfold({"crumple", "--output-dir", dir.path(), "--resolution", "2"});
        QCOMPARE(coarse.exitCode, 1);
        QVERIFY2(coarse.err.contains("--resolution"), coarse.err.constData());
        // A folder that is a file says so (it said only "cannot create").
        const QString file = dir.filePath(QStringLiteral("crease_maps.png"));
        for (const char* command : {"crumple", "figures", "stability"}) {
            const Result onAFile = runPaperfold({command, "--output-dir", file}, true);
            QCOMPARE(onAFile.exitCode, 1);
            QVERIFY2(onAFile.err.contains("is a file, not a folder"), onAFile.err.constData());
        }
    }

    void statsJsonHasEveryKey() {
        const Result r = runPaperfold({"simulate", "--scene", "press", "--steps", "300", "--seed",
                                       "3", "--phi", "0.1", "--psi", "0.25", "--stats"});
        QCOMPARE(r.exitCode, 0);
        QJsonParseError error;
        const QJsonObject o = QJsonDocument::fromJson(r.out, &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        for (const char* key : {"vertices", "springs", "triangles", "breaks", "recoveries",
                                "hinges", "total_mass", "max_strain", "rms_strain", "state_hash",
                                "sim_time", "wall_seconds", "steps_per_second", "build_tuning"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        // The settings used: xpbd's paper and sub-steps too.
        QCOMPARE(o[QStringLiteral("material")].toString(), QStringLiteral("office"));
        QCOMPARE(o[QStringLiteral("substeps")].toInt(), 40);
        QVERIFY(!o.contains(QLatin1String("loaded")));
        // The speed is reported with the tuning that measured it: portable unless the
        // build asked for -march=native (the tests are built with the same options).
        const QString tuning = o[QStringLiteral("build_tuning")].toString();
#if defined(PAPERFOLD_NATIVE)
        QVERIFY2(tuning.startsWith(QLatin1String("native (-march=native: ")), qPrintable(tuning));
#else
        QCOMPARE(tuning, QStringLiteral("portable (x86-64 baseline: SSE2)"));
#endif
        QVERIFY(o[QStringLiteral("vertices")].toInt() >= 494);
        QVERIFY(std::abs(o[QStringLiteral("total_mass")].toDouble() - 0.080 * 0.210 * 0.297) <
                1e-12);
        QVERIFY(std::abs(o[QStringLiteral("sim_time")].toDouble() - 300.0 / 240.0) < 1e-9);
        QCOMPARE(o[QStringLiteral("state_hash")].toString().size(), 16);
    }

    void sameArgumentsSameHash() {
        const QStringList args{"simulate", "--scene", "compress", "--steps", "200", "--stats"};
        const auto a = QJsonDocument::fromJson(runPaperfold(args).out).object();
        const auto b = QJsonDocument::fromJson(runPaperfold(args).out).object();
        QCOMPARE(a[QStringLiteral("state_hash")], b[QStringLiteral("state_hash")]);
    }

    // --threads changes who computes, never what: the same state on 1, 2 and 3 threads, on
    // a sheet large enough to be shared among them, crumpled by the press tool (in the
    // paper's jacobi, which breaks a free sheet and shares every pass among threads).
    void threadsGiveTheSameState() {
        QStringList hashes;
        // Sanitized builds step 60 (275 hinges by then; 200 steps three times took 29 s
        // under ASan).
        const QString steps =
            PAPERFOLD_TEST_SLOWDOWN > 1 ? QStringLiteral("60") : QStringLiteral("200");
        for (const char* threads : {"1", "2", "3"}) {
            const auto o =
                QJsonDocument::fromJson(
                    runPaperfold({"simulate", "--scene", "press", "--resolution", "60", "--steps",
                                  steps, "--integrator", "jacobi", "--gravity-outside-filter",
                                  "--threads", threads, "--stats"})
                        .out)
                    .object();
            QCOMPARE(o[QStringLiteral("threads")].toInt(), QString::fromLatin1(threads).toInt());
            QVERIFY(o[QStringLiteral("hinges")].toInt() > 0);
            hashes << o[QStringLiteral("state_hash")].toString();
        }
        QCOMPARE(hashes.size(), 3);
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(hashes[2], hashes[0]);
        // Without --threads: all the machine's.
        const auto all =
            QJsonDocument::fromJson(runPaperfold({"simulate", "--steps", "1", "--stats"}).out)
                .object();
        QCOMPARE(all[QStringLiteral("threads")].toInt(),
                 std::max(1, static_cast<int>(QThread::idealThreadCount())));
    }

    void optionsReachTheSimulation() {
        const auto o =
            QJsonDocument::fromJson(
                runPaperfold({"simulate", "--scene", "drape", "--steps", "10", "--integrator",
                              "backward-euler", "--dt", "0.002", "--resolution", "7", "--stats"})
                    .out)
                .object();
        QCOMPARE(o[QStringLiteral("integrator")].toString(), QStringLiteral("backward-euler"));
        // 7 along the short side; the long side keeps the A4 ratio: round(6·297/210) + 1 = 9.
        QCOMPARE(o[QStringLiteral("vertices")].toInt(), 7 * 9);
        QVERIFY(std::abs(o[QStringLiteral("sim_time")].toDouble() - 0.02) < 1e-12);
    }

    void badInputGivesOneLineErrorAndNonZeroExit_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown scene") << QStringList{"simulate", "--scene", "nope"} << "nope";
        QTest::newRow("a sheet with no name")
            << QStringList{"simulate", "--load", ""} << "the name is empty";
        QTest::newRow("a recording with no name")
            << QStringList{"replay", ""} << "the name is empty";
        QTest::newRow("phi out of range") << QStringList{"simulate", "--phi", "1.5"} << "phi";
        QTest::newRow("psi not a number") << QStringList{"simulate", "--psi", "abc"} << "psi";
        QTest::newRow("negative steps") << QStringList{"simulate", "--steps", "-4"} << "steps";
        QTest::newRow("nan dt") << QStringList{"simulate", "--dt", "nan"} << "dt";
        QTest::newRow("zero dt") << QStringList{"simulate", "--dt", "0"} << "dt";
        QTest::newRow("huge resolution")
            << QStringList{"simulate", "--resolution", "100000"} << "resolution";
        QTest::newRow("unknown integrator")
            << QStringList{"simulate", "--integrator", "rk4"} << "rk4";
        QTest::newRow("zero threads") << QStringList{"simulate", "--threads", "0"} << "threads";
        QTest::newRow("threads not a number")
            << QStringList{"simulate", "--threads", "many"} << "threads";
        QTest::newRow("too many threads")
            << QStringList{"render", "--threads", "65", "--output", "x.png"} << "threads";
        QTest::newRow("unknown option") << QStringList{"simulate", "--frobnicate"} << "frobnicate";
        // Root passes the permission bits in /proc, which then refuses a new file: the
        // save failed only after the run ("cannot write", with no option named).
        QTest::newRow("a save where no file can be made")
            << QStringList{"simulate",
                           "--scene",
                           "press",
                           "--steps",
                           "2000",
                           "--save",
                           "/proc/pf-never-written.paper"}
            << "--save: cannot write '/proc/pf-never-written.paper'";
        // A name with a newline split the result line in two; one with an escape set the
        // terminal's title.
        QTest::newRow("a newline in a name")
            << QStringList{"export", "--output", "new\nline.obj"}
            << "argument 3 ('new\\x0aline.obj') holds a control character (U+000a)";
        QTest::newRow("an escape in a name")
            << QStringList{"simulate", "--load", "esc\x1b]0;title\ax.paper"}
            << "('esc\\x1b]0;title\\x07x.paper') holds a control character (U+001b)";
        // An option the integrator does not read ran as if it were not given.
        QTest::newRow("sub-steps to jacobi")
            << QStringList{"simulate", "--integrator", "jacobi", "--substeps", "7"}
            << "--substeps applies to xpbd only; the integrator here is jacobi";
        QTest::newRow("sweeps to xpbd")
            << QStringList{"simulate", "--iterations", "3"} << "--iterations applies to jacobi";
        QTest::newRow("gravity outside the filter to symplectic")
            << QStringList{"export",     "--integrator",
                           "symplectic", "--gravity-outside-filter",
                           "--output",   QDir::temp().filePath("pf-never-written.obj")}
            << "the integrator here is symplectic";
        QTest::newRow("self-contact to backward-euler")
            << QStringList{"render",   "--integrator", "backward-euler", "--no-self-contact",
                           "--output", "x.png"}
            << "--no-self-contact applies to xpbd only";
        QTest::newRow("fidelity's sub-steps to jacobi")
            << QStringList{"fidelity", "--integrator", "jacobi", "--substeps", "3"}
            << "--substeps applies to xpbd only";
        QTest::newRow("unknown command") << QStringList{"fly"} << "fly";
        QTest::newRow("stray argument") << QStringList{"simulate", "extra"} << "extra";
    }
    void badInputGivesOneLineErrorAndNonZeroExit() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        const Result r = runPaperfold(args);
        QVERIFY(r.exitCode > 0);
        const QString err = QString::fromUtf8(r.err).trimmed();
        QVERIFY2(!err.isEmpty() && !err.contains(QLatin1Char('\n')), qPrintable(err));
        QVERIFY2(err.contains(mentions), qPrintable(err));
        QVERIFY(r.out.isEmpty());
    }

    // --help-all is listed by every command's --help: it ran the command instead (figures
    // and crumple wrote over their output folders). --help and --version need no display,
    // and a command after the editor's options is named, not taken for the editor.
    void helpAndVersionPrintAndRunNothing() {
        for (const char* command : {"figures", "crumple"}) {
            QTemporaryDir dir;
            const Result r =
                runPaperfold({command, "--help-all", "--output-dir", dir.path()}, true);
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.contains("Usage:"), r.out.constData());
            QVERIFY2(QDir(dir.path()).isEmpty(), command);
        }
        const Result simulate = runPaperfold({"simulate", "--help-all"}, true);
        QCOMPARE(simulate.exitCode, 0);
        QVERIFY2(simulate.out.startsWith("Usage:"), simulate.out.constData()); // not a run
        for (const char* ask : {"--version", "--help"}) {
            const Result r = runPaperfold({ask}, true);
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.contains(ask == QLatin1String("--version") ? "PaperFold" : "commands:"),
                     r.out.constData());
        }
        const Result late = runPaperfold({"--lang", "ko", "simulate", "--steps", "1"}, true);
        QCOMPARE(late.exitCode, 1);
        QVERIFY2(late.err.contains("'simulate' must come first"), late.err.constData());
        QVERIFY(late.out.isEmpty());
    }

    // --stats' statistics are the run's result: printed to a full disk they were lost and
    // the command said nothing, exit 0. So were the help and the version.
    void statisticsThatCannotBeWrittenFailTheCommand_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("statistics") << QStringList{"simulate", "--scene",      "press",  "--steps",
                                                   "1",        "--integrator", "jacobi", "--stats"};
        QTest::newRow("the commands' help") << QStringList{"--help"};
        QTest::newRow("the editor's version") << QStringList{"--version"};
        QTest::newRow("the editor's whole help") << QStringList{"--help-all"};
    }
    void statisticsThatCannotBeWrittenFailTheCommand() {
        QFETCH(QStringList, args);
        if (!QFile::exists(QStringLiteral("/dev/full"))) QSKIP("no /dev/full here");
        QProcess p;
        p.setStandardOutputFile(QStringLiteral("/dev/full"));
        p.start(QStringLiteral(PAPERFOLD_EXE), args);
        QVERIFY(p.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 2);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("the output could not be written"), err.constData());
    }

    // A run of minutes showed nothing until it ended. On a terminal it shows the step it
    // has reached, ending on the last; in a pipe it says nothing. `script` gives it one.
    void simulateShowsItsStepOnATerminal() {
        if (QStandardPaths::findExecutable(QStringLiteral("script")).isEmpty())
            QSKIP("no script(1) here to give the run a terminal");
        QProcess terminal;
        terminal.start(QStringLiteral("script"),
                       {"-qec",
                        "exec \"" PAPERFOLD_EXE "\" simulate --scene drape --resolution 7 "
                        "--integrator jacobi --steps 50",
                        "/dev/null"});
        QVERIFY(terminal.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN));
        QCOMPARE(terminal.exitCode(), 0);
        const QByteArray shown = terminal.readAllStandardOutput();
        QVERIFY2(shown.startsWith("\rsimulating: step 50 of 50 (100 %)\r\ndrape: 50 steps"),
                 shown.constData());
        const Result piped = runPaperfold({"simulate", "--scene", "drape", "--resolution", "7",
                                           "--integrator", "jacobi", "--steps", "50"});
        QCOMPARE(piped.exitCode, 0);
        QVERIFY2(piped.err.isEmpty(), piped.err.constData());
    }

    // Qt reads arguments as UTF-8: a name in another encoding ("a\xff.paper", byte 0xFF)
    // was saved as "a\uFFFD.paper", a file of another name, and said nothing of it.
    void aNameNotInUtf8IsRefusedNotChanged() {
        QTemporaryDir dir;
        QProcess p;
        p.setWorkingDirectory(dir.path());
        // QProcess writes its arguments as UTF-8, so a shell's printf makes the byte.
        p.start(QStringLiteral("/bin/sh"),
                {"-c",
                 "exec \"$0\" simulate --scene drape --steps 1 --integrator jacobi --save "
                 "\"$(printf 'a\\377.paper')\"",
                 QStringLiteral(PAPERFOLD_EXE)});
        QVERIFY(p.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 1);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("argument 9 ('a\xef\xbf\xbd.paper') is not UTF-8 text"),
                 err.constData());
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList());
    }

    // Ctrl+C or a kill while the output was written left its hidden temporary file beside
    // the target (".big.obj.5633.1.75306.0.tmp", 121 MB). Killed at that moment, it
    // leaves nothing; the target it would have replaced stays as it was.
    void aKillDuringTheWriteLeavesNoTemporaryFile() {
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("big.obj"));
        QFile kept(target);
        QVERIFY(kept.open(QIODevice::WriteOnly) && kept.write("kept\n") == 5);
        kept.close();
        QProcess p;
        p.start(QStringLiteral(PAPERFOLD_EXE),
                {"export", "--resolution", "100", "--subdiv", "3", "--output", target});
        QVERIFY(p.waitForStarted());
        const QDir folder(dir.path());
        const auto temporary = [&] {
            return folder.entryList({QStringLiteral(".*.tmp")}, QDir::Files | QDir::Hidden);
        };
        QElapsedTimer waited;
        waited.start();
        QStringList seen;
        while ((seen = temporary()).isEmpty() && p.state() == QProcess::Running &&
               waited.elapsed() < 120000 * PAPERFOLD_TEST_SLOWDOWN)
            QThread::msleep(1);
        QVERIFY2(!seen.isEmpty(),
                 qPrintable(QStringLiteral("the write ended before the test saw it begin: ") +
                            QString::fromUtf8(p.readAllStandardError())));
        ::kill(pid_t(p.processId()), SIGTERM);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::CrashExit); // ended by the signal, as it asked
        QCOMPARE(temporary(), QStringList());
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("kept\n"));
    }

    // Under a memory limit (ulimit -v) a large export ended in "terminate called after
    // throwing an instance of 'std::bad_alloc'" and SIGABRT, with no message of ours.
    void runningOutOfMemorySaysSo() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1)
            QSKIP("the sanitizers reserve more address space than the limit leaves");
        QTemporaryDir dir;
        QProcess p;
        p.setChildProcessModifier([] {
            const rlimit limit{1500LL << 20, 1500LL << 20};
            setrlimit(RLIMIT_AS, &limit);
        });
        p.start(QStringLiteral(PAPERFOLD_EXE),
                {"export", "--resolution", "200", "--subdiv", "4", "--output",
                 dir.filePath(QStringLiteral("huge.ply"))});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit); // not killed by SIGABRT
        QCOMPARE(p.exitCode(), 2);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.startsWith("paperfold: out of memory") && err.count('\n') == 1,
                 err.constData());
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList());
    }

    // Under a file-size limit (ulimit -f) the process was killed mid-write by SIGXFSZ,
    // with no message and its temporary file left beside the one it was to replace.
    void aFileSizeLimitFailsTheSaveAndLeavesNothing() {
        QTemporaryDir dir;
        const QString kept = dir.filePath(QStringLiteral("keep.paper"));
        QCOMPARE(runPaperfold({"simulate", "--scene", "press", "--steps", "0", "--integrator",
                               "jacobi", "--resolution", "5", "--save", kept})
                     .exitCode,
                 0);
        const QByteArray before = [&] {
            QFile f(kept);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        QVERIFY(!before.isEmpty());
        QProcess p;
        p.setChildProcessModifier([] {
            const rlimit limit{20 * 1024, 20 * 1024};
            setrlimit(RLIMIT_FSIZE, &limit);
        });
        p.start(QStringLiteral(PAPERFOLD_EXE),
                {"simulate", "--scene", "press", "--steps", "1", "--integrator", "jacobi",
                 "--resolution", "20", "--save", kept});
        QVERIFY(p.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit); // not killed by a signal
        QVERIFY(p.exitCode() != 0);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("File too large"), err.constData());
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{QStringLiteral("keep.paper")});
        QFile f(kept);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);
    }

    // The editor on a platform with no OpenGL made its window and crashed in the first
    // paint (SIGSEGV); it says why and ends.
    void theEditorWithoutOpenGlSaysSo() {
        // With no display either: given one, the offscreen platform draws through GLX.
        const Result r = runPaperfold({}, true, {"QT_QPA_PLATFORM=offscreen"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("gives no OpenGL context"), r.err.constData());
    }

    void saveThenLoadResumesExactly() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("half.paper"));
        const Result first =
            runPaperfold({"simulate", "--scene", "press", "--steps", "300", "--save", path});
        QCOMPARE(first.exitCode, 0);
        const auto resumed =
            QJsonDocument::fromJson(
                runPaperfold({"simulate", "--load", path, "--steps", "300", "--stats"}).out)
                .object();
        const auto whole =
            QJsonDocument::fromJson(
                runPaperfold({"simulate", "--scene", "press", "--steps", "600", "--stats"}).out)
                .object();
        QVERIFY(whole[QStringLiteral("breaks")].toInt() > 0);
        QCOMPARE(resumed[QStringLiteral("state_hash")], whole[QStringLiteral("state_hash")]);
        QCOMPARE(resumed[QStringLiteral("sim_time")], whole[QStringLiteral("sim_time")]);
        // A loaded sheet is named by its file, and the scene it began as is kept.
        QCOMPARE(resumed[QStringLiteral("loaded")].toString(), path);
        QCOMPARE(resumed[QStringLiteral("scene")].toString(), QStringLiteral("press"));
        const Result line = runPaperfold({"simulate", "--load", path, "--steps", "1"});
        QCOMPARE(line.exitCode, 0);
        QVERIFY2(line.out.startsWith("half.paper (begun as press): 1 steps"), line.out.constData());
    }

    void loadingABadFileGivesOneLineError() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.paper"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray::fromHex("a1656d61676963") + "bad"); // {"magic": <truncated>
        f.close();
        const Result r = runPaperfold({"simulate", "--load", path, "--steps", "5"});
        QCOMPARE(r.exitCode, 1);
        const QString err = QString::fromUtf8(r.err).trimmed();
        QVERIFY2(err.contains(QStringLiteral("bad.paper")) && !err.contains(QLatin1Char('\n')),
                 qPrintable(err));
        QCOMPARE(runPaperfold({"simulate", "--load", path, "--scene", "press"}).exitCode, 1);
        QCOMPARE(runPaperfold({"simulate", "--load", path, "--seed", "4"}).exitCode, 1);
    }

    // The command line's export of a mountain fold lying on the desk went 3.2 mm into the
    // desk at σ = 4 (test_export has the editor's; tests/data/README.md the sheet).
    void exportKeepsAFoldOnTheDeskAboveIt() {
        const std::optional<pf::World> folded =
            pf::test::packedState("mountain-fold-on-desk.paper.qz");
        QVERIFY(folded);
        QTemporaryDir dir;
        const QString sheet = dir.filePath(QStringLiteral("mountain.paper"));
        QString error;
        QVERIFY2(pf::saveWorld(*folded, sheet, &error), qPrintable(error));
        const QString out = dir.filePath(QStringLiteral("mountain.obj"));
        const Result r = runPaperfold(
            {"export", "--load", sheet, "--output", out, "--subdiv", "3", "--sigma", "4"});
        QCOMPARE(r.exitCode, 0);
        QFile obj(out);
        QVERIFY(obj.open(QIODevice::ReadOnly));
        int points = 0;
        double below = 0.0;
        for (const QByteArray& line : obj.readAll().split('\n'))
            if (line.startsWith("v ")) {
                ++points;
                below = std::max(below, folded->groundHeight - line.split(' ').at(2).toDouble());
            }
        QVERIFY(points > 10000);
        QVERIFY2(below <= 1e-6,
                 qPrintable(QStringLiteral("%1 mm below the desk").arg(below * 1e3)));
    }

    void exportWritesEachFormat() {
        QTemporaryDir dir;
        const QString sheet = dir.filePath(QStringLiteral("s.paper"));
        QCOMPARE(runPaperfold({"simulate", "--scene", "press", "--steps", "100", "--save", sheet})
                     .exitCode,
                 0);
        for (const char* ext : {"obj", "ply", "glb"}) {
            const QString out = dir.filePath(QStringLiteral("s.") + QLatin1String(ext));
            const Result r = runPaperfold(
                {"export", "--load", sheet, "--output", out, "--subdiv", "1", "--sigma", "0.5"});
            QCOMPARE(r.exitCode, 0);
            QVERIFY(QFileInfo(out).size() > 1000);
        }
        // Only a GLB carries the look: elsewhere it is left out, and said (it was silent).
        const Result plain = runPaperfold(
            {"export", "--load", sheet, "--output", dir.filePath("t.obj"), "--texture", "grain"});
        QCOMPARE(plain.exitCode, 0);
        QVERIFY2(plain.err.contains("a .obj file carries no paper colour or texture"),
                 plain.err.constData());
        const Result bad = runPaperfold({"export", "--load", sheet, "--output", "x.stl"});
        QCOMPARE(bad.exitCode, 1);
        QVERIFY(QString::fromUtf8(bad.err).contains(QStringLiteral(".obj")));
        QCOMPARE(runPaperfold({"export", "--load", sheet}).exitCode, 1); // no --output
        QCOMPARE(runPaperfold({"export", "--load", sheet, "--output", dir.filePath("a.obj"),
                               "--subdiv", "9"})
                     .exitCode,
                 1);

        // The look: the grain travels inside the GLB as a PNG; a picture is an input,
        // so an output over it is refused before any work and the picture survives.
        const QString looked = dir.filePath(QStringLiteral("look.glb"));
        QCOMPARE(runPaperfold({"export", "--load", sheet, "--output", looked, "--paper-color",
                               "ivory", "--texture", "grain"})
                     .exitCode,
                 0);
        QFile glb(looked);
        QVERIFY(glb.open(QIODevice::ReadOnly));
        const QByteArray bytes = glb.readAll();
        QVERIFY(bytes.contains("\"image/png\""));
        QVERIFY(bytes.contains("\"TEXCOORD_0\""));
        const QString picture = dir.filePath(QStringLiteral("picture.png"));
        QImage stripes(32, 32, QImage::Format_RGB32);
        stripes.fill(Qt::red);
        QVERIFY(stripes.save(picture));
        const Result over = runPaperfold({"render", "--scene", "press", "--size", "64x64",
                                          "--texture", picture, "--output", picture},
                                         true);
        QCOMPARE(over.exitCode, 1);
        QCOMPARE(QImage(picture).pixelColor(5, 5), QColor(Qt::red));
        QCOMPARE(QImage(picture).size(), QSize(32, 32));
    }

    void renderWritesAPngWithNoDisplay() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("shot.png"));
        const Result r =
            runPaperfold({"render", "--scene", "press", "--steps", "120", "--size", "320x200",
                          "--view", "top", "--overlay", "springs,breaks", "--output", out},
                         true);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage image(out);
        QCOMPARE(image.size(), QSize(320, 200));
        QVERIFY(QString::fromUtf8(r.out).contains(QStringLiteral("llvmpipe")));
    }

    void theLegendOfARenderIsInCDigitsWhateverTheLanguage() {
        // The commands speak English; under LANG=de_DE the legend's numbers followed the
        // user's locale ("≥ 0,05") once the legend wrote them as the default locale does,
        // which the editor sets to its translation's language.
        QTemporaryDir dir;
        const QStringList shot{"render",    "--scene",           "press", "--size", "320x200",
                               "--overlay", "probability,strain"};
        const QString c = dir.filePath(QStringLiteral("c.png"));
        const QString german = dir.filePath(QStringLiteral("de.png"));
        Result r = runPaperfold(shot + QStringList{"--output", c}, true,
                                {"LANG=C.UTF-8", "LC_ALL=C.UTF-8"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        r = runPaperfold(shot + QStringList{"--output", german}, true,
                         {"LANG=de_DE.UTF-8", "LC_ALL=de_DE.UTF-8", "LANGUAGE=de"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(QImage(german), QImage(c));
    }

    void renderNeverLooksFromUnderTheDesk() {
        // A pitch of -30° drew the desk's underside and nothing else; the eye is raised
        // above the desk as the editor's orbit keeps it, so any pitch below that is the
        // same picture.
        QTemporaryDir dir;
        const QStringList shot{"render", "--scene", "press", "--size", "160x100"};
        const QString under = dir.filePath(QStringLiteral("under.png"));
        const QString level = dir.filePath(QStringLiteral("level.png"));
        QCOMPARE(runPaperfold(shot + QStringList{"--camera", "0,-30,0.5", "--output", under}, true)
                     .exitCode,
                 0);
        QCOMPARE(runPaperfold(shot + QStringList{"--camera", "0,0,0.5", "--output", level}, true)
                     .exitCode,
                 0);
        QCOMPARE(QImage(under), QImage(level));
    }

    void renderWritesAnImageSequence() {
        QTemporaryDir dir;
        const Result r = runPaperfold({"render", "--scene", "compress", "--size", "160x120",
                                       "--frames", "5", "--every", "10", "--output",
                                       dir.filePath(QStringLiteral("frame_%04d.png"))},
                                      true);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QStringList frames = QDir(dir.path()).entryList({QStringLiteral("frame_*.png")});
        QCOMPARE(frames, QStringList({"frame_0000.png", "frame_0001.png", "frame_0002.png",
                                      "frame_0003.png", "frame_0004.png"}));
        QVERIFY(QString::fromUtf8(r.err).contains(QStringLiteral("frame 5/5")));
        QVERIFY(QImage(dir.filePath(QStringLiteral("frame_0000.png"))) !=
                QImage(dir.filePath(QStringLiteral("frame_0004.png"))));
    }

    // Frames of a sequence that are one file (s_3.png a link to s_1.png, made by hand or
    // by an earlier run's tidying) overwrote each other: the sequence ended with frame 3
    // in both names and frame 1 lost. Refused before any work, for render and replay, and
    // nothing is written.
    void framesThatAreOneFileAreRefused() {
        QTemporaryDir dir;
        QFile kept(dir.filePath(QStringLiteral("s_1.png")));
        QVERIFY(kept.open(QIODevice::WriteOnly));
        kept.write("an earlier frame the user keeps");
        kept.close();
        QVERIFY(QFile::link(QStringLiteral("s_1.png"), dir.filePath(QStringLiteral("s_3.png"))));
        const Result r =
            runPaperfold({"render", "--scene", "press", "--size", "64x48", "--frames", "5",
                          "--every", "1", "--output", dir.filePath(QStringLiteral("s_%d.png"))},
                         true);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("--output: frames 1 and 3 ('" +
                                dir.filePath(QStringLiteral("s_1.png")).toUtf8() + "' and '" +
                                dir.filePath(QStringLiteral("s_3.png")).toUtf8() +
                                "') are the same file"),
                 r.err.constData());
        QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("s_*")}, QDir::Files | QDir::System),
                 QStringList({"s_1.png", "s_3.png"}));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("an earlier frame the user keeps"));
        kept.close();
        // A hard link is one file too; replay's frames are checked the same way.
        QVERIFY(QFile::remove(dir.filePath(QStringLiteral("s_3.png"))));
        QCOMPARE(::link(QFile::encodeName(dir.filePath(QStringLiteral("s_1.png"))).constData(),
                        QFile::encodeName(dir.filePath(QStringLiteral("s_2.png"))).constData()),
                 0);
        pf::EditSession session(pf::test::machineryScene("press"));
        QCOMPARE(session.advance(8), pf::StepStatus::Ok);
        const QString rec = dir.filePath(QStringLiteral("session.paperrec"));
        QString error;
        QVERIFY2(pf::saveRecording(session.log(), rec, &error), qPrintable(error));
        const Result replayed =
            runPaperfold({"replay", rec, "--render", dir.filePath(QStringLiteral("s_%d.png")),
                          "--every", "2", "--size", "64x48"},
                         true);
        QCOMPARE(replayed.exitCode, 1);
        QVERIFY2(replayed.err.contains("--render: frames 1 and 2"), replayed.err.constData());
        QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("s_*")}, QDir::Files),
                 QStringList({"s_1.png", "s_2.png"}));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("an earlier frame the user keeps"));
    }

    // A crumpled sheet's creases are drawn as fine lines; --no-creases draws the surface
    // alone. A sheet that has not broken draws the same either way.
    void renderDrawsCreasesUnlessAsked() {
        QTemporaryDir dir;
        const QString sheet = dir.filePath(QStringLiteral("c.paper"));
        QCOMPARE(runPaperfold({"simulate", "--scene", "press", "--integrator", "jacobi", "--steps",
                               "240", "--save", sheet})
                     .exitCode,
                 0);
        const auto draw = [&](const QStringList& from, const QString& name, bool creases) {
            QStringList args = QStringList{"render"} + from +
                               QStringList{"--size", "240x160", "--output", dir.filePath(name)};
            if (!creases) args << QStringLiteral("--no-creases");
            const Result r = runPaperfold(args, true);
            return r.exitCode == 0 ? QImage(dir.filePath(name)) : QImage();
        };
        const QImage marked = draw({"--load", sheet}, "marked.png", true);
        const QImage clean = draw({"--load", sheet}, "clean.png", false);
        QVERIFY(!marked.isNull() && !clean.isNull());
        QVERIFY(marked != clean);
        const QImage fresh = draw({"--scene", "press"}, "fresh.png", true);
        QVERIFY(!fresh.isNull());
        QCOMPARE(fresh, draw({"--scene", "press"}, "fresh-clean.png", false));
    }

    void renderComparesWithAReference() {
        QTemporaryDir dir;
        const QString base = dir.filePath(QStringLiteral("base.png"));
        const QStringList shot{"render", "--scene", "press", "--steps", "100", "--size", "240x160"};
        QCOMPARE(runPaperfold(shot + QStringList{"--output", base}, true).exitCode, 0);
        // The same picture matches.
        const Result same = runPaperfold(
            shot + QStringList{"--output", dir.filePath("same.png"), "--reference", base}, true);
        QCOMPARE(same.exitCode, 0);
        QVERIFY(QString::fromUtf8(same.out).contains(QStringLiteral("0.000 %")));
        // A reference of another size: said, exit 4, and no difference image named (it
        // said "100.000 % of pixels differ" and named one it never wrote).
        const Result sized =
            runPaperfold({"render", "--scene", "press", "--steps", "100", "--size", "160x100",
                          "--output", dir.filePath("small.png"), "--reference", base},
                         true);
        QCOMPARE(sized.exitCode, 4);
        QVERIFY2(sized.err.contains("the sizes differ (render it with --size 240x160)"),
                 sized.err.constData());
        QVERIFY(!sized.err.contains("diff.png"));
        QVERIFY(QString::fromUtf8(sized.out).contains(
            QStringLiteral("it is 240x160, the image 160x100")));
        // Another view does not: exit 4 and a difference image next to the output.
        const Result other =
            runPaperfold(shot + QStringList{"--view", "top", "--output", dir.filePath("other.png"),
                                            "--reference", base},
                         true);
        QCOMPARE(other.exitCode, 4);
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("other.diff.png"))));
    }

    void renderRejectsBadValues_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("no output") << QStringList{"render"} << "--output";
        QTest::newRow("bad size") << QStringList{"render", "--size", "10x10", "--output", "a.png"}
                                  << "size";
        QTest::newRow("size garbage")
            << QStringList{"render", "--size", "big", "--output", "a.png"} << "size";
        // Options that did nothing without another, taken without a word (exit 0).
        QTest::newRow("steps between frames of no sequence")
            << QStringList{"render", "--every", "3", "--output", "a.png"}
            << "--every applies only with --frames";
        QTest::newRow("a threshold with nothing to compare")
            << QStringList{"render", "--threshold", "0.5", "--output", "a.png"}
            << "--threshold applies only with --reference";
        QTest::newRow("no legend of no overlay")
            << QStringList{"render", "--no-legend", "--output", "a.png"}
            << "--no-legend applies only with --overlay";
        QTest::newRow("a reference that is not a PNG")
            << QStringList{"render",
                           "--resolution",
                           "5",
                           "--size",
                           "32x32",
                           "--reference",
                           QStringLiteral(PAPERFOLD_EXE),
                           "--output",
                           QDir::temp().filePath("pf-never-written.png")}
            << ": not a PNG image";
        QTest::newRow("a view and a camera")
            << QStringList{"render", "--view", "top", "--camera", "0,10,1", "--output", "a.png"}
            << "--view and --camera exclude each other";
        QTest::newRow("bad view") << QStringList{"render", "--view", "side", "--output", "a.png"}
                                  << "side";
        QTest::newRow("an option twice")
            << QStringList{"render", "--scene", "press", "--scene", "drape", "--output", "a.png"}
            << "--scene is given more than once";
        QTest::newRow("bad camera")
            << QStringList{"render", "--camera", "1,95,1", "--output", "a.png"} << "camera";
        QTest::newRow("bad overlay")
            << QStringList{"render", "--overlay", "springs,glitter", "--output", "a.png"}
            << "glitter";
        QTest::newRow("bad paper colour")
            << QStringList{"render", "--paper-color", "glitter", "--output", "a.png"} << "glitter";
        QTest::newRow("see-through paper colour")
            << QStringList{"render", "--paper-color", "transparent", "--output", "a.png"}
            << "'transparent' is not opaque";
        QTest::newRow("paper colour with alpha")
            << QStringList{"render", "--paper-color", "#80ff0000", "--output", "a.png"}
            << "not opaque";
        QTest::newRow("missing texture")
            << QStringList{"render", "--texture", "/nonexistent/paper.png", "--output", "a.png"}
            << "--texture";
        QTest::newRow("bad subdiv")
            << QStringList{"render", "--subdiv", "7", "--output", "a.png"} << "subdiv";
        QTest::newRow("sequence without pattern")
            << QStringList{"render", "--frames", "3", "--output", "a.png"} << "pattern";
        QTest::newRow("missing folder")
            << QStringList{"render", "--output", "/nonexistent/dir/a.png"} << "folder";
        QTest::newRow("not a png name")
            << QStringList{"render", "--output", "/tmp/pf-not-png-test.txt"}
            << "'/tmp/pf-not-png-test.txt' does not end in .png";
        QTest::newRow("sequence not a png name")
            << QStringList{"render", "--frames", "2", "--output", "/tmp/pf-frame-%d.jpg"}
            << "does not end in .png";
        QTest::newRow("unreadable reference") << QStringList{"render",
                                                             "--size",
                                                             "64x64",
                                                             "--output",
                                                             "/tmp/pf-ref-test.png",
                                                             "--reference",
                                                             "/nonexistent.png"}
                                              << "reference";
    }
    void renderRejectsBadValues() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        QFile::remove(QStringLiteral("/tmp/pf-not-png-test.txt"));
        const Result r = runPaperfold(args, true);
        QVERIFY(r.exitCode > 0);
        const QString err = QString::fromUtf8(r.err).trimmed();
        QVERIFY2(err.contains(mentions), qPrintable(err));
        // Ours first (libpng printed "libpng error: Not a PNG file" before it). Not the only
        // line: under AddressSanitizer the leak checker reports its suppressions after it.
        QVERIFY2(err.startsWith(QLatin1String("paperfold: ")), qPrintable(err));
        QVERIFY(!QFileInfo::exists(QStringLiteral("/tmp/pf-not-png-test.txt")));
    }

    void stabilityMapsWhereMethodsFail() {
        // A sweep of every method over a grid: numbers, checked in the Release build (it
        // took 50-160 s of the sanitized suite, whose work is the memory it touches).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("a numeric sweep; run in the Release build");
        QTemporaryDir dir;
        const Result r = runPaperfold({"stability", "--quick", "--output-dir", dir.path()}, true);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile csv(dir.filePath(QStringLiteral("stability.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 9 * 3 * 9); // header + methods × scenes × (3 × 3) cells
        QMap<QString, int> failures;
        QStringList xpbdFailures;
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(QLatin1Char(','));
            QCOMPARE(f.size(), 9);
            failures[f[0]] += f[5] != QLatin1String("stable");
            if (f[0] == QLatin1String("xpbd") && f[5] != QLatin1String("stable"))
                xpbdFailures << f[1] + QLatin1Char('@') + f[2] + QLatin1Char('x') + f[3];
        }
        // What the theory says, on this grid (docs/solver-lab.md).
        QCOMPARE(failures.value(QStringLiteral("jacobi-1")), 0);
        QCOMPARE(failures.value(QStringLiteral("backward-euler")), 0);
        QVERIFY(failures.value(QStringLiteral("jacobi-1-unclamped")) > 0);
        QVERIFY(failures.value(QStringLiteral("jacobi-0")) > 0);
        QVERIFY(failures.value(QStringLiteral("symplectic")) > 0);
        // xpbd: only compress, crushed at 1/30 s at each stiffness and at ×1 at 1/480 s.
        QCOMPARE(xpbdFailures, QStringList({QStringLiteral("compress@0.0333333x1"),
                                            QStringLiteral("compress@0.00208333x1"),
                                            QStringLiteral("compress@0.0333333x100"),
                                            QStringLiteral("compress@0.0333333x10000")}));
        for (const char* m : {"jacobi-0", "jacobi-1", "symplectic", "backward-euler", "xpbd"}) {
            const QImage map(
                dir.filePath(QStringLiteral("stability_%1.png").arg(QLatin1String(m))));
            QVERIFY(!map.isNull());
        }
    }

    void benchScalingChartsCostAgainstSize() {
        // A benchmark, not a timed test: what is checked is what it reports, not how fast.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("a timing sweep; run in the Release build");
        QTemporaryDir dir;
        // Without --integrator it measures the default one.
        const Result r = runPaperfold(
            {"bench", "--scaling", "--quick", "--threads", "2", "--output-dir", dir.path()}, true);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.out.startsWith("build: "));
        QVERIFY2(
            r.out.contains("integrator: " + QByteArray::fromStdString(pf::SimParams{}.integrator) +
                           " (the editor's settings)"),
            r.out.constData());
        QVERIFY(r.out.contains("threads: 2 of the machine's"));
        QVERIFY(r.out.contains(
            "largest real-time sheet (240 steps/s), press (tool crumpling), 2 thread(s)"));
        QVERIFY(r.out.contains("speed-up on 2 threads, drape (swinging), resolution 27: "));
        QFile csv(dir.filePath(QStringLiteral("scaling.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 3 * 3 * 2); // header + 3 loads × 3 resolutions × 1, 2 threads
        QMap<QString, QList<double>> springs, cost;
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(QLatin1Char(','));
            QCOMPARE(f.size(), 8);
            QCOMPARE(f[0], QStringLiteral("xpbd"));
            QVERIFY(f[1] == QStringLiteral("1") || f[1] == QStringLiteral("2"));
            const QString series = f[2] + QLatin1Char('/') + f[1];
            springs[series] << f[5].toDouble();
            cost[series] << f[7].toDouble();
            // ns per spring per step is what the steps per second and springs say.
            const double product = f[7].toDouble() * f[6].toDouble() * f[5].toDouble();
            QVERIFY2(std::abs(product / 1e9 - 1.0) < 1e-4, qPrintable(line));
        }
        for (const auto& s : springs) QVERIFY(s.size() == 3 && s[0] < s[1] && s[1] < s[2]);
        // Every load at every size on each thread count was measured (a sheet that blew up
        // would be left out).
        QCOMPARE(cost.size(), 6);
        const QImage chart(dir.filePath(QStringLiteral("scaling.png")));
        QVERIFY(!chart.isNull());
        // An unknown integrator, and --integrator without --scaling, are refused.
        QCOMPARE(runPaperfold({"bench", "--scaling", "--integrator", "rubber"}).exitCode, 1);
        QCOMPARE(runPaperfold({"bench", "--quick", "--integrator", "xpbd"}).exitCode, 1);
    }

    void benchChartsSpeedAgainstAccuracy() {
        // A sweep of every method over a grid: numbers, checked in the Release build (it
        // took 50-160 s of the sanitized suite, whose work is the memory it touches).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("a numeric sweep; run in the Release build");
        QTemporaryDir dir;
        const Result r = runPaperfold({"bench", "--quick", "--output-dir", dir.path()}, true);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.out.startsWith("build: "), r.out.left(200).constData());
        QFile csv(dir.filePath(QStringLiteral("bench.csv")));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines =
            QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 2 * 7 * 3); // header + 2 scenes × 7 methods × 3 steps
        QMap<QString, QList<double>> error, fall, dropError, energy, stretch;
        const QString xpbd = QStringLiteral("xpbd office paper (40 sub-steps)");
        for (const QString& line : lines.mid(1)) {
            const QStringList f = line.split(QLatin1Char(','));
            QCOMPARE(f.size(), 14);
            // xpbd is measured against its own physics, everything else against the springs'.
            QCOMPARE(f[8], QLatin1String(f[1] == xpbd ? "xpbd" : "backward-euler"));
            stretch[f[1]] << f[10].toDouble();
            if (f[0] == QLatin1String("drop")) {
                dropError[f[1]] << f[7].toDouble();
                continue;
            }
            energy[f[1]] << f[12].toDouble();
            error[f[1]] << f[7].toDouble();
            fall[f[1]] << f[11].toDouble();
        }
        // Paper with its real stiffness: under 1 % stretch at every step in both scenes,
        // free fall at g, and it converges toward its own small-step run.
        QCOMPARE(stretch.value(xpbd).size(), 6);
        for (double e : stretch.value(xpbd))
            QVERIFY2(e >= 0.0 && e < 0.01, qPrintable(QString::number(e)));
        for (double a : fall.value(xpbd)) QVERIFY(std::abs(a - 1.0) < 1e-6);
        const auto own = error.value(xpbd);
        QVERIFY(own.size() == 3 && own[0] > own[1] && own[1] > own[2]);
        // The fix moves one sweep toward the front where springs lie along gravity: at
        // every step the tilted drop's trajectory error at least halves, at the same cost.
        const auto paper = dropError.value(QStringLiteral("jacobi K=1 (paper)"));
        const auto fixed = dropError.value(QStringLiteral("jacobi K=1 + gravity outside"));
        QCOMPARE(paper.size(), 3);
        QCOMPARE(fixed.size(), 3);
        for (int k = 0; k < 3; ++k)
            QVERIFY2(fixed[k] < 0.5 * paper[k],
                     qPrintable(QStringLiteral("%1 vs %2").arg(fixed[k]).arg(paper[k])));
        // The exact method converges as the step shrinks; the fix restores free fall.
        const auto be = error.value(QStringLiteral("backward Euler (CG)"));
        // Implicit Euler dissipates: undamped, it never gains energy, and loses less
        // as the step shrinks.
        const auto beEnergy = energy.value(QStringLiteral("backward Euler (CG)"));
        QVERIFY(beEnergy.size() == 3 && beEnergy[2] <= 1.0 + 1e-6 && beEnergy[0] < beEnergy[1] &&
                beEnergy[1] < beEnergy[2]);
        QVERIFY(be.size() == 3 && be[0] > be[1] && be[1] > be[2]);
        for (double a : fall.value(QStringLiteral("jacobi K=1 + gravity outside")))
            QVERIFY(std::abs(a - 1.0) < 1e-6);
        for (double a : fall.value(QStringLiteral("jacobi K=1 (paper)"))) QVERIFY(a < 0.1);
        const QImage chart(dir.filePath(QStringLiteral("bench_drape.png")));
        QVERIFY(!chart.isNull());
        int coloured = 0; // markers are drawn: pixels that are neither grey nor white
        for (int y = 0; y < chart.height(); y += 2)
            for (int x = 0; x < chart.width(); x += 2) {
                const QColor c = chart.pixelColor(x, y);
                coloured += c.saturation() > 100;
            }
        QVERIFY(coloured > 100);
    }

    void replayDoesARecordedSessionAgain() {
        // A session as the editor records one: a push stroke along the press path (which
        // breaks the sheet), its undo, then steps.
        pf::EditSession session(pf::test::machineryScene("press"));
        const auto path = pf::makeScene("press")->script.sphereKeys;
        const double radius = session.world().sphere.radius;
        for (double t = 0.0; t < 0.6; t += 1.0 / 60.0) {
            session.setTool(pf::spherePathAt(path, t), radius, true, true);
            QCOMPARE(session.advance(4), pf::StepStatus::Ok);
        }
        session.setTool(pf::spherePathAt(path, 0.6), radius, true, false);
        session.undoStroke(0);
        QCOMPARE(session.advance(40), pf::StepStatus::Ok);
        const QString expected = QStringLiteral("%1").arg(pf::stateHash(session.world().sheet), 16,
                                                          16, QLatin1Char('0'));

        QTemporaryDir dir;
        const QString rec = dir.filePath(QStringLiteral("session.paperrec"));
        QString error;
        QVERIFY2(pf::saveRecording(session.log(), rec, &error), qPrintable(error));
        const QString sheet = dir.filePath(QStringLiteral("end.paper"));
        const Result r =
            runPaperfold({"replay", rec, "--stats", "--save", sheet, "--threads", "2"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o[QStringLiteral("state_hash")].toString(), expected);
        QCOMPARE(o[QStringLiteral("threads")].toInt(), 2);
        QCOMPARE(o[QStringLiteral("complete")].toBool(), true);
        QCOMPARE(o[QStringLiteral("steps")].toInt(), int(session.world().stepCount));
        QVERIFY(QFileInfo::exists(sheet));
        // The recording carries the state it ended in; this replay ends there, and says
        // nothing more.
        QCOMPARE(o[QStringLiteral("recorded_state_hash")].toString(), expected);
        QCOMPARE(o[QStringLiteral("matches_recording")].toBool(), true);
        QVERIFY2(r.err.isEmpty(), r.err.constData());

        // On a terminal the replay shows the step it has reached, and ends on the last one;
        // above, in a pipe, it said nothing. `script` gives it a terminal.
        if (!QStandardPaths::findExecutable(QStringLiteral("script")).isEmpty()) {
            QProcess terminal;
            terminal.start(
                QStringLiteral("script"),
                {"-qec", "exec \"" PAPERFOLD_EXE "\" replay \"" + rec + "\"", "/dev/null"});
            QVERIFY(terminal.waitForFinished(120000 * PAPERFOLD_TEST_SLOWDOWN));
            QCOMPARE(terminal.exitCode(), 0);
            const QByteArray shown = terminal.readAllStandardOutput();
            const QByteArray last = QStringLiteral("\rreplaying: step %1 of %1 (100 %)\r\n")
                                        .arg(session.world().stepCount)
                                        .toUtf8();
            QVERIFY2(shown.startsWith("\rreplaying: step ") && shown.contains(last),
                     shown.constData());
        }

        // A recording whose session ended elsewhere (as one made by another version of
        // PaperFold that undoes differently): the replay runs as this version does, and
        // says it ended elsewhere.
        pf::EditLog other = session.log();
        other.endState = *other.endState ^ 1;
        const QString otherRec = dir.filePath(QStringLiteral("other.paperrec"));
        QVERIFY2(pf::saveRecording(other, otherRec, &error), qPrintable(error));
        const Result elsewhere = runPaperfold({"replay", otherRec, "--stats"});
        QCOMPARE(elsewhere.exitCode, 0);
        const QJsonObject e = QJsonDocument::fromJson(elsewhere.out).object();
        QCOMPARE(e[QStringLiteral("state_hash")].toString(), expected);
        QCOMPARE(e[QStringLiteral("matches_recording")].toBool(), false);
        QCOMPARE(elsewhere.err.count('\n'), 1);
        QVERIFY2(elsewhere.err.contains("another version of PaperFold"), elsewhere.err.constData());
        // One made before recordings carried it: nothing to compare, nothing said.
        other.endState.reset();
        QVERIFY2(pf::saveRecording(other, otherRec, &error), qPrintable(error));
        const Result older = runPaperfold({"replay", otherRec, "--stats"});
        QCOMPARE(older.exitCode, 0);
        QVERIFY(!QJsonDocument::fromJson(older.out).object().contains(
            QStringLiteral("matches_recording")));
        QVERIFY2(older.err.isEmpty(), older.err.constData());

        // The same session as an image sequence: the start, then every 10 steps.
        const QString pattern = dir.filePath(QStringLiteral("f_%03d.png"));
        const Result frames = runPaperfold(
            {"replay", rec, "--render", pattern, "--every", "10", "--size", "96x64", "--stats"},
            true);
        QCOMPARE(frames.exitCode, 0);
        QCOMPARE(
            QJsonDocument::fromJson(frames.out).object()[QStringLiteral("state_hash")].toString(),
            expected);
        const int steps = int(session.world().stepCount);
        const int count = steps / 10 + 1 + (steps % 10 != 0 ? 1 : 0);
        QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("f_*.png")}).size(), count);
        const QImage first(dir.filePath(QStringLiteral("f_000.png")));
        const QImage last(
            dir.filePath(QStringLiteral("f_%1.png").arg(count - 1, 3, 10, QLatin1Char('0'))));
        QCOMPARE(first.size(), QSize(96, 64));
        QVERIFY(!last.isNull());
        QVERIFY(first != last); // the stroke and the settling changed the picture
        // Every so many steps that do not divide the session's: the start, the one frame
        // inside it, and its end (it stopped at the frame inside).
        QVERIFY(steps > 2);
        const QString apart = dir.filePath(QStringLiteral("a_%03d.png"));
        QCOMPARE(runPaperfold({"replay", rec, "--render", apart, "--every",
                               QString::number(steps - 1), "--size", "96x64"},
                              true)
                     .exitCode,
                 0);
        QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("a_*.png")}).size(), 3);
        const QString whole = dir.filePath(QStringLiteral("w_%03d.png"));
        QCOMPARE(runPaperfold({"replay", rec, "--render", whole, "--every", QString::number(steps),
                               "--size", "96x64"},
                              true)
                     .exitCode,
                 0);
        QCOMPARE(QImage(dir.filePath(QStringLiteral("a_002.png"))),
                 QImage(dir.filePath(QStringLiteral("w_001.png"))));
        QCOMPARE(runPaperfold({"replay", rec, "--render", dir.filePath("no_field.png")}).exitCode,
                 1);
        // Without --render nothing is drawn: a camera of "garbage" was taken, exit 0.
        const Result undrawn = runPaperfold({"replay", rec, "--camera", "garbage"});
        QCOMPARE(undrawn.exitCode, 1);
        QVERIFY2(undrawn.err.contains("--camera applies only with --render"),
                 undrawn.err.constData());
        // The sheet saved under a frame's name replaced frame 0, and rc 0.
        const Result clash =
            runPaperfold({"replay", rec, "--render", dir.filePath("clash_%d.png"), "--every", "100",
                          "--save", dir.filePath("clash_0.png")});
        QCOMPARE(clash.exitCode, 1);
        QVERIFY2(clash.err.contains("--save: '" + dir.filePath("clash_0.png").toUtf8() +
                                    "' is also frame 0 of --render"),
                 clash.err.constData());
        QVERIFY(QDir(dir.path()).entryList({QStringLiteral("clash*")}).isEmpty());
        // PNG data under another name would not open as what the name says.
        const Result text = runPaperfold({"replay", rec, "--render", dir.filePath("t_%03d.txt")});
        QCOMPARE(text.exitCode, 1);
        QVERIFY2(text.err.contains("does not end in .png"), text.err.constData());
        QVERIFY(QDir(dir.path()).entryList({QStringLiteral("t_*")}).isEmpty());

        // A broken recording: one line, exit 1, nothing written.
        QFile f(rec);
        QVERIFY(f.open(QIODevice::ReadWrite));
        const QByteArray bytes = f.readAll();
        f.resize(bytes.size() / 3);
        f.close();
        const Result bad = runPaperfold({"replay", rec});
        QCOMPARE(bad.exitCode, 1);
        QCOMPARE(bad.err.count('\n'), 1);
        QVERIFY2(bad.err.contains("session.paperrec"), bad.err.constData());
        QCOMPARE(runPaperfold({"replay"}).exitCode, 1);
    }

    void divergenceIsReportedNotCrashed() {
        // The sheet saved is the last good state, as the message says: not one already
        // blown up (at this step it was stretched 605 times over, a step before the one
        // that went 1 km out).
        QTemporaryDir dir;
        const QString saved = dir.filePath(QStringLiteral("kept.paper"));
        const Result r =
            runPaperfold({"simulate", "--scene", "drape", "--integrator", "symplectic", "--dt",
                          "0.02", "--steps", "2000", "--stats", "--save", saved});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(QString::fromUtf8(r.err).contains(QStringLiteral("diverged")));
        const auto o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o[QStringLiteral("diverged")].toBool(), true);
        const Result kept = runPaperfold({"simulate", "--load", saved, "--steps", "0", "--stats"});
        QCOMPARE(kept.exitCode, 0);
        const double stretch =
            QJsonDocument::fromJson(kept.out).object()[QStringLiteral("max_stretch")].toDouble(-1);
        QVERIFY2(stretch >= 0.0 && stretch < pf::kDivergenceStretch - 1.0,
                 qPrintable(QString::number(stretch)));
        // A sequence names the image it stopped before and keeps the ones before it
        // ("frame 3/10" counted from 1 and "diverged before frame 3" from 0).
        const QString pattern = dir.filePath(QStringLiteral("d%02d.png"));
        const Result sequence = runPaperfold(
            {"render", "--scene", "drop", "--integrator", "symplectic", "--dt", "0.05", "--frames",
             "10", "--every", "1", "--size", "64x48", "--output", pattern});
        QCOMPARE(sequence.exitCode, 3);
        const QStringList written =
            QDir(dir.path()).entryList({QStringLiteral("d*.png")}, QDir::Files, QDir::Name);
        QVERIFY(!written.isEmpty());
        const QString next =
            dir.filePath(QStringLiteral("d%1.png").arg(written.size(), 2, 10, QLatin1Char('0')));
        QVERIFY2(sequence.err.contains(QStringLiteral("diverged before %1; the %2 image")
                                           .arg(next)
                                           .arg(written.size())
                                           .toUtf8()),
                 sequence.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestSimulateCli)
#include "test_simulate_cli.moc"
