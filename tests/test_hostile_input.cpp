// Everything a user types or opens, probed as a hostile tester would: format strings in
// output names, device nodes and other non-files as targets, an output equal to an
// input, a full disk, a read-only folder, files built to multiply the loader's memory,
// non-finite camera values, far-away sheets, and an editor started with no display.
// Each case is a regression test for a reproduction in the issue that found it.
#include "OutputFile.h"
#include "OutputPattern.h"
#include "PngDecode.h"
#include "RecordingFile.h"
#include "ReferenceImage.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SheetValidation.h"

#include <QBuffer>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

struct Result {
    int exitCode; // -2 for a crash (signal), -1 for a time-out
    QString err;
};

// The headless commands' environment: Qt's offscreen platform, whatever the caller has.
QProcessEnvironment headless() {
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    e.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    return e;
}

// Sanitizer builds run the commands many times slower; their limits scale with it.
constexpr int kSlowdown = PAPERFOLD_TEST_SLOWDOWN;

Result runPaperfold(const QStringList& args, int timeoutMs = 120000,
                    const QProcessEnvironment& env = headless()) {
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(PAPERFOLD_EXE), args);
    if (!p.waitForFinished(timeoutMs * kSlowdown)) {
        p.kill();
        p.waitForFinished();
        return {-1, QStringLiteral("timeout")};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2,
            QString::fromUtf8(p.readAllStandardError())};
}

QByteArray fileHash(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    QCryptographicHash h(QCryptographicHash::Sha256);
    h.addData(&f);
    return h.result();
}

void writeBytes(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

// A valid sheet file with one more top-level key, "junk", holding `count` one-element
// arrays [0]: 2 bytes each in the file, but a whole value tree each if it were built.
QByteArray sheetWithJunk(qint64 count) {
    QByteArray bytes = pf::encodeWorld(*pf::makeScene("press"));
    const auto head = static_cast<unsigned char>(bytes[0]);
    Q_ASSERT(head >= 0xa0 && head < 0xb7); // a map of fewer than 23 entries
    bytes[0] = static_cast<char>(head + 1);
    bytes += QByteArray("\x64junk\x9a", 6);
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((count >> shift) & 0xff);
    bytes += QByteArray("\x81\x00", 2).repeated(count);
    return bytes;
}

// Peak resident memory of one run of paperfold, in bytes (wait4 gives this child's own).
qint64 peakMemoryOf(const QStringList& args) {
    std::vector<QByteArray> storage{QByteArray(PAPERFOLD_EXE)};
    for (const QString& a : args) storage.push_back(a.toLocal8Bit());
    std::vector<char*> argv;
    for (QByteArray& s : storage) argv.push_back(s.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, PAPERFOLD_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    int status = 0;
    struct rusage usage {};
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status)) return -1;
    return qint64(usage.ru_maxrss) * 1024;
}

// Runs a shell script in a private mount namespace (unshare), where it may mount a
// small tmpfs: the only way to give a test a really full or read-only file system.
// Returns false when this machine does not allow it.
bool unshareWorks() {
    QProcess p;
    p.start(QStringLiteral("unshare"),
            {QStringLiteral("--user"), QStringLiteral("--map-root-user"), QStringLiteral("--mount"),
             QStringLiteral("sh"), QStringLiteral("-c"),
             QStringLiteral("mount -t tmpfs -o size=64k none /tmp")});
    return p.waitForFinished(20000 * kSlowdown) && p.exitStatus() == QProcess::NormalExit &&
           p.exitCode() == 0;
}

