// Long-session check of recorded sessions (not a ctest: it runs for minutes). Drives a
// real MainWindow for SESSION_SECONDS (default 120) of wall time: push strokes while the
// simulation plays, φ slider edits, undo and redo, pauses with single steps. Then it
// saves the recording through File ▸ Save Recording, replays it headless, and compares
// the replay's state hash with the editor's.
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/tests/editor_replay_session
// Exit status 1 if the replay does not end exactly where the editor is.
#include "MainWindow.h"
#include "ParameterPanel.h"
#include "RandomStroke.h"
#include "RecordingFile.h"
#include "SheetStats.h"
#include "SimulationThread.h"
#include "Viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <cstdio>
#include <cstdlib>

using namespace pf;

int main(int argc, char** argv) {
    Viewport::prepareProcess(); // as the editor does
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("PaperFoldReplayBench"));
    const char* env = std::getenv("SESSION_SECONDS");
    const int seconds = env && *env ? std::atoi(env) : 120;
    QRandomGenerator rng(2026);

    MainWindow window;
    window.resize(1000, 700);
    QString lastError;
    window.showError = [&](const QString& m) {
        lastError = m;
        std::fprintf(stderr, "error: %s\n", qPrintable(m));
    };
    window.askToSave = [] { return QMessageBox::Discard; };
    QTemporaryDir dir;
    const QString recording = dir.filePath(QStringLiteral("session.paperrec"));
    window.chooseFile = [&](MainWindow::FileDialog) { return recording; };
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 2;
    QElapsedTimer t;
    t.start();
    while (!window.viewport()->snapshot() && t.elapsed() < 10000) QTest::qWait(10);

    int strokes = 0, undos = 0, redos = 0, edits = 0, pauses = 0;
    t.restart();
    while (t.elapsed() < seconds * 1000) {
        const int what = rng.bounded(10);
        if (what < 5) {
            bench::randomStroke(window.viewport(), rng, 30);
            ++strokes;
        } else if (what < 7 && window.undoStack()->canUndo()) {
            window.undoStack()->undo();
            ++undos;
        } else if (what < 8 && window.undoStack()->canRedo()) {
            window.undoStack()->redo();
            ++redos;
        } else if (what < 9) {
            window.panel()->phiSlider()->setValue(rng.bounded(0, 101));
            ++edits;
        } else {
            window.action("play")->setChecked(false);
            for (int k = 0; k < 5; ++k) window.action("step")->trigger();
            QTest::qWait(100);
            window.action("play")->setChecked(true);
            ++pauses;
        }
        QTest::qWait(50);
    }
    window.action("play")->setChecked(false);
    window.simulation()->sync();
    window.action("saveRecording")->trigger();
    if (!lastError.isEmpty()) return 1;

    const auto editor = std::make_shared<const World>(window.simulation()->copyWorld());

    const RecordingLoad load = loadRecording(recording);
    if (!load.log) {
        std::fprintf(stderr, "%s\n", qPrintable(load.error));
        return 1;
    }
    QElapsedTimer replayTime;
    replayTime.start();
    EditSession replayed(*load.log);
    const std::string failure = replay(*load.log, replayed);
    const bool same = failure.empty() && replayed.world().stepCount == editor->stepCount &&
                      stateHash(replayed.world().sheet) == stateHash(editor->sheet);
    std::printf("%d s: %d strokes, %d undos, %d redos, %d φ edits, %d pauses; %zu commands over "
                "%lld steps, %lld vertices, %.1f MB recording\n",
                seconds, strokes, undos, redos, edits, pauses, load.log->commands.size(),
                static_cast<long long>(editor->stepCount),
                static_cast<long long>(editor->sheet.verts.size()),
                QFileInfo(recording).size() / 1e6);
    std::printf("editor %016llx, replay %016llx (%.1f s)%s%s\n",
                static_cast<unsigned long long>(stateHash(editor->sheet)),
                static_cast<unsigned long long>(stateHash(replayed.world().sheet)),
                replayTime.nsecsElapsed() * 1e-9, same ? ": the same" : ": DIFFERENT ",
                failure.c_str());
    window.close();
    return same ? 0 : 1;
}
