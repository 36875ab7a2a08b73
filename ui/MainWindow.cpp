#include "MainWindow.h"

#include "ActionTexts.h"
#include "AllocatorTuning.h"
#include "ChartBrowser.h"
#include "DockScrollArea.h"
#include "EditorDialogs.h"
#include "EditorParameters.h"
#include "HelpText.h"
#include "Language.h"
#include "OffscreenRenderer.h"
#include "PaperLookMenu.h"
#include "ParameterPanel.h"
#include "RecentFiles.h"
#include "RecordingFile.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SheetStats.h"
#include "SimulationThread.h"
#include "SnapshotExport.h"
#include "SolverPanel.h"
#include "StatusReadout.h"
#include "StrokeHistory.h"
#include "UndoCommands.h"
#include "Viewport.h"
#include "ViewportInput.h"
#include "WorkerPool.h"
#include "WrappedToolTips.h"
#include "XpbdIntegrator.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QEventLoop>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <QMenuBar>
#include <QProgressDialog>
#include <QSettings>
#include <QShortcut>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>
#include <algorithm>
#include <atomic>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pf {

namespace {

// Swallows what would close a dialog that must stay until its work is done.
class StaysOpen : public QObject {
  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Close) {
            event->ignore();
            return true;
        }
        if (event->type() == QEvent::KeyPress &&
            static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape)
            return true;
        return QObject::eventFilter(watched, event);
    }
};

const char* const kOverlayActions[] = {"overlay.springs", "overlay.probability", "overlay.strain",
                                       "overlay.breaks", "overlay.wireframe"};
const Overlay kOverlayBits[] = {OverlaySpringKinds, OverlayBreakProbability, OverlayStrain,
                                OverlayRecentBreaks, OverlayWireframe};

} // namespace

