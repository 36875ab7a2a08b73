#pragma once

#include "Camera.h"
#include "Params.h"
#include "Picking.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"
#include "World.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QMessageBox>
#include <functional>
#include <memory>

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QToolBar;
class QUndoStack;
class QUndoView;

namespace pf {

struct EditLog;
class ParameterPanel;
class SolverPanel;
class SimulationThread;
class Viewport;
class ViewportInput;

// The editor: viewport, parameter panel, undo history, menus, toolbar, status bar.
// It only talks to the simulation through SimulationThread.
class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Hooks the tests replace; by default they show dialogs.
    enum class FileDialog { Open, Save, ExportImage, ExportMesh, SaveRecording };
    std::function<QString(FileDialog)> chooseFile;
    std::function<void(const QString&)> showError;
    std::function<QMessageBox::StandardButton()> askToSave;
    std::function<QSize()> chooseImageSize;

    // Actions, for tests and the toolbar.
    QAction* action(const char* name) const;

    SimulationThread* simulation() const { return sim_.get(); }
    Viewport* viewport() const { return viewport_; }
    ParameterPanel* panel() const { return panel_; }
    SolverPanel* solverPanel() const { return solver_; }
    // Where Open Latest Chart looks for bench_*.png (the folder `paperfold bench` wrote).
    QString chartFolder;
    // The chart it showed last (tests read it).
    QString lastChart() const { return lastChart_; }
    QUndoStack* undoStack() const { return undo_; }
    const SimParams& params() const { return params_; }
    QString currentFile() const { return file_; }
    bool isModified() const;
    // The last tool pose sent to the simulation (target centre, radius, pressed).
    Vec3 toolTarget() const;
    bool toolPressed() const;

    bool openFile(const QString& path);
    bool saveFile(const QString& path);
    void newScene(const QString& scene);
    // Switches the interface language ("" follows the system, else "ko", "ja", "de", "en").
    static bool installLanguage(const QString& code);

  protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    void createActions();
    void createMenus();
    void createDocks();
    void retranslate();
    void onSnapshot();
    void applyParams(const SimParams& params);
    void onParamsEdited(const SimParams& params, const QString& what, int drag);
    void updateTitle();
    void updateRecentMenu();
    void addRecent(const QString& path);
    bool maybeSave();
    std::shared_ptr<const World> fetchWorld();
    std::shared_ptr<const EditLog> fetchRecording();
    template <typename T, typename Reply, typename Request>
    std::shared_ptr<const T> awaitReply(Reply reply, Request request);
    void saveRecording(const QString& path);
    void exportImage();
    void exportMesh();
    void showHelp();
    void openLatestChart();
    World sceneWorld(const QString& scene) const;

    std::unique_ptr<SimulationThread> sim_;
    Viewport* viewport_ = nullptr;
    ViewportInput* input_ = nullptr;
    ParameterPanel* panel_ = nullptr;
    SolverPanel* solver_ = nullptr;
    QString lastChart_;
    QUndoStack* undo_ = nullptr;
    QUndoView* undoView_ = nullptr;
    QDockWidget *panelDock_ = nullptr, *historyDock_ = nullptr, *solverDock_ = nullptr;
    QToolBar* toolBar_ = nullptr;
    QMenu *fileMenu_ = nullptr, *newMenu_ = nullptr, *recentMenu_ = nullptr, *editMenu_ = nullptr,
          *viewMenu_ = nullptr, *overlayMenu_ = nullptr, *languageMenu_ = nullptr,
          *simMenu_ = nullptr, *helpMenu_ = nullptr;
    QLabel *fpsLabel_ = nullptr, *stepLabel_ = nullptr, *countsLabel_ = nullptr;
    QActionGroup* languageGroup_ = nullptr;

    SimParams params_;
    QString scene_ = QStringLiteral("press");
    QString file_;
    std::int64_t savedStep_ = 0;
    std::int64_t lastStep_ = 0;
    bool firstSnapshot_ = true;
    // Set when the simulation replaced its World (New, Open, Reset): the next frame
    // drawn hands the freed heap back to the system.
    bool releasePending_ = false;
    bool playing_ = true;
    QElapsedTimer fpsClock_;
    int framesSinceFps_ = 0;
    double fps_ = 0.0;
    quint64 nextRequest_ = 1;
};

} // namespace pf
