#pragma once

#include "Camera.h"
#include "EditorDialogs.h"
#include "FoldPlan.h"
#include "Params.h"
#include "Picking.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"
#include "SimulationStatus.h"
#include "World.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QMessageBox>
#include <functional>
#include <memory>
#include <vector>

class QAction;
class QShortcut;
class QActionGroup;
class QDockWidget;
class QMenu;
class QTimer;
class QToolBar;
class QUndoStack;
class QUndoView;

namespace pf {

class ChartBrowser;
class EditorParameters;
class PaperLookMenu;
class ParameterPanel;
class RecentFiles;
class SolverPanel;
class StatusReadout;
class SimulationThread;
class Viewport;
class ViewportInput;

// The editor: viewport, parameter panel, undo history, menus, toolbar, status bar.
// It only talks to the simulation through SimulationThread.
class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    // QSettings key: true once the first-run hint was dismissed.
    static constexpr const char* kHintSetting = "hints/firstRunDone";
    static constexpr const char* kThreadsSetting = "solver/threads";
    // The size of the last image exported, offered by the next Export Image (a user typed
    // 1280x720 and was offered 1920x1080 again every time).
    static constexpr const char* kImageSizeSetting = "export/imageSize";
    // View ▸ Crease Lines, kept for the next session.
    static constexpr const char* kCreasesSetting = "look/creases";
    // How often the live numbers (step time, stretch, fps) are redrawn at most.
    static constexpr int kReadoutMs = 250;
    // Paper the hand holds this far from the cursor, with pins holding it too, is held
    // back by the pins: the status bar says so, once a grab (m).
    static constexpr double kHeldBackSaid = 0.02;
    // The cores that step the sheet unless the user chose: all but one, which the view
    // needs (ui/README.md, "Cores for the step": on two cores, stepping on both while
    // the view drew made a 50k-spring sheet's steps 1.3-1.6 times slower).
    static int defaultThreads();
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Hooks the tests replace; by default they show dialogs.
    using FileDialog = pf::FileDialog;
    std::function<QString(FileDialog)> chooseFile;
    std::function<void(const QString&)> showError;
    std::function<QMessageBox::StandardButton()> askToSave;
    std::function<QSize()> chooseImageSize;
    // An invalid colour when cancelled.
    std::function<QColor(const QColor&)> chooseColor;
    // Export Mesh's subdivision level (0..kMaxSubdivisionLevel), -1 when cancelled.
    std::function<int(int current)> chooseMeshSubdivision;

    // Actions, for tests and the toolbar.
    QAction* action(const char* name) const;

    SimulationThread* simulation() const { return sim_.get(); }
    Viewport* viewport() const { return viewport_; }
    ParameterPanel* panel() const { return panel_; }
    PaperLookMenu* paperLook() const { return paperLook_; }
    SolverPanel* solverPanel() const { return solver_; }
    // Open Latest Chart (the Solver dock's button).
    ChartBrowser* charts() const { return charts_; }
    QUndoStack* undoStack() const { return undo_; }
    EditorParameters* parameters() const { return parameters_; }
    const SimParams& params() const;
    QString currentFile() const { return file_; }
    bool isModified() const;
    // The last tool pose sent to the simulation (target centre, radius, pressed).
    Vec3 toolTarget() const;
    bool toolPressed() const;

    bool openFile(const QString& path);
    bool saveFile(const QString& path);
    void newScene(const QString& scene);

  protected:
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    void createActions();
    void createMenus();
    void createDocks();
    void fitDocks();
    void retranslate();
    void connectParameters();
    void onSnapshot();
    void updateTitle();
    // chooseFile, with the kind's suffix added to a name typed without one.
    QString chooseFileToWrite(FileDialog kind);
    bool maybeSave();
    void saveRecording(const QString& path);
    void exportImage();
    void exportMesh();
    World sceneWorld(const QString& scene) const;
    // The scene's fresh sheet with the window's parameters (New and Reset).
    World sceneWorldWithParams(const QString& scene) const;

    std::unique_ptr<SimulationThread> sim_;
    Viewport* viewport_ = nullptr;
    ViewportInput* input_ = nullptr;
    ParameterPanel* panel_ = nullptr;
    PaperLookMenu* paperLook_ = nullptr;
    SolverPanel* solver_ = nullptr;
    EditorParameters* parameters_ = nullptr;
    ChartBrowser* charts_ = nullptr;
    RecentFiles* recent_ = nullptr;
    QUndoStack* undo_ = nullptr;
    QUndoView* undoView_ = nullptr;
    QDockWidget *panelDock_ = nullptr, *historyDock_ = nullptr, *solverDock_ = nullptr;
    QToolBar* toolBar_ = nullptr;
    QMenu *fileMenu_ = nullptr, *newMenu_ = nullptr, *recentMenu_ = nullptr, *editMenu_ = nullptr,
          *viewMenu_ = nullptr, *overlayMenu_ = nullptr, *languageMenu_ = nullptr,
          *simMenu_ = nullptr, *helpMenu_ = nullptr, *toolMenu_ = nullptr;
    StatusReadout* readout_ = nullptr;
    QActionGroup* languageGroup_ = nullptr;

    QString scene_ = QStringLiteral("press");
    static constexpr int kMinimumWidth = 640, kMinimumHeight = 480;
    bool foldUnderWay_ = false;
    bool heldBackSaid_ = false; // in this grab
    bool settleUnderWay_ = false;
    // Ctrl+Z, Ctrl+Shift+Z and Ctrl+Y while the history waits (gateUndo): they say why nothing
    // happened, and only then are enabled (beside the enabled actions they would clash).
    std::vector<QShortcut*> historyWaits_;
    QString whyUndoWaits_;
    void setEditUnderWay(bool folding, bool settling);
    void showReadouts(const SimulationStatus& st);
    // Undo, Redo and the history enabled as the stack allows, unless a fold is carried,
    // a Settle settles, the mouse holds the paper, or (Undo and Redo only) the simulation
    // has not answered the last click or release yet.
    void gateUndo();
    // Settle and Reset wait while the mouse holds the paper: says so, and returns true.
    bool refusedWhileThePaperIsHeld();
    // What the status bar says to a fold: that it began, or why it was refused.
    static QString foldAnswerText(FoldRefusal refusal);
    QString file_;
    // The file the sheet was opened from (empty for a new sheet): the history's first
    // entry names it.
    QString openedFrom_;
    void nameHistoryStart();
    // What the file holds, and the sheet's state in the newest snapshot (stateHash).
    std::uint64_t savedHash_ = 0, lastHash_ = 0;
    SimParams savedParams_;
    bool firstSnapshot_ = true;
    // The readouts as last shown, and when (onSnapshot).
    SimulationStatus readoutShown_;
    QElapsedTimer readoutClock_;
    QTimer* readoutLater_ = nullptr; // shows a snapshot's numbers the throttle held back
    // Set when the simulation replaced its World (New, Open, Reset): the next frame
    // drawn hands the freed heap back to the system.
    bool releasePending_ = false;
    bool playing_ = true;
    // The first-run hint is up until the first thing done in the view (QSettings
    // remembers that it went).
    bool hintShown_ = false;
    // Export Image renders on a worker while a nested event loop keeps the window drawn.
    bool exporting_ = false;
};

} // namespace pf