int MainWindow::defaultThreads() {
    return std::max(1, WorkerPool::machineThreads() - 1);
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("MainWindow"));
    keepFreedHeapForTheNextFrame();
    qApp->installEventFilter(new WrappedToolTips(this));
    const World first = sceneWorld(scene_);
    sim_ = std::make_unique<SimulationThread>(first);

    viewport_ = new Viewport(this);
    viewport_->setMouseTracking(true);
    viewport_->setFocusPolicy(Qt::StrongFocus);
    input_ = new ViewportInput(viewport_, sim_.get(), this);
    setCentralWidget(viewport_);
    undo_ = new QUndoStack(this);
    parameters_ = new EditorParameters(undo_, this);
    charts_ = new ChartBrowser(this);

    chooseFile = [this](FileDialog kind) { return EditorDialogs::chooseFile(this, kind, file_); };
    showError = [this](const QString& message) { EditorDialogs::showError(this, message); };
    askToSave = [this] { return EditorDialogs::askToSave(this); };
    chooseImageSize = [this] {
        const QSize last = QSettings().value(QLatin1String(kImageSizeSetting)).toSize();
        return EditorDialogs::chooseImageSize(
            this,
            OffscreenRenderer::sizeAllowed(last.width(), last.height()) ? last : QSize(1920, 1080));
    };
    chooseColor = [this](const QColor& current) {
        return EditorDialogs::chooseColor(this, current);
    };
    chooseMeshSubdivision = [this](int current) {
        return EditorDialogs::chooseMeshSubdivision(this, current);
    };

    createActions();
    createMenus();
    createDocks();
    readout_ = new StatusReadout(statusBar());
    connectParameters();
    parameters_->set(first.params);
    panel_->setToolRadius(input_->toolRadius());

    connect(sim_.get(), &SimulationThread::snapshotReady, this, &MainWindow::onSnapshot);
    readoutLater_ = new QTimer(this);
    readoutLater_->setSingleShot(true);
    connect(readoutLater_, &QTimer::timeout, this, [this] { showReadouts(sim_->status()); });
    // After New/Open the crumpled sheet, its snapshots and the renderer's buffers for it
    // are freed, but glibc keeps the freed pages in its arenas (the simulation thread's
    // and the GUI's): give them back once the new sheet's first frame is drawn.
    connect(sim_.get(), &SimulationThread::worldReplaced, this, [this] {
        releasePending_ = true;
        // The new sheet's snapshot is the latest now (it was published first). Fitting
        // the first snapshot to arrive after New or Open could fit the old sheet's, still
        // queued, and leave the new one out of view.
        if (auto snap = sim_->latestSnapshot()) viewport_->setSnapshot(snap);
        firstSnapshot_ = false;
        input_->frameNewSheet();
    });
    connect(viewport_, &Viewport::frameDrawn, readout_, &StatusReadout::frameDrawn);
    connect(viewport_, &Viewport::frameDrawn, this, [this] {
        if (!releasePending_) return;
        releasePending_ = false;
#if defined(__GLIBC__)
        malloc_trim(0);
#endif
    });
    connect(sim_.get(), &SimulationThread::strokeRecorded, this,
            [this](int stroke, int events, int kind) {
                undo_->push(new StrokeCommand(sim_.get(), stroke, events, kind));
                // The view fits the fresh sheet, as after New (its snapshot comes next).
                if (kind == static_cast<int>(EditSession::StrokeKind::Reset)) firstSnapshot_ = true;
                // The fold's "Folding…" would otherwise stand for seconds after it ended.
                if (kind == static_cast<int>(EditSession::StrokeKind::Fold))
                    statusBar()->showMessage(tr("Folded. Edit ▸ Undo unfolds the paper."), 5000);
            });
    // A user pushed a sheet pinned at its four corners, saw nothing happen and nothing
    // in the History, and read nothing of why. (Paused, the press already said so.)
    connect(sim_.get(), &SimulationThread::pushMovedNothing, this, [this] {
        if (playing_)
            statusBar()->showMessage(
                tr("This push moved nothing: the tool touched no paper, or slid over paper it "
                   "cannot move (paper held by pins, say). Push where the paper is "
                   "free, or unpin it."),
                8000);
    });
    auto* history = new StrokeHistory(sim_.get(), undo_, this);
    connect(history, &StrokeHistory::renamed, undoView_->viewport(), qOverload<>(&QWidget::update));
    connect(history, &StrokeHistory::said, this,
            [this](const QString& message) { statusBar()->showMessage(message, 8000); });
    // Said once the paper has had its second (EditSession::takeFoldTurnedBack): a third
    // fold along the diagonal of a sheet folded twice sprang back 99° while the status
    // bar said "the crease keeps it".
    connect(sim_.get(), &SimulationThread::foldSprangBack, this, [this](double degrees) {
        statusBar()->showMessage(
            tr("The fold opened %1° again after it was let go: its crease did not hold the "
               "flap. Edit ▸ Undo unfolds the paper.")
                .arg(degrees, 0, 'f', 0),
            10000);
    });
    // A fold to 90° (or 120°, 150°) fell flat onto the rest of the sheet while the status
    // bar said "Folded.".
    connect(sim_.get(), &SimulationThread::foldFellShut, this, [this](double asked) {
        statusBar()->showMessage(
            tr("The fold fell shut after it was let go: its crease cannot hold the flap up at "
               "%1°. Edit ▸ Undo unfolds the paper.")
                .arg(asked, 0, 'f', 0),
            10000);
    });
    // Card folded to 60° stood at 124°, its base lifted: closed, not shut.
    connect(sim_.get(), &SimulationThread::foldClosedFurther, this, [this](double degrees) {
        statusBar()->showMessage(
            tr("The fold closed %1° further than asked after it was let go: its crease cannot "
               "hold the flap at that angle. Edit ▸ Undo unfolds the paper.")
                .arg(degrees, 0, 'f', 0),
            10000);
    });
    // Said as soon as the flap opens past kSprangBack: a 90° fold lay flat again while
    // "Folded." stood for most of a second. The reading a second after the let-go says
    // how far it went.
    connect(sim_.get(), &SimulationThread::foldOpening, this, [this] {
        statusBar()->showMessage(
            tr("The fold is opening again: its crease does not hold the flap. Edit ▸ Undo "
               "unfolds the paper."),
            10000);
    });
    // A third fold across a sheet folded twice carried its upper layers over and left the
    // lower ones lying flat, while the status bar said "Folded."; in an editor session
    // such layers also went round while carried and fell back open at the let-go.
    connect(sim_.get(), &SimulationThread::foldLeftPaperBehind, this, [this](double share) {
        statusBar()->showMessage(
            tr("Only part of the fold held: %1 % of the paper on the flap's side lies "
               "unfolded. The fold holds the paper that lies flat along the line, not layers "
               "above or below it. Edit ▸ Undo unfolds the paper.")
                .arg(100.0 * share, 0, 'f', 0),
            10000);
    });
    connect(sim_.get(), &SimulationThread::settled, this, [this](int stroke) {
        undo_->push(new StrokeCommand(sim_.get(), stroke, 0,
                                      static_cast<int>(EditSession::StrokeKind::Settle)));
        statusBar()->showMessage(tr("Settled: the sheet stays as it is until the next edit."),
                                 5000);
    });
    connect(sim_.get(), &SimulationThread::settleRefused, this, [this](bool alreadySettled) {
        statusBar()->showMessage(
            alreadySettled ? tr("Already settled: the sheet stays as it is until the next edit.")
                           : tr("Not settled: an edit is under way. Settle once it is over."),
            5000);
    });
    connect(sim_.get(), &SimulationThread::diverged, this, [this](qint64 step) {
        // The worker has paused; Play shows it, so that one Space plays again.
        action("play")->setChecked(false);
        showError(
            tr("The simulation blew up at step %1 and was paused; the last good state is kept. "
               "Try more steps per second or the jacobi integrator.")
                .arg(step));
    });
    connect(undo_, &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(parameters_, &EditorParameters::changed, this, &MainWindow::updateTitle);
    connect(solver_, &SolverPanel::openChartRequested, charts_, &ChartBrowser::showLatest);
    connect(charts_, &ChartBrowser::failed, this, [this](const QString& m) { showError(m); });
    connect(panel_, &ParameterPanel::toolRadiusChanged, input_, &ViewportInput::setToolRadius);
    connect(input_, &ViewportInput::toolRadiusChanged, panel_, &ParameterPanel::setToolRadius);
    connect(panel_, &ParameterPanel::pushDepthChanged, input_, &ViewportInput::setPushDepth);
    // How many cores step the sheet: the user's choice, kept between sessions; 0 (and
    // anything unreadable) means the default, worked out on whatever machine the next
    // session runs.
    const int all = WorkerPool::machineThreads();
    const int saved = QSettings().value(QLatin1String(kThreadsSetting), 0).toInt();
    const int threads = saved > 0 ? std::min(saved, all) : defaultThreads();
    sim_->setThreads(threads);
    solver_->showThreads(threads);
    connect(solver_, &SolverPanel::threadsChanged, this, [this](int n) {
        sim_->setThreads(n);
        QSettings().setValue(QLatin1String(kThreadsSetting), n == defaultThreads() ? 0 : n);
    });
    hintShown_ = !QSettings().value(QLatin1String(kHintSetting)).toBool();
    connect(input_, &ViewportInput::acted, this, [this] {
        if (!hintShown_) return;
        hintShown_ = false;
        viewport_->setHint(QString());
        QSettings().setValue(QLatin1String(kHintSetting), true);
    });
    connect(input_, &ViewportInput::strokeBegan, this, [this] {
        // The carried flap is the one edit under way: a push, grab or pin waits for it
        // (EditSession::busy), and said nothing. A second fold line says so when refused.
        if (foldUnderWay_ && input_->tool() != ViewportInput::Tool::Fold) {
            statusBar()->showMessage(tr("Not now: a fold is under way."), 5000);
            return;
        }
        if (playing_) return;
        switch (input_->tool()) {
        case ViewportInput::Tool::Push:
            statusBar()->showMessage(tr("Paused: the push moves the paper only while the "
                                        "simulation runs (Space plays, Ctrl+. steps)."),
                                     5000);
            break;
        case ViewportInput::Tool::Grab:
            statusBar()->showMessage(tr("Paused: the grab moves the paper only while the "
                                        "simulation runs (Space plays, Ctrl+. steps)."),
                                     5000);
            break;
        case ViewportInput::Tool::Pin:
            break; // a pin holds at once
        case ViewportInput::Tool::Fold:
            statusBar()->showMessage(
                tr("Paused: the fold is carried round once the simulation runs (Space plays, "
                   "Ctrl+. steps)."),
                5000);
            break;
        }
    });
    connect(input_, &ViewportInput::foldDrawn, this, [this](const Vec3& from, const Vec3& to) {
        // Valley and mountain as the user sees the paper: toward the eye, or away.
        const Vec3 viewer = (viewport_->camera().eye() - from).normalized();
        sim_->fold({from, to, panel_->foldAngle(), panel_->foldMountain(), viewer});
    });
    connect(sim_.get(), &SimulationThread::foldAnswered, this, [this](int refusal) {
        // Paused, "Folding: …" replaced the stroke's "Paused: …" at once, and the fold
        // stood held and still, its Undo greyed, with nothing saying that Play moves it.
        if (refusal == int(FoldRefusal::None) && !playing_)
            statusBar()->showMessage(tr("Paused: the fold waits. Space plays and carries the "
                                        "paper round the line; Ctrl+. steps."));
        else if (refusal == int(FoldRefusal::None))
            // Until the fold ends (setEditUnderWay): carried behind real time, a tissue
            // fold took 15 s, and after 8 the readouts stood where "Folding…" had been.
            statusBar()->showMessage(foldAnswerText(FoldRefusal::None));
        else
            statusBar()->showMessage(foldAnswerText(static_cast<FoldRefusal>(refusal)), 8000);
        if (refusal == int(FoldRefusal::None)) setEditUnderWay(true, settleUnderWay_);
    });
    // The stack enables its own actions whenever it moves (a parameter change, say). A
    // message about what came before is over too (a fold's refusal stood for 8 s after
    // an undo); what a new step says is shown after it is pushed.
    connect(undo_, &QUndoStack::indexChanged, this, [this] {
        statusBar()->clearMessage();
        gateUndo();
    });
    // Pressed while the history waits, the keys say why (gateUndo enables these then).
    for (const char* name : {"undo", "redo"})
        for (const QKeySequence& keys : action(name)->shortcuts()) {
            auto* waits = new QShortcut(keys, this);
            waits->setEnabled(false);
            connect(waits, &QShortcut::activated, this,
                    [this] { statusBar()->showMessage(whyUndoWaits_, 5000); });
            historyWaits_.push_back(waits);
        }
    // The stack's own actions enable themselves after indexChanged (createUndoAction):
    // gated again after them, or a step back of the History while the mouse held the
    // paper gave Ctrl+Z back.
    connect(undo_, &QUndoStack::canUndoChanged, this, &MainWindow::gateUndo);
    connect(undo_, &QUndoStack::canRedoChanged, this, &MainWindow::gateUndo);
    connect(sim_.get(), &SimulationThread::allAnswered, this, &MainWindow::gateUndo);
    connect(input_, &ViewportInput::holdChanged, this, [this](bool holding) {
        // Let go, the push or grab becomes a step (strokeRecorded) a frame later: Undo
        // waits for it, or it would undo the step before.
        if (!holding) sim_->awaitAnswer();
        gateUndo();
    });
    // An undo or redo lets go of a held grab (EditSession); the hand follows. (Undo and
    // Redo wait while the mouse holds the paper, so this is only a guard.)
    connect(sim_.get(), &SimulationThread::strokeUndone, input_, &ViewportInput::letGo);
    connect(sim_.get(), &SimulationThread::strokeRedone, input_, &ViewportInput::letGo);

    retranslate();
    // Smaller, the docks' values and boxes were cut off and the legend covered the view,
    // and the docks kept their squeezed heights when the window grew again.
    setMinimumSize(kMinimumWidth, kMinimumHeight);
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    if (settings.value(QStringLiteral("window/geometry")).isNull()) resize(1280, 800);
    updateTitle();
}