// Runs `script` with $PF set to paperfold and $D a fresh tmpfs of `size` mounted on a
// folder of `outside`; the script leaves what the test reads in $OUT (= outside).
bool runInPrivateMount(const QString& outside, const QString& mountOptions, const QString& script) {
    QDir(outside).mkpath(QStringLiteral("mnt"));
    const QString full = QStringLiteral("set -u; mount -t tmpfs -o %1 none \"$D\" || exit 97; %2")
                             .arg(mountOptions, script);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PF"), QStringLiteral(PAPERFOLD_EXE));
    env.insert(QStringLiteral("D"), outside + QStringLiteral("/mnt"));
    env.insert(QStringLiteral("OUT"), outside);
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral("unshare"),
            {QStringLiteral("--user"), QStringLiteral("--map-root-user"), QStringLiteral("--mount"),
             QStringLiteral("sh"), QStringLiteral("-c"), full});
    return p.waitForFinished(300000 * kSlowdown) && p.exitStatus() == QProcess::NormalExit &&
           p.exitCode() == 0;
}

QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()).trimmed() : QString();
}

} // namespace

class TestHostileInput : public QObject {
    Q_OBJECT

  private slots:
    // --- 1. Format strings -----------------------------------------------------------

    void outputPatternParsesOnlyANumberField_data() {
        QTest::addColumn<QString>("pattern");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<QString>("frame12");
        QTest::newRow("plain name") << "shot.png" << true << "shot.png";
        QTest::newRow("%d") << "f_%d.png" << true << "f_12.png";
        QTest::newRow("%04d") << "f_%04d.png" << true << "f_0012.png";
        QTest::newRow("%01d") << "%01d" << true << "12";
        QTest::newRow("%n") << "x_%n.png" << false << "";
        QTest::newRow("%s") << "o_%s%s%s%s.png" << false << "";
        QTest::newRow("two fields") << "o_%d_%d.png" << false << "";
        QTest::newRow("%%") << "100%%.png" << false << "";
        QTest::newRow("%x") << "f_%x.png" << false << "";
        QTest::newRow("%00d") << "f_%00d.png" << false << "";
        QTest::newRow("%4d") << "f_%4d.png" << false << "";
        QTest::newRow("%010d") << "f_%010d.png" << false << "";
        QTest::newRow("%*d") << "f_%*d.png" << false << "";
        QTest::newRow("trailing %") << "f_%" << false << "";
        QTest::newRow("%0 at end") << "f_%0" << false << "";
        QTest::newRow("%ld") << "f_%ld" << false << "";
    }
    void outputPatternParsesOnlyANumberField() {
        QFETCH(QString, pattern);
        QFETCH(bool, valid);
        QFETCH(QString, frame12);
        QString error;
        const auto p = pf::OutputPattern::parse(pattern, &error);
        QCOMPARE(bool(p), valid);
        if (valid) {
            QCOMPARE(p->path(12), frame12);
        } else {
            QVERIFY(error.contains(pattern)); // the message quotes what was typed, intact
            QVERIFY(error.contains(QStringLiteral("%0Nd")));
        }
    }

    void formatStringsInOutputNamesAreRefused_data() {
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("output");
        QTest::newRow("%n") << QStringList{} << "x_%n.png";
        QTest::newRow("%s sequence")
            << QStringList{"--frames", "2", "--every", "1"} << "o_%s%s%s%s.png";
        QTest::newRow("%d three times") << QStringList{"--frames", "2"} << "o_%d_%d_%d.png";
    }
    void formatStringsInOutputNamesAreRefused() {
        QFETCH(QStringList, extra);
        QFETCH(QString, output);
        QTemporaryDir dir;
        const Result r = runPaperfold(QStringList{"render", "--scene", "press", "--size", "32x32",
                                                  "--output", dir.filePath(output)} +
                                      extra);
        QCOMPARE(r.exitCode, 1); // refused, not a crash (-2)
        QVERIFY2(r.err.contains(QStringLiteral("--output")), qPrintable(r.err));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }

