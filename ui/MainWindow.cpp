#include "MainWindow.h"

#include "AllocatorTuning.h"
#include "OffscreenRenderer.h"
#include "ParameterPanel.h"
#include "PngFile.h"
#include "RecordingFile.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SimulationThread.h"
#include "SolverPanel.h"
#include "Subdivision.h"
#include "SurfaceExport.h"
#include "UndoCommands.h"
#include "Viewport.h"
#include "ViewportInput.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QLibraryInfo>
#include <QLocale>
#include <QMenuBar>
#include <QMouseEvent>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QTranslator>
#include <QUndoStack>
#include <QUndoView>
#include <QVBoxLayout>
#include <QWheelEvent>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pf {

namespace {

constexpr int kMaxRecent = 8;

const char* const kOverlayActions[] = {"overlay.springs", "overlay.probability", "overlay.strain",
                                       "overlay.breaks", "overlay.wireframe"};
const Overlay kOverlayBits[] = {OverlaySpringKinds, OverlayBreakProbability, OverlayStrain,
                                OverlayRecentBreaks, OverlayWireframe};

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("MainWindow"));
    keepLargeAllocationsReturnable(); // so that New gives a crumpled sheet's memory back
    const World first = sceneWorld(scene_);
    params_ = first.params;
    sim_ = std::make_unique<SimulationThread>(first);

    viewport_ = new Viewport(this);
    viewport_->setMouseTracking(true);
    viewport_->setFocusPolicy(Qt::StrongFocus);
    input_ = new ViewportInput(viewport_, sim_.get(), this);
    setCentralWidget(viewport_);
    undo_ = new QUndoStack(this);

    chooseFile = [this](FileDialog kind) {
        const QString sheets = tr("PaperFold sheets (*.paper)");
        switch (kind) {
        case FileDialog::Open:
            return QFileDialog::getOpenFileName(this, tr("Open Sheet"), QString(), sheets);
        case FileDialog::Save:
            return QFileDialog::getSaveFileName(this, tr("Save Sheet"), file_, sheets);
        case FileDialog::ExportImage:
            return QFileDialog::getSaveFileName(this, tr("Export Image"), QString(),
                                                tr("PNG images (*.png)"));
        case FileDialog::ExportMesh:
            return QFileDialog::getSaveFileName(this, tr("Export Mesh"), QString(),
                                                tr("Meshes (*.obj *.ply *.glb)"));
        case FileDialog::SaveRecording:
            return QFileDialog::getSaveFileName(this, tr("Save Recording"), QString(),
                                                tr("PaperFold recordings (*.paperrec)"));
        }
        return QString();
    };
    showError = [this](const QString& message) {
        QMessageBox::critical(this, tr("PaperFold"), message);
    };
    askToSave = [this] {
        return QMessageBox::warning(this, tr("PaperFold"),
                                    tr("The sheet has unsaved changes. Save them?"),
                                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    };
    chooseImageSize = [this] {
        bool ok = false;
        const QString text =
            QInputDialog::getText(this, tr("Export Image"), tr("Size in pixels (width x height):"),
                                  QLineEdit::Normal, QStringLiteral("1920x1080"), &ok);
        const QStringList wh = text.split(QLatin1Char('x'));
        if (!ok || wh.size() != 2) return QSize();
        return QSize(wh[0].trimmed().toInt(), wh[1].trimmed().toInt());
    };

    createActions();
    createMenus();
    createDocks();
    fpsLabel_ = new QLabel(this);
    stepLabel_ = new QLabel(this);
    countsLabel_ = new QLabel(this);
    statusBar()->addWidget(fpsLabel_);
    statusBar()->addWidget(stepLabel_);
    statusBar()->addPermanentWidget(countsLabel_);
    panel_->showParams(params_);
    solver_->showParams(params_);
    panel_->setToolRadius(input_->toolRadius());

    connect(sim_.get(), &SimulationThread::snapshotReady, this, &MainWindow::onSnapshot);
    // After New/Open the crumpled sheet, its snapshots and the renderer's buffers for it
    // are freed, but glibc keeps the freed pages in its arenas (the simulation thread's
    // and the GUI's): give them back once the new sheet's first frame is drawn.
    connect(sim_.get(), &SimulationThread::worldReplaced, this, [this] { releasePending_ = true; });
    connect(viewport_, &Viewport::frameDrawn, this, [this] {
        if (!releasePending_) return;
        releasePending_ = false;
#if defined(__GLIBC__)
        malloc_trim(0);
#endif
    });
    connect(sim_.get(), &SimulationThread::strokeRecorded, this, [this](int stroke, int events) {
        undo_->push(new PushStrokeCommand(sim_.get(), stroke, events));
    });
    connect(sim_.get(), &SimulationThread::diverged, this, [this](qint64 step) {
        playing_ = false;
        showError(
            tr("The simulation blew up at step %1 and was paused; the last good state is kept. "
               "Try more steps per second or the jacobi integrator.")
                .arg(step));
    });
    connect(undo_, &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(panel_, &ParameterPanel::paramsEdited, this, &MainWindow::onParamsEdited);
    connect(solver_, &SolverPanel::paramsEdited, this, &MainWindow::onParamsEdited);
    connect(solver_, &SolverPanel::openChartRequested, this, &MainWindow::openLatestChart);
    chartFolder =
        QSettings().value(QStringLiteral("bench/folder"), QStringLiteral("bench")).toString();
    connect(panel_, &ParameterPanel::toolRadiusChanged, input_, &ViewportInput::setToolRadius);
    connect(input_, &ViewportInput::toolRadiusChanged, panel_, &ParameterPanel::setToolRadius);

    retranslate();
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    if (settings.value(QStringLiteral("window/geometry")).isNull()) resize(1280, 800);
    fpsClock_.start();
    updateTitle();
}

MainWindow::~MainWindow() {
    // Children (the undo stack, the panel, the viewport) are deleted by ~QObject, after
    // this object's own part and the simulation thread are gone; stop them calling back.
    // The input filter talks to the simulation thread, which goes before the widgets do.
    viewport_->removeEventFilter(input_);
    undo_->disconnect(this);
    panel_->disconnect(this);
    solver_->disconnect(this);
}

World MainWindow::sceneWorld(const QString& scene) const {
    SceneOptions options;
    if (panel_) {
        options.resolution = panel_->resolution();
        options.width = panel_->sheetWidth();
        options.length = panel_->sheetLength();
    }
    World w = makeScene(scene.toStdString(), options).value_or(*makeScene("press"));
    w.script.sphereKeys.clear();
    // The solver lab's fix: the paper's step would let a hanging sheet fall at 0.4 % of g.
    w.params.gravityOutsideFilter = true;
    w.sphere.radius = input_ ? input_->toolRadius() : ViewportInput::kDefaultToolRadius;
    w.sphere.active = false;
    return w;
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
                const QString path = file_.isEmpty() ? chooseFile(FileDialog::Save) : file_;
                if (!path.isEmpty()) saveFile(path);
            });
    connect(make("saveAs", QKeySequence::SaveAs), &QAction::triggered, this, [this] {
        const QString path = chooseFile(FileDialog::Save);
        if (!path.isEmpty()) saveFile(path);
    });
    connect(make("saveRecording"), &QAction::triggered, this, [this] {
        const QString path = chooseFile(FileDialog::SaveRecording);
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
        sim_->setPlaying(on);
        action("play")->setIcon(
            style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    connect(make("step", QKeySequence(tr("Ctrl+.")), QStyle::SP_MediaSkipForward),
            &QAction::triggered, this, [this] {
                action("play")->setChecked(false);
                sim_->stepOnce();
            });
    connect(make("reset", QKeySequence(tr("Ctrl+R")), QStyle::SP_BrowserReload),
            &QAction::triggered, this, [this] {
                if (maybeSave()) newScene(scene_);
            });

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
    connect(make("view.top", QKeySequence(Qt::Key_1)), &QAction::triggered, this,
            [this] { input_->setView("top"); });
    connect(make("view.front", QKeySequence(Qt::Key_2)), &QAction::triggered, this,
            [this] { input_->setView("front"); });
    connect(make("view.iso", QKeySequence(Qt::Key_3)), &QAction::triggered, this,
            [this] { input_->setView("iso"); });
    connect(make("view.fit", QKeySequence(Qt::Key_F)), &QAction::triggered, this,
            [this] { input_->fitCamera(); });
    connect(make("help", QKeySequence::HelpContents), &QAction::triggered, this,
            &MainWindow::showHelp);
    connect(make("about"), &QAction::triggered, this, [this] {
        QMessageBox::about(
            this, tr("About PaperFold"),
            tr("<p><b>PaperFold %1</b></p><p>Crumple and fold virtual paper in real time, "
               "after Kang &amp; Cho, <i>A Simple and Effective Model for Interactive "
               "Paper Folding</i>.</p>")
                .arg(QCoreApplication::applicationVersion()));
    });

    languageGroup_ = new QActionGroup(this);
    for (const char* code : {"", "en", "de", "ja", "ko"}) {
        QAction* a = make(qPrintable(QStringLiteral("language.") + QLatin1String(code)));
        a->setCheckable(true);
        a->setData(QString::fromLatin1(code));
        languageGroup_->addAction(a);
        connect(a, &QAction::triggered, this, [code] {
            installLanguage(QString::fromLatin1(code));
            QSettings().setValue(QStringLiteral("language"), QString::fromLatin1(code));
        });
    }
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

    viewMenu_ = menuBar()->addMenu(QString());
    overlayMenu_ = viewMenu_->addMenu(QString());
    for (const char* name : kOverlayActions) overlayMenu_->addAction(action(name));
    viewMenu_->addSeparator();
    for (const char* name : {"view.top", "view.front", "view.iso", "view.fit"})
        viewMenu_->addAction(action(name));
    viewMenu_->addSeparator();
    languageMenu_ = viewMenu_->addMenu(QString());
    languageMenu_->addActions(languageGroup_->actions());

    simMenu_ = menuBar()->addMenu(QString());
    for (const char* name : {"play", "step", "reset"}) simMenu_->addAction(action(name));

    helpMenu_ = menuBar()->addMenu(QString());
    helpMenu_->addAction(action("help"));
    helpMenu_->addAction(action("about"));

    toolBar_ = addToolBar(QString());
    toolBar_->setObjectName(QStringLiteral("mainToolBar"));
    for (const char* name : {"open", "save", "undo", "redo", "play", "step", "reset"})
        toolBar_->addAction(action(name));
    toolBar_->addSeparator();
    for (const char* name : kOverlayActions) toolBar_->addAction(action(name));
    updateRecentMenu();
}

void MainWindow::createDocks() {
    panel_ = new ParameterPanel(this);
    panelDock_ = new QDockWidget(this);
    panelDock_->setObjectName(QStringLiteral("parameterDock"));
    panelDock_->setWidget(panel_);
    addDockWidget(Qt::RightDockWidgetArea, panelDock_);
    undoView_ = new QUndoView(undo_, this);
    historyDock_ = new QDockWidget(this);
    historyDock_->setObjectName(QStringLiteral("historyDock"));
    historyDock_->setWidget(undoView_);
    addDockWidget(Qt::RightDockWidgetArea, historyDock_);
    solver_ = new SolverPanel(this);
    solverDock_ = new QDockWidget(this);
    solverDock_->setObjectName(QStringLiteral("solverDock"));
    solverDock_->setWidget(solver_);
    addDockWidget(Qt::RightDockWidgetArea, solverDock_);
    viewMenu_->addSeparator();
    viewMenu_->addAction(panelDock_->toggleViewAction());
    viewMenu_->addAction(historyDock_->toggleViewAction());
    viewMenu_->addAction(solverDock_->toggleViewAction());
}

void MainWindow::retranslate() {
    auto set = [this](const char* name, const QString& text, const QString& tip = QString()) {
        QAction* a = action(name);
        a->setText(text);
        a->setToolTip(tip.isEmpty() ? QString(text).remove(QLatin1Char('&')) : tip);
    };
    set("new.press", tr("&Press (sphere on a sheet)"));
    set("new.drape", tr("&Drape (hanging sheet)"));
    set("new.compress", tr("&Compress (edges pushed together)"));
    set("new.drop", tr("D&rop (tilted sheet falls)"));
    set("open", tr("&Open…"));
    set("save", tr("&Save"));
    set("saveAs", tr("Save &As…"));
    set("saveRecording", tr("Save &Recording…"),
        tr("Save everything done since New or Open; paperfold replay does it again"));
    set("exportImage", tr("Export &Image…"));
    set("exportMesh", tr("Export &Mesh…"));
    set("quit", tr("&Quit"));
    set("play", tr("&Play"), tr("Play or pause the simulation (Space)"));
    set("step", tr("S&tep"), tr("Advance one step"));
    set("reset", tr("&Reset"), tr("Start the current scene again"));
    set("overlay.springs", tr("&Spring kinds"));
    set("overlay.probability", tr("&Break probability"));
    set("overlay.strain", tr("S&train"));
    set("overlay.breaks", tr("&Recent breaks"));
    set("overlay.wireframe", tr("Simulation &wireframe"));
    set("view.top", tr("&Top"));
    set("view.front", tr("&Front"));
    set("view.iso", tr("&Isometric"));
    set("view.fit", tr("Fit to &sheet"));
    set("help", tr("&Mouse and Keys"));
    set("about", tr("&About PaperFold"));
    set("language.", tr("System language"));
    set("language.en", QStringLiteral("English"));
    set("language.de", QStringLiteral("Deutsch"));
    set("language.ja", QStringLiteral("日本語"));
    set("language.ko", QStringLiteral("한국어"));
    action("undo")->setText(tr("&Undo"));
    action("redo")->setText(tr("&Redo"));
    undo_->setUndoLimit(0);
    fileMenu_->setTitle(tr("&File"));
    newMenu_->setTitle(tr("&New"));
    recentMenu_->setTitle(tr("Open &Recent"));
    editMenu_->setTitle(tr("&Edit"));
    viewMenu_->setTitle(tr("&View"));
    overlayMenu_->setTitle(tr("&Overlays"));
    languageMenu_->setTitle(tr("&Language"));
    simMenu_->setTitle(tr("&Simulation"));
    helpMenu_->setTitle(tr("&Help"));
    toolBar_->setWindowTitle(tr("Main toolbar"));
    panelDock_->setWindowTitle(tr("Parameters"));
    historyDock_->setWindowTitle(tr("History"));
    solverDock_->setWindowTitle(tr("Solver"));
    undoView_->setEmptyLabel(tr("<new sheet>"));
    updateTitle();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(event);
}

bool MainWindow::installLanguage(const QString& code) {
    static QTranslator* current = nullptr;
    if (current) {
        QCoreApplication::removeTranslator(current);
        delete current;
        current = nullptr;
    }
    const QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    auto* t = new QTranslator;
    if (!t->load(locale, QStringLiteral("paperfold"), QStringLiteral("_"),
                 QStringLiteral(":/i18n"))) {
        delete t;
        // English is the source language: no translator needed.
        return code.isEmpty() || code == QLatin1String("en");
    }
    QCoreApplication::installTranslator(t);
    current = t;
    return true;
}

void MainWindow::onSnapshot() {
    auto snap = sim_->latestSnapshot();
    if (!snap) return;
    viewport_->setSnapshot(snap);
    if (firstSnapshot_) {
        firstSnapshot_ = false;
        input_->fitCamera();
    }
    const SimulationStatus st = sim_->status();
    lastStep_ = st.step;
    ++framesSinceFps_;
    if (fpsClock_.elapsed() > 500) {
        fps_ = 1000.0 * framesSinceFps_ / fpsClock_.restart();
        framesSinceFps_ = 0;
    }
    fpsLabel_->setText(tr("%1 fps").arg(fps_, 0, 'f', 0));
    stepLabel_->setText(tr("step %1 µs").arg(st.stepSeconds * 1e6, 0, 'f', 0));
    solver_->showStatus(st);
    countsLabel_->setText(tr("%1 vertices · %2 springs · %3 breaks · %4 hinges")
                              .arg(st.vertices)
                              .arg(st.springs)
                              .arg(st.breaks)
                              .arg(st.hinges));
    updateTitle();
}

// User edits always count. Simulating further counts for a sheet that came from a
// file (the file no longer holds it); a fresh scene that only ran is not worth a prompt.
bool MainWindow::isModified() const {
    return !undo_->isClean() || (!file_.isEmpty() && lastStep_ != savedStep_);
}

void MainWindow::updateTitle() {
    const QString name = file_.isEmpty() ? tr("Untitled") : QFileInfo(file_).fileName();
    setWindowTitle(tr("%1[*] — PaperFold").arg(name));
    setWindowModified(isModified());
}

void MainWindow::applyParams(const SimParams& params) {
    params_ = params;
    panel_->showParams(params);
    solver_->showParams(params);
    sim_->setParams(params);
}

void MainWindow::onParamsEdited(const SimParams& params, const QString& what, int drag) {
    const SimParams before = params_;
    params_ = params;
    // Each panel edits some fields; keep both showing (and sending) the whole.
    panel_->showParams(params_);
    solver_->showParams(params_);
    undo_->push(new ParameterCommand(before, params, what, drag,
                                     [this](const SimParams& p) { applyParams(p); }));
}

void MainWindow::newScene(const QString& scene) {
    scene_ = scene;
    World w = sceneWorld(scene);
    const bool breaking = w.params.breaking; // the scene's own (drape has none)
    w.params = params_;
    w.params.breaking = breaking;
    sim_->replaceWorld(w);
    undo_->clear();
    file_.clear();
    savedStep_ = 0;
    lastStep_ = 0;
    firstSnapshot_ = true;
    updateTitle();
}

bool MainWindow::openFile(const QString& path) {
    WorldLoad load = loadWorld(path);
    if (!load.world) {
        showError(tr("Could not open the sheet: %1").arg(load.error));
        return false;
    }
    params_ = load.world->params;
    panel_->showParams(params_);
    solver_->showParams(params_);
    savedStep_ = lastStep_ = load.world->stepCount;
    sim_->replaceWorld(*load.world);
    scene_ = QString::fromStdString(load.world->scene);
    undo_->clear();
    file_ = path;
    firstSnapshot_ = true;
    addRecent(path);
    updateTitle();
    return true;
}

template <typename T, typename Reply, typename Request>
std::shared_ptr<const T> MainWindow::awaitReply(Reply reply, Request request) {
    // Waits at most one simulation frame for the copy.
    const quint64 id = nextRequest_++;
    std::shared_ptr<const T> result;
    QEventLoop loop;
    auto c = connect(sim_.get(), reply, &loop, [&](quint64 got, std::shared_ptr<const T> copy) {
        if (got != id) return;
        result = std::move(copy);
        loop.quit();
    });
    (sim_.get()->*request)(id);
    QTimer::singleShot(5000, &loop, &QEventLoop::quit);
    loop.exec(QEventLoop::ExcludeUserInputEvents);
    disconnect(c);
    return result;
}

std::shared_ptr<const World> MainWindow::fetchWorld() {
    return awaitReply<World>(&SimulationThread::worldCopied, &SimulationThread::requestWorld);
}

std::shared_ptr<const EditLog> MainWindow::fetchRecording() {
    return awaitReply<EditLog>(&SimulationThread::recordingCopied,
                               &SimulationThread::requestRecording);
}

void MainWindow::saveRecording(const QString& path) {
    const auto log = fetchRecording();
    QString error;
    if (!log || !pf::saveRecording(*log, path, &error)) {
        showError(tr("Could not save the recording: %1")
                      .arg(log ? error : tr("the simulation did not answer")));
        return;
    }
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
}

bool MainWindow::saveFile(const QString& path) {
    const auto world = fetchWorld();
    QString error;
    if (!world || !saveWorld(*world, path, &error)) {
        showError(tr("Could not save the sheet: %1")
                      .arg(world ? error : tr("the simulation did not answer")));
        return false;
    }
    file_ = path;
    savedStep_ = lastStep_ = world->stepCount;
    undo_->setClean();
    addRecent(path);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
    return true;
}

bool MainWindow::maybeSave() {
    if (!isModified()) return true;
    switch (askToSave()) {
    case QMessageBox::Save: {
        const QString path = file_.isEmpty() ? chooseFile(FileDialog::Save) : file_;
        return !path.isEmpty() && saveFile(path);
    }
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

void MainWindow::addRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), recent);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& path : recent) {
        QAction* a = recentMenu_->addAction(QFileInfo(path).fileName());
        a->setToolTip(path);
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybeSave()) openFile(path);
        });
    }
    recentMenu_->setEnabled(!recent.isEmpty());
}