MainWindow::~MainWindow() {
    // Children (the undo stack, the panel, the viewport) are deleted by ~QObject, after
    // this object's own part and the simulation thread are gone; stop them calling back.
    // The input filter talks to the simulation thread, which goes before the widgets do.
    viewport_->removeEventFilter(input_);
    undo_->disconnect(this);
    parameters_->disconnect();
    panel_->disconnect(this);
    solver_->disconnect(this);
}

// The parameters have one owner, EditorParameters: the panels turn edits into changes
// there and show what it holds; the simulation hears what it uses; σ, a look, goes to
// the viewport only.
void MainWindow::connectParameters() {
    auto edit = [this](const QString& what, int drag, const ParamChange& change) {
        parameters_->edit(what, drag, change);
    };
    connect(panel_, &ParameterPanel::edited, this, edit);
    connect(solver_, &SolverPanel::edited, this, edit);
    connect(parameters_, &EditorParameters::changed, panel_, &ParameterPanel::showParams);
    connect(parameters_, &EditorParameters::changed, solver_, &SolverPanel::showParams);
    connect(parameters_, &EditorParameters::simulationChanged, this,
            [this](const SimParams& p) { sim_->setParams(p); });
    connect(parameters_, &EditorParameters::sigmaChanged, viewport_, [this](double sigma) {
        RenderOptions o = viewport_->renderOptions();
        o.sigma = sigma;
        viewport_->setRenderOptions(o);
    });
}

const SimParams& MainWindow::params() const {
    return parameters_->params();
}

World MainWindow::sceneWorld(const QString& scene) const {
    SceneOptions options;
    if (panel_) {
        options.resolution = panel_->resolution();
        options.width = panel_->sheetWidth();
        options.length = panel_->sheetLength();
    }
    return makeEditorScene(scene.toStdString(), options,
                           input_ ? input_->toolRadius() : ViewportInput::kDefaultToolRadius);
}

QAction* MainWindow::action(const char* name) const {
    return findChild<QAction*>(QLatin1String(name));
}

