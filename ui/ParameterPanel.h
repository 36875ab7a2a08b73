#pragma once

#include "EditorParameters.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace pf {

// The knobs an artist turns: φ, ψ, σ and the tool radius up front; stiffness and
// the sheet's size and resolution under Advanced. The solver has its own dock.
class ParameterPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ParameterPanel(QWidget* parent = nullptr);

    // Shows `params` without emitting anything.
    void showParams(const SimParams& params);
    double toolRadius() const;
    void setToolRadius(double metres);
    int resolution() const;
    double sheetWidth() const;  // metres
    double sheetLength() const; // metres
    // The Fold tool's choices: the angle the flap ends at, and the kind of fold.
    double foldAngle() const; // radians
    bool foldMountain() const;

    // The widgets, for tests that drive them.
    QSlider* phiSlider() const { return phi_.slider; }
    QSlider* psiSlider() const { return psi_.slider; }
    QSlider* sigmaSlider() const { return sigma_.slider; }
    QDoubleSpinBox* phiSpin() const { return phi_.spin; }
    QDoubleSpinBox* pushDepthSpin() const { return depth_.spin; }
    QComboBox* foldKindBox() const { return foldKind_; }
    QSpinBox* foldAngleSpin() const { return foldAngle_; }

  signals:
    // A user edit of the parameter `what`. `drag` numbers a slider drag: edits with the
    // same drag number belong to one gesture (and one undo step).
    void edited(const QString& what, int drag, const pf::ParamChange& change);
    void toolRadiusChanged(double metres);
    void pushDepthChanged(double shareOfRadius);

  protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void fitNote();
    struct SliderRow {
        QLabel* label = nullptr;
        QSlider* slider = nullptr;
        QDoubleSpinBox* spin = nullptr;
        double scale = 100.0; // slider units per value unit
    };
    SliderRow addSliderRow(QGridLayout* grid, int row, double min, double max, int decimals,
                           double scale);
    void retranslate();
    bool eventFilter(QObject* watched, QEvent* event) override;
    void emitEdit(const QString& what, const ParamChange& change);
    void rowEdited(int row, double value);

    SliderRow phi_, psi_, sigma_, radius_, depth_;
    QLabel* foldLabel_ = nullptr;
    QComboBox* foldKind_ = nullptr;
    QSpinBox* foldAngle_ = nullptr;
    QGroupBox* advanced_ = nullptr;
    QLabel *stiffnessLabel_ = nullptr, *bendingLabel_ = nullptr, *resolutionLabel_ = nullptr,
           *sizeLabel_ = nullptr;
    QDoubleSpinBox* stiffness_ = nullptr;
    QDoubleSpinBox* bending_ = nullptr;
    QSpinBox* resolution_ = nullptr;
    QDoubleSpinBox* width_ = nullptr;
    QDoubleSpinBox* length_ = nullptr;
    QLabel* sheetNote_ = nullptr;
    int drag_ = 0;
    bool sliderDown_ = false;
    // The mouse is held down on a slider, on its handle or its groove: one gesture,
    // however many page steps the held button repeats.
    bool mouseOnSlider_ = false;
    bool updating_ = false;
};

} // namespace pf