Vec3 MainWindow::toolTarget() const {
    return input_->toolTarget();
}

bool MainWindow::toolPressed() const {
    return input_->toolPressed();
}

void MainWindow::exportImage() {
    auto snap = viewport_->snapshot();
    if (!snap) return;
    const QSize size = chooseImageSize();
    if (!size.isValid()) return;
    const QString path = chooseFile(FileDialog::ExportImage);
    if (path.isEmpty()) return;
    QString error;
    auto renderer = OffscreenRenderer::create(size.width(), size.height(), &error);
    if (!renderer) {
        showError(tr("Could not export the image: %1").arg(error));
        return;
    }
    OrbitCamera camera = viewport_->camera();
    const QImage image = renderer->render(*snap, camera, viewport_->renderOptions());
    if (!writePng(image, path, &error)) showError(tr("Could not export the image: %1").arg(error));
}

void MainWindow::exportMesh() {
    auto snap = viewport_->snapshot();
    if (!snap) return;
    const QString path = chooseFile(FileDialog::ExportMesh);
    if (path.isEmpty()) return;
    MeshFormat format;
    if (!meshFormatForPath(path, &format)) {
        showError(tr("Choose a file ending in .obj, .ply or .glb"));
        return;
    }
    const SurfaceMesh mesh = subdivide(snap->x, snap->tris, nullptr, snap->sigma,
                                       viewport_->renderOptions().subdivision);
    QString error;
    if (!writeSurface(mesh, path, format, true, &error))
        showError(tr("Could not export the mesh: %1").arg(error));
}

