#pragma once

#include "EditorParameters.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace pf {

struct SimulationStatus;

// The Solver dock: which integrator steps the sheet and how, what it costs and how
// far the springs stretch right now, and the latest speed–accuracy chart.
class SolverPanel : public QWidget {
    Q_OBJECT

  public:
    explicit SolverPanel(QWidget* parent = nullptr);

    void showParams(const SimParams& params); // without emitting
    void showStatus(const SimulationStatus& status);
    void showThreads(int threads); // without emitting

    QComboBox* integratorBox() const { return integrator_; }
    QComboBox* materialBox() const { return material_; }
    QSpinBox* iterationsBox() const { return iterations_; }
    QCheckBox* gravityBox() const { return gravityOutside_; }
    QSpinBox* threadsBox() const { return threads_; }
    QSpinBox* stepsPerSecondBox() const { return stepsPerSecond_; }
    QLabel* stretchLabel() const { return stretch_; }
    QLabel* breakRateLabel() const { return breakRate_; }

  signals:
    // A user edit of the parameter `what` (each its own undo step).
    void edited(const QString& what, int drag, const pf::ParamChange& change);
    void openChartRequested();
    // The user chose how many threads step the sheet.
    void threadsChanged(int threads);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslate();
    // A paper preset's name in the window's language ("office" in English).
    static QString paperName(const QString& preset);
    void emitEdit(const QString& what, const ParamChange& change);
    void enableWhatItUses(const std::string& integrator);

    int edits_ = 0;
    bool updating_ = false;
    QLabel *integratorLabel_ = nullptr, *iterationsLabel_ = nullptr, *dtLabel_ = nullptr,
           *stepTimeLabel_ = nullptr, *stretchTitle_ = nullptr;
    QComboBox* integrator_ = nullptr;
    QLabel* materialLabel_ = nullptr;
    QComboBox* material_ = nullptr;
    QSpinBox* iterations_ = nullptr;
    QSpinBox* stepsPerSecond_ = nullptr;
    QCheckBox* gravityOutside_ = nullptr;
    QLabel* threadsLabel_ = nullptr;
    QSpinBox* threads_ = nullptr;
    QLabel* stepTime_ = nullptr;
    QLabel* stretch_ = nullptr;
    QLabel *breakRateTitle_ = nullptr, *breakRate_ = nullptr;
    QPushButton* openChart_ = nullptr;
};

} // namespace pf