    void aPatternNumbersTheFrames() {
        QTemporaryDir dir;
        const Result r =
            runPaperfold({"render", "--scene", "press", "--size", "32x32", "--frames", "2",
                          "--every", "1", "--output", dir.filePath(QStringLiteral("f_%03d.png"))});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 (QStringList{"f_000.png", "f_001.png"}));
    }

    // --- 2. Targets that are not regular files -----------------------------------

    void nonFilesAreNeverReplaced() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("pipe.obj"));
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        const QString folder = dir.filePath(QStringLiteral("folder.obj"));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder.obj")));
        const QString loop = dir.filePath(QStringLiteral("loop.obj"));
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("loop2.obj")), loop));
        QVERIFY(QFile::link(loop, dir.filePath(QStringLiteral("loop2.obj"))));
        const QString dangling = dir.filePath(QStringLiteral("dangling.obj"));
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("nothing/x")), dangling));
        for (const QString& target : {fifo, folder, loop, dangling}) {
            for (const QStringList& args :
                 {QStringList{"simulate", "--steps", "1", "--save", target},
                  QStringList{"export", "--subdiv", "0", "--output", target}}) {
                const Result r = runPaperfold(args, 30000);
                QVERIFY2(r.exitCode == 1, qPrintable(target + QLatin1Char(' ') + r.err));
            }
        }
        struct stat st {};
        QVERIFY(lstat(QFile::encodeName(fifo).constData(), &st) == 0 && S_ISFIFO(st.st_mode));
        QVERIFY(QFileInfo(folder).isDir());
        QVERIFY(QFileInfo(loop).isSymLink() && QFileInfo(dangling).isSymLink());
    }

    void deviceNodesAreNeverReplaced() {
        if (geteuid() != 0) QSKIP("creating a device node needs root; skipped");
        QTemporaryDir dir;
        // The same device as /dev/null (1, 3), made here so nothing real is at stake.
        const QString node = dir.filePath(QStringLiteral("null.obj"));
        if (mknod(QFile::encodeName(node).constData(), S_IFCHR | 0666, makedev(1, 3)) != 0)
            QSKIP("mknod is not allowed in this container; skipped");
        for (const QStringList& args :
             {QStringList{"simulate", "--steps", "1", "--save", node},
              QStringList{"export", "--subdiv", "0", "--output", node},
              QStringList{"render", "--size", "32x32", "--output", node}}) {
            const Result r = runPaperfold(args);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(QStringLiteral("not a regular file")), qPrintable(r.err));
        }
        struct stat st {};
        QVERIFY(lstat(QFile::encodeName(node).constData(), &st) == 0 && S_ISCHR(st.st_mode));
        QCOMPARE(major(st.st_rdev), 1u);
    }

    void aLinkToAFileIsFollowedAndKept() {
        QTemporaryDir dir;
        const QString real = dir.filePath(QStringLiteral("real.paper"));
        const QString link = dir.filePath(QStringLiteral("link.paper"));
        QCOMPARE(runPaperfold({"simulate", "--steps", "1", "--save", real}).exitCode, 0);
        const QByteArray before = fileHash(real);
        QVERIFY(QFile::link(real, link));
        QCOMPARE(runPaperfold({"simulate", "--steps", "2", "--save", link}).exitCode, 0);
        QVERIFY(QFileInfo(link).isSymLink());
        QVERIFY(fileHash(real) != before); // the file the link names was replaced
        QVERIFY(pf::loadWorld(real).world);
    }

    // --- 3. An output that is an input --------------------------------------------

    void anOutputEqualToAnInputIsRefused() {
        QTemporaryDir dir;
        const QString sheet = dir.filePath(QStringLiteral("g.paper"));
        QCOMPARE(runPaperfold({"simulate", "--steps", "5", "--save", sheet}).exitCode, 0);
        const QString ref = dir.filePath(QStringLiteral("ref.png"));
        QCOMPARE(runPaperfold({"render", "--size", "32x32", "--output", ref}).exitCode, 0);
        // Other names of the same files: a hard link, a symbolic link, a relative path.
        const QString hard = dir.filePath(QStringLiteral("hard.obj"));
        QCOMPARE(::link(QFile::encodeName(sheet).constData(), QFile::encodeName(hard).constData()),
                 0);
        const QString soft = dir.filePath(QStringLiteral("soft.png"));
        QVERIFY(QFile::link(ref, soft));
        const QByteArray sheetBefore = fileHash(sheet), refBefore = fileHash(ref);

        const QList<QStringList> cases{
            {"render", "--load", sheet, "--size", "32x32", "--output", sheet},
            {"render", "--load", sheet, "--size", "32x32", "--output", hard},
            {"simulate", "--load", sheet, "--steps", "1", "--save", sheet},
            {"simulate", "--load", sheet, "--steps", "1", "--save", hard},
            {"export", "--load", sheet, "--output", hard},
            {"render", "--size", "32x32", "--output", ref, "--reference", ref},
            {"render", "--size", "32x32", "--output", soft, "--reference", ref},
        };
        for (const QStringList& args : cases) {
            const Result r = runPaperfold(args);
            QVERIFY2(r.exitCode == 1, qPrintable(args.join(' ') + QLatin1Char('\n') + r.err));
            QVERIFY2(r.err.contains(QStringLiteral("destroy")), qPrintable(r.err));
        }
        QCOMPARE(fileHash(sheet), sheetBefore);
        QCOMPARE(fileHash(ref), refBefore);
        // The comparison itself still works against a different output.
        const Result same =
            runPaperfold({"render", "--size", "32x32", "--output",
                          dir.filePath(QStringLiteral("again.png")), "--reference", ref});
        QCOMPARE(same.exitCode, 0);
    }

    // --- 4. A full disk and a read-only folder --------------------------------------

    void aFullDiskIsAnErrorThatKeepsTheOldFile() {
        if (!unshareWorks()) QSKIP("no private mount namespace here (unshare); skipped");
        QTemporaryDir outside;
        // Save a sheet, fill the file system, then save, render and map stability into it.
        const QString script = QStringLiteral(
            "cd \"$D\" && \"$PF\" simulate --steps 1 --save keep.paper >/dev/null || exit 98; "
            "cp keep.paper \"$OUT/copy.paper\"; "
            "mkdir map; dd if=/dev/zero of=fill bs=4096 2>/dev/null; "
            "\"$PF\" simulate --steps 2 --save keep.paper 2>\"$OUT/save.err\"; echo $? "
            ">\"$OUT/save.rc\"; "
            "\"$PF\" render --size 64x64 --output shot.png 2>\"$OUT/render.err\" "
            ">/dev/null; echo $? >\"$OUT/render.rc\"; "
            "\"$PF\" stability --quick --output-dir map >\"$OUT/map.out\" 2>\"$OUT/map.err\"; "
            "echo $? >\"$OUT/map.rc\"; "
            "cmp -s keep.paper \"$OUT/copy.paper\" && echo same >\"$OUT/kept\"; "
            "ls -A . map >\"$OUT/list\" 2>&1; exit 0");
        QVERIFY(runInPrivateMount(outside.path(), QStringLiteral("size=256k"), script));
        QCOMPARE(readText(outside.filePath(QStringLiteral("save.rc"))), QStringLiteral("2"));
        QVERIFY2(readText(outside.filePath(QStringLiteral("save.err")))
                     .contains(QStringLiteral("No space left on device")),
                 qPrintable(readText(outside.filePath(QStringLiteral("save.err")))));
        QCOMPARE(readText(outside.filePath(QStringLiteral("kept"))), QStringLiteral("same"));
        QCOMPARE(readText(outside.filePath(QStringLiteral("render.rc"))), QStringLiteral("2"));
        QVERIFY(readText(outside.filePath(QStringLiteral("render.err")))
                    .contains(QStringLiteral("No space left on device")));
        QCOMPARE(readText(outside.filePath(QStringLiteral("map.rc"))), QStringLiteral("2"));
        QVERIFY(readText(outside.filePath(QStringLiteral("map.err")))
                    .contains(QStringLiteral("No space left on device")));
        QVERIFY(!readText(outside.filePath(QStringLiteral("map.out")))
                     .contains(QStringLiteral("wrote")));
        // Nothing half-written: no PNG, no CSV, no temporary file.
        const QString list = readText(outside.filePath(QStringLiteral("list")));
        QVERIFY2(!list.contains(QStringLiteral(".png")) && !list.contains(QStringLiteral(".csv")) &&
                     !list.contains(QStringLiteral(".tmp")),
                 qPrintable(list));
    }

    void aReadOnlyFolderFailsBeforeTheWork() {
        if (!unshareWorks()) QSKIP("no private mount namespace here (unshare); skipped");
        QTemporaryDir outside;
        const QString script = QStringLiteral(
            "\"$PF\" bench --quick --output-dir \"$D\" >\"$OUT/bench.out\" 2>\"$OUT/bench.err\"; "
            "echo $? >\"$OUT/bench.rc\"; "
            "\"$PF\" stability --quick --output-dir \"$D\" >/dev/null 2>\"$OUT/map.err\"; "
            "echo $? >\"$OUT/map.rc\"; exit 0");
        QVERIFY(runInPrivateMount(outside.path(), QStringLiteral("ro,size=64k"), script));
        for (const char* name : {"bench", "map"}) {
            const QString err = readText(outside.filePath(QLatin1String(name) + ".err"));
            QCOMPARE(readText(outside.filePath(QLatin1String(name) + ".rc")), QStringLiteral("1"));
            QVERIFY2(err.contains(QStringLiteral("Read-only file system")), qPrintable(err));
        }
        // Refused before any measuring: bench prints its reference line once it starts.
        QVERIFY(!readText(outside.filePath(QStringLiteral("bench.err")))
                     .contains(QStringLiteral("reference")));
    }

    void theCheckedWriterReportsTheReasonAndLeavesNoTemporaryFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.csv"));
        QString error;
        QVERIFY(pf::writeOutputFile(path, "one", &error));
        QVERIFY(QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner));
        QVERIFY(pf::writeOutputFile(path, "two", &error));
        QCOMPARE(QFileInfo(path).permissions() & 0x7777,
                 QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadUser |
                     QFileDevice::WriteUser); // an existing file keeps its mode
        QVERIFY(!pf::writeOutputFile(dir.filePath(QStringLiteral("none/a.csv")), "x", &error));
        QVERIFY(error.contains(QStringLiteral("does not exist")));
        QVERIFY(!pf::writeOutputFile(path, "x", &error, {path}));
        QVERIFY(!pf::writeOutputFile(QString(), "x", &error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("two"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"a.csv"});
    }

    // --- 5. The loader's memory ---------------------------------------------------

    void theLoaderSkipsUnknownKeysWithoutBuildingThem() {
        QTemporaryDir dir;
        const QString base = dir.filePath(QStringLiteral("base.paper"));
        writeBytes(base, pf::encodeWorld(*pf::makeScene("press")));
        const QString junk = dir.filePath(QStringLiteral("junk.paper"));
        const qint64 count = 16 * 1024 * 1024; // 32 MiB of [0] arrays
        writeBytes(junk, sheetWithJunk(count));
        const qint64 size = QFileInfo(junk).size();
        // In process: accepted, and the sheet is the one saved.
        QFile f(junk);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const pf::WorldLoad load = pf::decodeWorld(f.readAll());
        QVERIFY2(load.world, qPrintable(load.error));
        QCOMPARE(load.world->sheet.verts.size(), pf::makeScene("press")->sheet.verts.size());
        // In a child process: peak memory within the file's size of a plain load. Building
        // every array (QCborValue::fromCbor) took about 75 bytes of memory per file byte.
        const qint64 plain = peakMemoryOf({"simulate", "--load", base, "--steps", "1"});
        const qint64 junky = peakMemoryOf({"simulate", "--load", junk, "--steps", "1"});
        QVERIFY(plain > 0 && junky > 0);
        qInfo("peak RSS: plain sheet %lld MiB, with %lld MiB of junk %lld MiB", plain >> 20,
              size >> 20, junky >> 20);
        QVERIFY2(junky <= plain + 2 * size, qPrintable(QString::number(junky >> 20)));
    }

    void aKnownKeyCannotHoldUnboundedValues() {
        QByteArray bytes = sheetWithJunk(4);
        // Rename "junk" to "pins": a known key, now holding 25 M values.
        QByteArray big = pf::encodeWorld(*pf::makeScene("press"));
        big[0] = char(static_cast<unsigned char>(big[0]) + 1);
        big += QByteArray("\x64pins\x9a\x01\x80\x00\x00", 10) +
               QByteArray("\x81\x00", 2).repeated(0x01800000);
        const pf::WorldLoad load = pf::decodeWorld(big);
        QVERIFY(!load.world);
        QVERIFY2(load.error.contains(QStringLiteral("values")), qPrintable(load.error));
        QVERIFY(pf::decodeWorld(bytes).world); // a few junk values are harmless
    }

    void deepNestingIsRefusedWithoutRecursingForEver() {
        // Found by fuzz_sheet_loader: 100,000 nested tags under a known key overflowed
        // the stack. Nested arrays under a known and under an unknown key likewise.
        const QByteArray tags =
            QByteArray("\xa1\x65sheet", 7) + QByteArray(100000, '\xc6') + QByteArray(1, '\x00');
        const QByteArray arrays =
            QByteArray("\xa1\x65sheet", 7) + QByteArray(100000, '\x81') + QByteArray(1, '\x00');
        const QByteArray unknown = QByteArray("\xa1\x65"
                                              "extra",
                                              7) +
                                   QByteArray(100000, '\x81') + QByteArray(1, '\x00');
        for (const QByteArray& bytes : {tags, arrays, unknown}) {
            const pf::WorldLoad load = pf::decodeWorld(bytes);
            QVERIFY(!load.world);
            QVERIFY(!load.error.isEmpty());
        }
        QVERIFY(pf::decodeWorld(tags).error.contains(QStringLiteral("nested")));
    }

    void inputsTheFuzzersFoundAreRefused() {
        // tests/fuzz/regressions: each once crashed a fuzz target.
        const QDir dir(QStringLiteral(PAPERFOLD_FUZZ_REGRESSIONS));
        QFile sheet(dir.filePath(QStringLiteral("sheet_nested_tags.bin")));
        QVERIFY(sheet.open(QIODevice::ReadOnly));
        const pf::WorldLoad load = pf::decodeWorld(sheet.readAll());
        QVERIFY(!load.world && !load.error.isEmpty());
        // A GIF whose header declares 11,308 pixels a side: a reference must be a PNG.
        QFile gif(dir.filePath(QStringLiteral("reference_image_gif_header.bin")));
        QVERIFY(gif.open(QIODevice::ReadOnly));
        QString error;
        QVERIFY(pf::decodeReferenceImage(gif.readAll(), &error).isNull());
        QVERIFY(!error.isEmpty());
        // A crumple-cycles recording whose sheet has two pinned rim vertices on one point:
        // a hinge between them had rest length zero, and the replayed sheet was invalid.
        // A press recording whose sheet holds two material points 8e-59 m apart: a break
        // halved a triangle that thin into one of zero area. A recording whose sheet holds a
        // spring of rest length 1.9e185: Eq. 11 squared it and put the new vertex at
        // infinity. A recording whose 20-vertex sheet has edges up to 58 m long: its breaks
        // made a fan of 1,867 springs round one vertex within 20 steps, and the projection's
        // dense block there took 27 s to replay in Release, 158 s under the sanitizers
        // (kMaxProjectedDegree).
        for (const char* name : {"recording_coincident_pins.bin", "recording_hairline_triangle.bin",
                                 "recording_huge_rest_length.bin", "recording_fan_of_breaks.bin"}) {
            QFile file(dir.filePath(QString::fromLatin1(name)));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const pf::RecordingLoad recording = pf::decodeRecording(file.readAll());
            QVERIFY2(recording.log, qPrintable(recording.error));
            pf::EditSession session(*recording.log);
            pf::replay(*recording.log, session);
            QCOMPARE(QString::fromStdString(pf::validateSheet(session.world().sheet)), QString());
        }
    }

    // A damaged PNG, as a texture or a reference, is said in one line of ours with
    // libpng's words in it: Qt's reader let libpng print "libpng error: IDAT: invalid code
    // lengths set" on the console first. A sound one decodes to its pixels exactly.
    void aDamagedPngIsSaidInOurOwnLine() {
        QImage picture(24, 16, QImage::Format_RGBA8888);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 24; ++x)
                picture.setPixelColor(x, y, QColor(10 * x, 15 * y, 255 - 10 * x, 255 - 8 * y));
        for (const QImage& sound : {picture, picture.convertToFormat(QImage::Format_Grayscale8),
                                    picture.convertToFormat(QImage::Format_Indexed8)}) {
            QByteArray bytes;
            QBuffer buffer(&bytes);
            buffer.open(QIODevice::WriteOnly);
            QVERIFY(sound.save(&buffer, "PNG"));
            QString error;
            const QImage decoded = pf::decodePng(bytes, 64, &error);
            QVERIFY2(!decoded.isNull(), qPrintable(error));
            QCOMPARE(decoded, sound.convertToFormat(QImage::Format_RGBA8888));
            // Larger than asked: refused before its pixels.
            QVERIFY(pf::decodePng(bytes, 20, &error).isNull());
            QCOMPARE(error, QStringLiteral("a 24x16 image is larger than 20 pixels a side"));
        }
        QTemporaryDir dir;
        const QString good = dir.filePath(QStringLiteral("good.png"));
        QVERIFY(picture.save(good, "PNG"));
        QFile file(good);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QByteArray flipped = bytes;
        flipped[bytes.indexOf("IDAT") + 10] = char(flipped[bytes.indexOf("IDAT") + 10] ^ 0xff);
        const QByteArray truncated = bytes.left(bytes.size() / 2);
        for (const auto& [name, damaged] :
             {std::pair{"flipped.png", flipped}, std::pair{"truncated.png", truncated}}) {
            const QString path = dir.filePath(QLatin1String(name));
            QFile out(path);
            QVERIFY(out.open(QIODevice::WriteOnly) && out.write(damaged) == damaged.size());
            out.close();
            QString error;
            QVERIFY(pf::decodePng(damaged, 64, &error).isNull());
            QVERIFY2(error.startsWith(QStringLiteral("a damaged PNG (")) && error.size() > 17,
                     qPrintable(error));
            for (const char* option : {"--texture", "--reference"}) {
                const Result r = runPaperfold({"render", "--resolution", "5", "--size", "32x32",
                                               QLatin1String(option), path, "--output",
                                               dir.filePath(QStringLiteral("r.png"))});
                QCOMPARE(r.exitCode, 1);
                const QString& err = r.err;
                QVERIFY2(err.startsWith(QStringLiteral("paperfold: ")) &&
                             err.contains(QLatin1String(name)) &&
                             err.contains(QStringLiteral("a damaged PNG (")) &&
                             !err.contains(QStringLiteral("libpng error")),
                         qPrintable(err));
            }
        }
        // The sound file is read as a texture.
        const Result r =
            runPaperfold({"render", "--resolution", "5", "--size", "32x32", "--texture", good,
                          "--output", dir.filePath(QStringLiteral("r.png"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }

    void devicesAndPipesAreNotRead() {
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("pipe.paper"));
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        for (const QString& path : {QStringLiteral("/dev/zero"), fifo, dir.path()}) {
            const Result r = runPaperfold({"simulate", "--load", path, "--steps", "1"}, 30000);
            QCOMPARE(r.exitCode, 1); // not a hang (-1), not a crash (-2)
            QVERIFY2(r.err.contains(QStringLiteral("not a regular file")), qPrintable(r.err));
        }
        // A texture too: a FIFO kept Qt's image reader waiting for a writer forever, and a
        // folder read "File not found".
        for (const QString& path : {fifo, dir.path()}) {
            const Result r =
                runPaperfold({"render", "--resolution", "5", "--size", "16x16", "--texture", path,
                              "--output", dir.filePath(QStringLiteral("t.png"))},
                             30000);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(QStringLiteral("--texture")) &&
                         r.err.contains(QStringLiteral("not a regular file")),
                     qPrintable(r.err));
        }
        // Refused before reading: no more memory than a run that loads nothing (reading
        // /dev/zero until the size limit took 590 MB).
        const qint64 zero = peakMemoryOf({"simulate", "--load", "/dev/zero", "--steps", "1"});
        const qint64 none = peakMemoryOf({"simulate", "--steps", "0"});
        QVERIFY2(zero > 0 && none > 0 && zero < none + (32LL << 20),
                 qPrintable(QStringLiteral("%1 MiB vs %2 MiB").arg(zero >> 20).arg(none >> 20)));
    }

    // --- 7. Smaller ones -------------------------------------------------------------

    void nonFiniteAndHugeCameraValuesAreRefused_data() {
        QTest::addColumn<QString>("camera");
        for (const char* c : {"0,nan,1", "nan,0,1", "0,0,nan", "1e308,0,1", "0,0,inf", "0,-inf,1",
                              "0,0,0", "0,95,1"})
            QTest::newRow(c) << QString::fromLatin1(c);
    }
    void nonFiniteAndHugeCameraValuesAreRefused() {
        QFETCH(QString, camera);
        QTemporaryDir dir;
        const Result r = runPaperfold({"render", "--size", "32x32", "--camera", camera, "--output",
                                       dir.filePath(QStringLiteral("c.png"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(QStringLiteral("--camera")));
        QVERIFY(QDir(dir.path()).isEmpty());
    }

    void farAwaySheetsAreRefusedNotRenderedBlank() {
        QTemporaryDir dir;
        pf::World w = *pf::makeScene("press");
        for (pf::Vec3& x : w.sheet.verts.x) x += pf::Vec3(1e300, 0, 0);
        pf::WorldLoad load = pf::decodeWorld(pf::encodeWorld(w));
        QVERIFY(!load.world);
        QVERIFY2(load.error.contains(QStringLiteral("10 km")), qPrintable(load.error));
        // Within the file's bounds but too far to frame in single precision.
        w = *pf::makeScene("press");
        for (pf::Vec3& x : w.sheet.verts.x) x += pf::Vec3(5000, 0, 0);
        const QString far = dir.filePath(QStringLiteral("far.paper"));
        writeBytes(far, pf::encodeWorld(w));
        const Result r = runPaperfold({"render", "--load", far, "--size", "32x32", "--output",
                                       dir.filePath(QStringLiteral("far.png"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("too far")), qPrintable(r.err));
    }

    void theEditorWithoutADisplaySaysSo() {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(QLatin1String(name));
        const Result none = runPaperfold({}, 30000, env);
        QCOMPARE(none.exitCode, 2); // a message, not Qt's abort (-2)
        QVERIFY2(none.err.contains(QStringLiteral("display")) &&
                     none.err.contains(QStringLiteral("headless")),
                 qPrintable(none.err));
        // A display that is set but has no server behind it.
        env.insert(QStringLiteral("DISPLAY"), QStringLiteral(":4321"));
        const Result unreachable = runPaperfold({}, 30000, env);
        QCOMPARE(unreachable.exitCode, 2);
        QVERIFY(unreachable.err.contains(QStringLiteral(":4321")));
    }
};

QTEST_GUILESS_MAIN(TestHostileInput)
#include "test_hostile_input.moc"