void MainWindow::openLatestChart() {
    QDir dir(chartFolder);
    QFileInfoList charts =
        dir.entryInfoList({QStringLiteral("bench_*.png")}, QDir::Files, QDir::Time);
    if (charts.isEmpty()) {
        const QString picked = QFileDialog::getExistingDirectory(
            this, tr("Folder written by 'paperfold bench'"), chartFolder);
        if (picked.isEmpty()) return;
        chartFolder = picked;
        QSettings().setValue(QStringLiteral("bench/folder"), picked);
        charts =
            QDir(picked).entryInfoList({QStringLiteral("bench_*.png")}, QDir::Files, QDir::Time);
    }
    if (charts.isEmpty()) {
        showError(
            tr("No bench_*.png in %1. Run: paperfold bench --output-dir %1").arg(chartFolder));
        return;
    }
    lastChart_ = charts.first().absoluteFilePath();
    auto* dialog = new QDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(charts.first().fileName());
    auto* layout = new QVBoxLayout(dialog);
    auto* picture = new QLabel(dialog);
    picture->setPixmap(QPixmap(lastChart_));
    auto* scroll = new QScrollArea(dialog);
    scroll->setWidget(picture);
    layout->addWidget(scroll);
    dialog->resize(1000, 640);
    dialog->show();
}