void MainWindow::createActions() {
    auto make = [this](const char* name, const QKeySequence& key = {},
                       QStyle::StandardPixmap icon = QStyle::SP_CustomBase) {
        auto* a = new QAction(this);
        a->setObjectName(QLatin1String(name));
        if (!key.isEmpty()) a->setShortcut(key);
        if (icon != QStyle::SP_CustomBase) a->setIcon(style()->standardIcon(icon));
        return a;
    };
    connect(make("open", QKeySequence::Open, QStyle::SP_DialogOpenButton), &QAction::triggered,
            this, [this] {
                if (!maybeSave()) return;
                const QString path = chooseFile(FileDialog::Open);
                if (!path.isEmpty()) openFile(path);
            });
    connect(make("save", QKeySequence::Save, QStyle::SP_DialogSaveButton), &QAction::triggered,
            this, [this] {
                const QString path = file_.isEmpty() ? chooseFileToWrite(FileDialog::Save) : file_;
                if (!path.isEmpty()) saveFile(path);
            });
    QAction* saveAs = make("saveAs", QKeySequence::SaveAs);
    // Outside KDE and GNOME (a bare X server) Qt knows no Save As key.
    if (saveAs->shortcut().isEmpty()) saveAs->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    connect(saveAs, &QAction::triggered, this, [this] {
        const QString path = chooseFileToWrite(FileDialog::Save);
        if (!path.isEmpty()) saveFile(path);
    });
    connect(make("saveRecording"), &QAction::triggered, this, [this] {
        const QString path = chooseFileToWrite(FileDialog::SaveRecording);
        if (!path.isEmpty()) saveRecording(path);
    });
    connect(make("exportImage", QKeySequence(tr("Ctrl+E"))), &QAction::triggered, this,
            &MainWindow::exportImage);
    connect(make("exportMesh", QKeySequence(tr("Ctrl+Shift+E"))), &QAction::triggered, this,
            &MainWindow::exportMesh);
    connect(make("quit", QKeySequence::Quit), &QAction::triggered, this, &QWidget::close);
    for (const auto& scene : sceneNames()) {
        const QString name = QString::fromStdString(scene);
        QAction* a = make(qPrintable(QStringLiteral("new.") + name));
        connect(a, &QAction::triggered, this, [this, name] {
            if (maybeSave()) newScene(name);
        });
    }
    action("new.press")->setShortcut(QKeySequence::New);

    QAction* undo = undo_->createUndoAction(this);
    undo->setObjectName(QStringLiteral("undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(style()->standardIcon(QStyle::SP_ArrowBack));
    QAction* redo = undo_->createRedoAction(this);
    redo->setObjectName(QStringLiteral("redo"));
    redo->setShortcuts({QKeySequence::Redo, QKeySequence(tr("Ctrl+Y"))});
    redo->setIcon(style()->standardIcon(QStyle::SP_ArrowForward));

    QAction* play = make("play", QKeySequence(Qt::Key_Space), QStyle::SP_MediaPause);
    play->setCheckable(true);
    play->setChecked(true);
    connect(play, &QAction::toggled, this, [this](bool on) {
        playing_ = on;
        if (on) statusBar()->clearMessage(); // "Paused: …" and the like are over
        gateUndo();                          // why it waits may be the pause
        sim_->setPlaying(on);
        action("play")->setIcon(
            style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        ActionTexts::apply(this); // Pause while playing, Play while paused
    });
    connect(make("step", QKeySequence(tr("Ctrl+.")), QStyle::SP_MediaSkipForward),
            &QAction::triggered, this, [this] {
                action("play")->setChecked(false);
                sim_->stepOnce();
            });
    connect(make("settle", QKeySequence(tr("Ctrl+K"))), &QAction::triggered, this, [this] {
        if (refusedWhileThePaperIsHeld()) return;
        if (foldUnderWay_) {
            statusBar()->showMessage(tr("Not now: a fold is under way."), 5000);
            return;
        }
        sim_->settle();
        setEditUnderWay(foldUnderWay_, true); // at once, not a frame later
        statusBar()->showMessage(playing_ ? tr("Settling: the sheet comes to rest…")
                                          : tr("Settling once the simulation plays (Space)."));
    });
    connect(make("reset", QKeySequence(tr("Ctrl+R")), QStyle::SP_BrowserReload),
            &QAction::triggered, this, [this] {
                // An undo step, so nothing to ask: Edit ▸ Undo gives the sheet back.
                if (refusedWhileThePaperIsHeld()) return;
                if (foldUnderWay_) {
                    statusBar()->showMessage(tr("Not now: a fold is under way."), 5000);
                    return;
                }
                input_->letGo();
                sim_->reset(sceneWorldWithParams(scene_));
            });

    auto* tools = new QActionGroup(this);
    const std::pair<const char*, ViewportInput::Tool> kTools[] = {
        {"tool.push", ViewportInput::Tool::Push},
        {"tool.grab", ViewportInput::Tool::Grab},
        {"tool.pin", ViewportInput::Tool::Pin},
        {"tool.fold", ViewportInput::Tool::Fold}};
    const Qt::Key kToolKeys[] = {Qt::Key_P, Qt::Key_G, Qt::Key_I, Qt::Key_L};
    for (int k = 0; k < 4; ++k) {
        QAction* a = make(kTools[k].first, QKeySequence(kToolKeys[k]));
        a->setCheckable(true);
        a->setChecked(k == 0);
        tools->addAction(a);
        const ViewportInput::Tool tool = kTools[k].second;
        connect(a, &QAction::triggered, this, [this, tool] { input_->setTool(tool); });
    }

    for (int k = 0; k < 5; ++k) {
        QAction* a = make(kOverlayActions[k], QKeySequence(QStringLiteral("Alt+%1").arg(k + 1)));
        a->setCheckable(true);
        const Overlay bit = kOverlayBits[k];
        connect(a, &QAction::toggled, this, [this, bit](bool on) {
            RenderOptions o = viewport_->renderOptions();
            o.overlays = on ? (o.overlays | bit) : (o.overlays & ~unsigned(bit));
            viewport_->setRenderOptions(o);
        });
    }
    int key = Qt::Key_1;
    for (const char* view : {"top", "front", "iso"})
        connect(
            make(qPrintable(QStringLiteral("view.") + QLatin1String(view)), QKeySequence(key++)),
            &QAction::triggered, this, [this, view] { input_->setView(view); });
    connect(make("view.fit", QKeySequence(Qt::Key_F)), &QAction::triggered, this,
            [this] { input_->fitCamera(); });
    connect(make("help", QKeySequence::HelpContents), &QAction::triggered, this,
            [this] { HelpText::showMouseAndKeys(this); });
    connect(make("about"), &QAction::triggered, this, [this] { HelpText::showAbout(this); });
    languageGroup_ = createLanguageActions(this);

    paperLook_ = new PaperLookMenu(this);
    paperLook_->chooseColor = [this](const QColor& c) { return chooseColor(c); };
    paperLook_->chooseImage = [this] { return chooseFile(FileDialog::PaperImage); };
    paperLook_->showError = [this](const QString& m) { showError(m); };
    auto showLook = [this](const PaperLook& look) {
        RenderOptions o = viewport_->renderOptions();
        o.look = look;
        viewport_->setRenderOptions(o);
    };
    connect(paperLook_, &PaperLookMenu::lookChanged, this, showLook);
    showLook(paperLook_->look());

    // A look, kept for the next session like the paper's colour (not an undo step).
    QAction* creases = make("view.creases");
    creases->setCheckable(true);
    creases->setChecked(QSettings().value(QLatin1String(kCreasesSetting), true).toBool());
    auto showCreases = [this](bool on) {
        RenderOptions o = viewport_->renderOptions();
        o.creases = on;
        viewport_->setRenderOptions(o);
    };
    connect(creases, &QAction::toggled, this, [showCreases](bool on) {
        QSettings().setValue(QLatin1String(kCreasesSetting), on);
        showCreases(on);
    });
    showCreases(creases->isChecked());
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(QString());
    newMenu_ = fileMenu_->addMenu(QString());
    for (const auto& scene : sceneNames())
        newMenu_->addAction(
            action(qPrintable(QStringLiteral("new.") + QString::fromStdString(scene))));
    fileMenu_->addAction(action("open"));
    recentMenu_ = fileMenu_->addMenu(QString());
    fileMenu_->addAction(action("save"));
    fileMenu_->addAction(action("saveAs"));
    fileMenu_->addAction(action("saveRecording"));
    fileMenu_->addSeparator();
    fileMenu_->addAction(action("exportImage"));
    fileMenu_->addAction(action("exportMesh"));
    fileMenu_->addSeparator();
    fileMenu_->addAction(action("quit"));

    editMenu_ = menuBar()->addMenu(QString());
    editMenu_->addAction(action("undo"));
    editMenu_->addAction(action("redo"));

    toolMenu_ = menuBar()->addMenu(QString());
    for (const char* name : {"tool.push", "tool.grab", "tool.pin", "tool.fold"})
        toolMenu_->addAction(action(name));

    viewMenu_ = menuBar()->addMenu(QString());
    overlayMenu_ = viewMenu_->addMenu(QString());
    for (const char* name : kOverlayActions) overlayMenu_->addAction(action(name));
    viewMenu_->addSeparator();
    for (const char* name : {"view.top", "view.front", "view.iso", "view.fit"})
        viewMenu_->addAction(action(name));
    viewMenu_->addSeparator();
    viewMenu_->addMenu(paperLook_->menu());
    viewMenu_->addAction(action("view.creases"));
    languageMenu_ = viewMenu_->addMenu(QString());
    languageMenu_->addActions(languageGroup_->actions());

    simMenu_ = menuBar()->addMenu(QString());
    for (const char* name : {"play", "step", "settle", "reset"}) simMenu_->addAction(action(name));

    helpMenu_ = menuBar()->addMenu(QString());
    helpMenu_->addAction(action("help"));
    helpMenu_->addAction(action("about"));

    toolBar_ = addToolBar(QString());
    toolBar_->setObjectName(QStringLiteral("mainToolBar"));
    for (const char* name : {"open", "save", "undo", "redo", "play", "step", "reset"})
        toolBar_->addAction(action(name));
    toolBar_->addSeparator();
    for (const char* name : {"tool.push", "tool.grab", "tool.pin", "tool.fold"})
        toolBar_->addAction(action(name));
    toolBar_->addSeparator();
    for (const char* name : kOverlayActions) toolBar_->addAction(action(name));
    recent_ = new RecentFiles(recentMenu_, this);
    connect(recent_, &RecentFiles::openRequested, this, [this](const QString& path) {
        // An entry whose sheet can no longer be opened (moved, deleted, broken) goes:
        // the error has said why, and the menu should not offer it again.
        if (maybeSave() && !openFile(path)) recent_->remove(path);
    });
}

void MainWindow::createDocks() {
    panel_ = new ParameterPanel(this);
    panelDock_ = new QDockWidget(this);
    panelDock_->setObjectName(QStringLiteral("parameterDock"));
    auto* panelArea = new DockScrollArea(panel_);
    panelDock_->setWidget(panelArea);
    addDockWidget(Qt::RightDockWidgetArea, panelDock_);
    undoView_ = new QUndoView(undo_, this);
    historyDock_ = new QDockWidget(this);
    historyDock_->setObjectName(QStringLiteral("historyDock"));
    historyDock_->setWidget(undoView_);
    addDockWidget(Qt::RightDockWidgetArea, historyDock_);
    solver_ = new SolverPanel(this);
    solverDock_ = new QDockWidget(this);
    solverDock_->setObjectName(QStringLiteral("solverDock"));
    auto* solverArea = new DockScrollArea(solver_);
    solverDock_->setWidget(solverArea);
    addDockWidget(Qt::RightDockWidgetArea, solverDock_);
    for (DockScrollArea* area : {panelArea, solverArea})
        connect(area, &DockScrollArea::contentsResized, this, &MainWindow::fitDocks,
                Qt::QueuedConnection);
    // Return in a number box gives the keys back to the view: a user typed 180° into the
    // fold's angle, pressed Return and then 1 for the top view, and the angle became 1°
    // (the box kept the focus, and a digit is text to it, not a shortcut). A list chosen
    // from with the mouse leaves the keys where they were: a user chose tissue, then
    // pressed 3, g and i, and the list, keeping the focus, searched its items for the
    // letters. Tab still reaches it.
    for (QWidget* panel : {static_cast<QWidget*>(panel_), static_cast<QWidget*>(solver_)}) {
        for (auto* box : panel->findChildren<QAbstractSpinBox*>())
            if (auto* edit = box->findChild<QLineEdit*>())
                connect(edit, &QLineEdit::returnPressed, this,
                        [this] { viewport_->setFocus(Qt::OtherFocusReason); });
        for (auto* list : panel->findChildren<QComboBox*>()) list->setFocusPolicy(Qt::TabFocus);
    }
    viewMenu_->addSeparator();
    viewMenu_->addAction(panelDock_->toggleViewAction());
    viewMenu_->addAction(historyDock_->toggleViewAction());
    viewMenu_->addAction(solverDock_->toggleViewAction());
}

// The Parameters and Solver docks get the height of their contents where the window has
// it, the History what is left: Qt shares a short window's height out by the docks' size
// hints, and the two panels scrolled at the default 1280 × 800 with the History half
// empty. Done again when the window is resized or a panel's contents change their size
// hint (a section opened, another language), so a dragged splitter lasts until then.
void MainWindow::fitDocks() {
    if (!panelDock_ || !solverDock_ || !historyDock_) return;
    // (resizeDocks leaves a dock a pixel short of the height asked, and the panel then
    // scrolls by that pixel: asked for two more.)
    constexpr int kSlack = 2;
    // The docks shown one above another in the panels' column (whichever of the two
    // panels is shown decides where that is).
    QDockWidget* first = !panelDock_->isHidden() ? panelDock_ : solverDock_;
    const Qt::DockWidgetArea area = dockWidgetArea(first);
    const auto inColumn = [&](QDockWidget* d) {
        return !d->isHidden() && !d->isFloating() && dockWidgetArea(d) == area;
    };
    QList<QDockWidget*> docks;
    QList<int> heights;
    int column = 0, panels = 0;
    for (QDockWidget* d : {panelDock_, historyDock_, solverDock_})
        if (inColumn(d)) column += d->height();
    for (QDockWidget* d : {panelDock_, solverDock_})
        if (inColumn(d)) {
            docks << d;
            heights << d->sizeHint().height() + kSlack;
            panels += heights.back();
        }
    if (docks.isEmpty()) return;
    // The History is given what is left. Left out, it kept the height it had grown to
    // (with the window, while the panels were small), and Qt shrank the panels' heights
    // to make room for it: after a window squeezed to its smallest and grown again, and
    // Advanced opened, both panels scrolled in a window with room for them.
    if (inColumn(historyDock_)) {
        docks << historyDock_;
        heights << std::max(historyDock_->minimumSizeHint().height(), column - panels);
    }
    resizeDocks(docks, heights, Qt::Vertical);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    fitDocks();
}

void MainWindow::retranslate() {
    ActionTexts::apply(this);
    // The live numbers said again, in the new language and its digits: now, since while
    // paused no snapshot comes to say them.
    if (readoutClock_.isValid()) showReadouts(sim_->status());
    // The History's steps were named in the language of their time. (QUndoStack hands
    // them out const; they are ours, made with new.)
    for (int i = 0; i < undo_->count(); ++i)
        if (auto* step = dynamic_cast<const EditorCommand*>(undo_->command(i)))
            const_cast<EditorCommand*>(step)->retranslate();
    undoView_->viewport()->update();
    fileMenu_->setTitle(tr("&File"));
    newMenu_->setTitle(tr("&New"));
    recentMenu_->setTitle(tr("Open &Recent"));
    editMenu_->setTitle(tr("&Edit"));
    viewMenu_->setTitle(tr("&View"));
    overlayMenu_->setTitle(tr("&Overlays"));
    languageMenu_->setTitle(tr("&Language"));
    simMenu_->setTitle(tr("&Simulation"));
    toolMenu_->setTitle(tr("&Tools"));
    helpMenu_->setTitle(tr("&Help"));
    paperLook_->retranslate();
    toolBar_->setWindowTitle(tr("Main toolbar"));
    panelDock_->setWindowTitle(tr("Parameters"));
    historyDock_->setWindowTitle(tr("History"));
    solverDock_->setWindowTitle(tr("Solver"));
    nameHistoryStart();
    if (hintShown_)
        viewport_->setHint(
            tr("Left drag pushes the paper · L folds, G grabs and I pins (Tools menu) · "
               "right drag orbits · the wheel zooms · F1 lists every key"));
    updateTitle();
}

void MainWindow::nameHistoryStart() {
    // A new sheet by the scene it was made from, as the New menu names it (its text
    // without the shortcut's ampersand).
    const auto* made = findChild<QAction*>(QStringLiteral("new.") + scene_);
    if (!openedFrom_.isEmpty())
        undoView_->setEmptyLabel(QStringLiteral("<%1>").arg(QFileInfo(openedFrom_).fileName()));
    else
        undoView_->setEmptyLabel(made ? tr("<new: %1>").arg(made->iconText()) : tr("<new sheet>"));
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    // Back from a modal dialog, the view may get no Enter until the mouse moves.
    if (event->type() == QEvent::ActivationChange && isActiveWindow() && input_)
        input_->showToolUnderCursor();
    QMainWindow::changeEvent(event);
}

void MainWindow::onSnapshot() {
    auto snap = sim_->latestSnapshot();
    if (!snap) return;
    const bool anew = snap != viewport_->sharedSnapshot(); // not a sheet at rest's again
    viewport_->setSnapshot(snap);
    if (firstSnapshot_) {
        firstSnapshot_ = false;
        input_->fitCamera();
    } else if (anew) {
        input_->toolFollowsTheView(); // the paper under the hovering tool may have moved
    }
    const SimulationStatus st = sim_->status();
    lastHash_ = st.sheetHash;
    // The numbers are read, not watched frame by frame: redrawn at every snapshot (the
    // step's microseconds change each time) they kept the GUI thread at 7 % of a core
    // over a sheet at rest. What a user acts on (the counts, rest, play, a fold) shows at
    // once; the rest four times a second.
    const SimulationStatus& was = readoutShown_;
    const bool changed = st.vertices != was.vertices || st.springs != was.springs ||
                         st.breaks != was.breaks || st.hinges != was.hinges ||
                         st.breaksLastSecond != was.breaksLastSecond ||
                         st.resting() != was.resting() || st.playing != was.playing ||
                         st.folding != was.folding || st.threads != was.threads;
    if (changed || !readoutClock_.isValid() || readoutClock_.elapsed() >= kReadoutMs)
        showReadouts(st);
    else if (!readoutLater_->isActive())
        // The last snapshot before a pause or a quiet spell is shown too, a little later.
        readoutLater_->start(std::max(0, kReadoutMs - int(readoutClock_.elapsed())));
    setEditUnderWay(st.folding, st.settling);
    if (!input_->toolPressed()) {
        heldBackSaid_ = false;
    } else if (st.grabHeldBack > kHeldBackSaid && !heldBackSaid_) {
        heldBackSaid_ = true;
        statusBar()->showMessage(
            tr("The pins hold this paper taut: the hand pulls it with at most %1 N, as a pinch "
               "does before paper slips from it, and paper does not stretch to follow.")
                .arg(QLocale().toString(kHandForce)),
            8000);
    }
    updateTitle();
}

void MainWindow::showReadouts(const SimulationStatus& st) {
    readoutLater_->stop();
    readout_->show(st);
    solver_->showStatus(st);
    readoutShown_ = st;
    readoutClock_.start();
}

void MainWindow::setEditUnderWay(bool folding, bool settling) {
    if (foldUnderWay_ && !folding &&
        statusBar()->currentMessage() == foldAnswerText(FoldRefusal::None))
        statusBar()->clearMessage();
    foldUnderWay_ = folding;
    settleUnderWay_ = settling;
    gateUndo();
}

bool MainWindow::refusedWhileThePaperIsHeld() {
    // Not in the middle of a push; said, for a silent refusal seemed lost.
    if (!input_->toolPressed()) return false;
    statusBar()->showMessage(tr("Not now: the mouse holds the paper. Let go first."), 5000);
    return true;
}

void MainWindow::gateUndo() {
    // While a fold is carried round, the sheet is the fold's: the session refuses undo
    // and redo, so the history must not move either. While the mouse holds the paper
    // (Push or Grab), the step it makes is not in the history yet: Ctrl+Z then undid
    // the step before it and took the held push's breaks with it, and a redo the
    // session refused still moved the history. A Settle becomes a step once the sheet
    // freezes (at most EditSession::kSettleSeconds of the sheet's time): Ctrl+Z while it
    // settled undid the step before it, where a user meant the Settle.
    const bool busy = foldUnderWay_ || settleUnderWay_ || input_->toolPressed();
    undoView_->setEnabled(!busy);
    // A greyed Undo said nothing of why (a helper pressed Ctrl+Z during a fold and saw
    // nothing happen): its tip and the shortcut say it.
    whyUndoWaits_ = foldUnderWay_ && !playing_
                        ? tr("Undo waits until the fold is let go, and the simulation is "
                             "paused: Space plays.")
                    : foldUnderWay_   ? tr("Undo waits until the fold is let go.")
                    : settleUnderWay_ ? tr("Undo waits until the sheet has settled.")
                    : busy            ? tr("Undo waits until the mouse lets go of the paper.")
                                      : QString();
    for (const char* name : {"undo", "redo"}) {
        action(name)->setToolTip(whyUndoWaits_); // empty: the action's own text
        action(name)->setStatusTip(whyUndoWaits_);
    }
    for (QShortcut* waits : historyWaits_) waits->setEnabled(busy);
    // Until the session has answered what was sent (SimulationThread::awaitingAnswers),
    // for a frame or so: only the actions, so that the History does not flicker grey at
    // every undo.
    const bool waiting = busy || sim_->awaitingAnswers();
    action("undo")->setEnabled(!waiting && undo_->canUndo());
    action("redo")->setEnabled(!waiting && undo_->canRedo());
}

QString MainWindow::foldAnswerText(FoldRefusal refusal) {
    switch (refusal) {
    case FoldRefusal::None:
        return tr("Folding: the paper is carried round the line, pressed and let go…");
    case FoldRefusal::ShortLine:
        return tr("Not folded: draw a longer line across the paper.");
    case FoldRefusal::OffSheet:
        return tr("Not folded: the line must cross the paper.");
    case FoldRefusal::NothingToFold:
        return tr("Not folded: there is paper on one side of the line only.");
    case FoldRefusal::DeskInTheWay:
        return tr("Not folded: this way the flap would go through the desk, and pins hold the "
                  "paper down. Fold the other way (Valley or Mountain), or unpin the paper.");
    case FoldRefusal::BadAngle:
        return tr("Not folded: the angle must lie between 1° and 180°.");
    case FoldRefusal::PinnedBothSides:
        return tr("Not folded: pins hold the paper on both sides of the line. Unpin one side: "
                  "the pinned side stays, the other is folded over.");
    case FoldRefusal::Busy:
        return tr("Not folded: another edit is under way.");
    }
    return {};
}

// A sheet from a file is modified when it differs from the file: its positions and
// velocities, or its parameters (an undo back to the saved sheet is not a change). A
// fresh scene that only ran is not worth a prompt; one the user edited is.
bool MainWindow::isModified() const {
    if (file_.isEmpty()) return !undo_->isClean();
    return lastHash_ != savedHash_ || !(params() == savedParams_);
}

void MainWindow::updateTitle() {
    const QString name = file_.isEmpty() ? tr("Untitled") : QFileInfo(file_).fileName();
    setWindowTitle(tr("%1[*] — PaperFold").arg(name));
    setWindowModified(isModified());
}

World MainWindow::sceneWorldWithParams(const QString& scene) const {
    World w = sceneWorld(scene);
    const bool breaking = w.params.breaking; // the scene's own (drape has none)
    w.params = params();
    w.params.breaking = breaking;
    return w;
}

void MainWindow::newScene(const QString& scene) {
    scene_ = scene;
    const World w = sceneWorldWithParams(scene);
    parameters_->set(w.params); // the window's parameters are the sheet's
    sim_->replaceWorld(w);
    undo_->clear();
    file_.clear();
    openedFrom_.clear();
    nameHistoryStart();
    updateTitle();
}

bool MainWindow::openFile(const QString& path) {
    WorldLoad load = loadWorld(path);
    if (!load.world) {
        showError(tr("Could not open the sheet: %1").arg(load.error));
        return false;
    }
    parameters_->set(load.world->params);
    savedHash_ = lastHash_ = editedStateHash(load.world->sheet);
    savedParams_ = load.world->params;
    sim_->replaceWorld(*load.world);
    scene_ = QString::fromStdString(load.world->scene);
    undo_->clear();
    file_ = path;
    openedFrom_ = path;
    nameHistoryStart();
    recent_->add(path);
    updateTitle();
    return true;
}

void MainWindow::saveRecording(const QString& path) {
    EditLog log = sim_->copyRecording();
    log.start.params.sigma = params().sigma; // a look: the simulation never had it
    QString error;
    if (!pf::saveRecording(log, path, &error)) {
        showError(tr("Could not save the recording: %1").arg(error));
        return;
    }
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
}

bool MainWindow::saveFile(const QString& path) {
    World world = sim_->copyWorld();
    world.params.sigma = params().sigma; // a look: the simulation never had it
    QString error;
    if (!saveWorld(world, path, &error)) {
        showError(tr("Could not save the sheet: %1").arg(error));
        return false;
    }
    file_ = path;
    savedHash_ = lastHash_ = editedStateHash(world.sheet);
    savedParams_ = world.params;
    undo_->setClean();
    recent_->add(path);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
    return true;
}

// A name typed without a suffix gets the kind's: a sheet saved as "folded" was not listed
// by Open's "*.paper" filter, nor could Open take it.
QString MainWindow::chooseFileToWrite(FileDialog kind) {
    const QString path = chooseFile(kind);
    if (path.isEmpty() || !QFileInfo(path).suffix().isEmpty()) return path;
    switch (kind) {
    case FileDialog::Save:
        return path + QStringLiteral(".paper");
    case FileDialog::SaveRecording:
        return path + QStringLiteral(".paperrec");
    case FileDialog::ExportImage:
        return path + QStringLiteral(".png");
    case FileDialog::ExportMesh:
        return path + QStringLiteral(".glb"); // the one that keeps the paper's look
    default:
        return path;
    }
}

bool MainWindow::maybeSave() {
    if (!isModified()) return true;
    switch (askToSave()) {
    case QMessageBox::Save: {
        const QString path = file_.isEmpty() ? chooseFileToWrite(FileDialog::Save) : file_;
        return !path.isEmpty() && saveFile(path);
    }
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (exporting_) {
        statusBar()->showMessage(tr("An image is being exported; close once it is written."), 5000);
        event->ignore();
        return;
    }
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

Vec3 MainWindow::toolTarget() const {
    return input_->toolTarget();
}

bool MainWindow::toolPressed() const {
    return input_->toolPressed();
}

void MainWindow::exportImage() {
    if (exporting_) return; // one at a time: this one waits in a nested event loop
    // Held for the worker: new frames replace the viewport's while it renders.
    const std::shared_ptr<const SheetSnapshot> snap = viewport_->sharedSnapshot();
    if (!snap) return;
    // A size out of range is said and asked again (a user's 0x0 ended the export, which
    // had to be started over), until one fits or the dialog is cancelled.
    QSize size;
    for (;;) {
        size = chooseImageSize();
        if (!size.isValid()) return; // cancelled
        if (OffscreenRenderer::sizeAllowed(size.width(), size.height())) break;
        showError(tr("The image size is width x height, each from 16 to %1 pixels, such as "
                     "1920x1080.")
                      .arg(OffscreenRenderer::kMaxSize));
    }
    const QString path = chooseFileToWrite(FileDialog::ExportImage);
    if (path.isEmpty()) return;
    QSettings().setValue(QLatin1String(kImageSizeSetting), size);
    RenderOptions picture = viewport_->renderOptions();
    picture.pins = false;   // editing marks, not the artwork,
    picture.sphere = false; // as is the tool under the cursor
    // A large picture takes seconds in software: it renders on a thread of its own
    // (OSMesa needs no window) while a dialog says so and the window stays drawn.
    QString error;
    bool written = false;
    const OrbitCamera camera = viewport_->camera();
    QProgressDialog progress(
        tr("Rendering the image (%1 x %2)…").arg(size.width()).arg(size.height()), QString(), 0, 0,
        this);
    progress.setWindowTitle(tr("Export Image"));
    progress.setWindowModality(Qt::WindowModal);
    // The render cannot be stopped (OSMesa has no way to), so the dialog cannot be sent
    // away either: Escape closed it, and the image was written seconds later anyway.
    StaysOpen staysOpen;
    progress.installEventFilter(&staysOpen);
    progress.setMinimumDuration(400); // no flash for a small image
    progress.setValue(0);             // starts the minimum-duration timer of a busy indicator
    exporting_ = true;                // until then Export Image and closing the window wait
    // The worker only sets an atomic flag, which the window polls, and its results are
    // read after the join: synchronisation ThreadSanitizer sees (a queued Qt call or
    // QThread::wait would hand over through Qt's uninstrumented locks).
    std::atomic<bool> done = false;
    std::thread worker([&] {
        written =
            exportSnapshotImage(*snap, camera, picture, size.width(), size.height(), path, &error);
        done = true;
    });
    QEventLoop wait;
    QTimer poll;
    connect(&poll, &QTimer::timeout, &wait, [&] {
        if (done) wait.quit();
    });
    poll.start(20);
    wait.exec();
    worker.join();
    exporting_ = false;
    progress.reset();
    if (written)
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 5000);
    else
        showError(tr("Could not export the image: %1").arg(error));
}

void MainWindow::exportMesh() {
    // Held: the dialogs below run the event loop, and the frames published meanwhile
    // replace the viewport's snapshot (a raw pointer to it wrote empty meshes, or
    // crashed, while the sheet moved).
    const std::shared_ptr<const SheetSnapshot> snap = viewport_->sharedSnapshot();
    if (!snap) return;
    RenderOptions surface = viewport_->renderOptions();
    surface.subdivision = chooseMeshSubdivision(surface.subdivision);
    if (surface.subdivision < 0) return; // cancelled
    const QString path = chooseFileToWrite(FileDialog::ExportMesh);
    if (path.isEmpty()) return;
    MeshFormat format;
    if (!meshFormatForPath(path, &format)) {
        showError(tr("Choose a file ending in .obj, .ply or .glb"));
        return;
    }
    QString error;
    if (exportSnapshotMesh(*snap, surface, path, format, &error))
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 5000);
    else
        showError(tr("Could not export the mesh: %1").arg(error));
}

} // namespace pf