void MainWindow::showHelp() {
    QMessageBox::information(
        this, tr("Mouse and Keys"),
        tr("<table>"
           "<tr><td><b>Move the mouse</b></td><td>the sphere follows the cursor over the "
           "sheet</td></tr>"
           "<tr><td><b>Left drag</b></td><td>push the sphere into the paper (one undo step per "
           "stroke)</td></tr>"
           "<tr><td><b>Ctrl + wheel</b></td><td>sphere radius</td></tr>"
           "<tr><td><b>Right drag</b>, arrow keys</td><td>orbit the camera</td></tr>"
           "<tr><td><b>Middle drag</b>, Shift + right drag</td><td>pan</td></tr>"
           "<tr><td><b>Wheel</b>, + and −</td><td>zoom</td></tr>"
           "<tr><td><b>1</b>, <b>2</b>, <b>3</b>, <b>F</b></td><td>top, front, isometric view; fit "
           "to sheet</td></tr>"
           "<tr><td><b>Space</b>, <b>Ctrl+.</b>, <b>Ctrl+R</b></td><td>play/pause, single step, "
           "reset</td></tr>"
           "<tr><td><b>Alt+1…5</b></td><td>overlays: spring kinds, break probability, strain, "
           "recent breaks, wireframe</td></tr>"
           "<tr><td><b>Ctrl+Z</b>, <b>Ctrl+Shift+Z</b></td><td>undo, redo</td></tr>"
           "</table>"));
}

} // namespace pf
