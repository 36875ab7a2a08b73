#include "ParameterPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

namespace pf {

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* grid = new QGridLayout;
    layout->addLayout(grid);
    phi_ = addSliderRow(grid, 0, 0.0, 1.0, 2, 100.0);
    psi_ = addSliderRow(grid, 1, 0.0, 1.0, 2, 100.0);
    sigma_ = addSliderRow(grid, 2, 0.0, 4.0, 2, 100.0);  // the CLI's and the file's range
    radius_ = addSliderRow(grid, 3, 1.0, 10.0, 1, 10.0); // centimetres
    depth_ = addSliderRow(grid, 4, 10.0, 100.0, 0, 1.0); // per cent of the radius
    depth_.spin->setValue(60.0);
    depth_.slider->setValue(60);
    foldLabel_ = new QLabel(this);
    foldKind_ = new QComboBox(this);
    foldKind_->addItems({QString(), QString()}); // Valley, Mountain (retranslate)
    foldAngle_ = new QSpinBox(this);
    foldAngle_->setRange(1, 180);
    foldAngle_->setValue(180);
    foldAngle_->setSuffix(QStringLiteral("°"));
    grid->addWidget(foldLabel_, 5, 0);
    grid->addWidget(foldKind_, 5, 1);
    grid->addWidget(foldAngle_, 5, 2);

    advanced_ = new QGroupBox(this);
    advanced_->setCheckable(true);
    advanced_->setChecked(false);
    auto* adv = new QGridLayout(advanced_);
    stiffnessLabel_ = new QLabel(advanced_);
    stiffness_ = new QDoubleSpinBox(advanced_);
    stiffness_->setRange(1.0, 1e5);
    stiffness_->setDecimals(0);
    stiffness_->setSuffix(QStringLiteral(" N/m"));
    bendingLabel_ = new QLabel(advanced_);
    bending_ = new QDoubleSpinBox(advanced_);
    bending_->setRange(0.0, 1e4);
    bending_->setDecimals(1);
    bending_->setSuffix(QStringLiteral(" N/m"));
    resolutionLabel_ = new QLabel(advanced_);
    resolution_ = new QSpinBox(advanced_);
    resolution_->setRange(3, 60);
    resolution_->setValue(19);
    sizeLabel_ = new QLabel(advanced_);
    width_ = new QDoubleSpinBox(advanced_);
    length_ = new QDoubleSpinBox(advanced_);
    for (QDoubleSpinBox* b : {width_, length_}) {
        b->setRange(5.0, 100.0);
        b->setDecimals(1);
        b->setSuffix(QStringLiteral(" cm"));
    }
    width_->setValue(21.0);
    length_->setValue(29.7);
    sheetNote_ = new QLabel(advanced_);
    sheetNote_->setWordWrap(true);
    int r = 0;
    for (auto [label, field] :
         std::initializer_list<std::pair<QLabel*, QWidget*>>{{stiffnessLabel_, stiffness_},
                                                             {bendingLabel_, bending_},
                                                             {resolutionLabel_, resolution_}}) {
        adv->addWidget(label, r, 0);
        adv->addWidget(field, r++, 1, 1, 2);
    }
    adv->addWidget(sizeLabel_, r, 0);
    adv->addWidget(width_, r, 1);
    adv->addWidget(length_, r++, 2);
    adv->addWidget(sheetNote_, r, 0, 1, 3);
    for (QWidget* w : advanced_->findChildren<QWidget*>()) w->setVisible(false);
    connect(advanced_, &QGroupBox::toggled, this, [this](bool on) {
        for (QWidget* w : advanced_->findChildren<QWidget*>()) w->setVisible(on);
        fitNote();
    });
    layout->addWidget(advanced_);
    layout->addStretch();
    // Typing "0.1" commits once, on Enter or leaving the box, not at every keystroke
    // (which reformatted the text under the cursor and made each key an undo step).
    for (QAbstractSpinBox* box : findChildren<QAbstractSpinBox*>()) box->setKeyboardTracking(false);

    connect(stiffness_, &QDoubleSpinBox::valueChanged, this, [this](double k) {
        emitEdit(QStringLiteral("stiffness"), [k](SimParams& p) {
            p.stiffness[static_cast<int>(SpringKind::Structural)] = k;
            p.stiffness[static_cast<int>(SpringKind::Crease)] = k;
        });
    });
    connect(bending_, &QDoubleSpinBox::valueChanged, this, [this](double k) {
        emitEdit(QStringLiteral("bending"), [k](SimParams& p) {
            p.stiffness[static_cast<int>(SpringKind::Bending)] = k;
            p.stiffness[static_cast<int>(SpringKind::Hinge)] = k;
        });
    });
    retranslate();
}

ParameterPanel::SliderRow ParameterPanel::addSliderRow(QGridLayout* grid, int row, double min,
                                                       double max, int decimals, double scale) {
    SliderRow r;
    r.scale = scale;
    r.label = new QLabel(this);
    r.slider = new QSlider(Qt::Horizontal, this);
    r.slider->setRange(static_cast<int>(std::lround(min * scale)),
                       static_cast<int>(std::lround(max * scale)));
    r.spin = new QDoubleSpinBox(this);
    r.spin->setRange(min, max);
    r.spin->setDecimals(decimals);
    r.spin->setSingleStep(1.0 / scale);
    grid->addWidget(r.label, row, 0);
    grid->addWidget(r.slider, row, 1);
    grid->addWidget(r.spin, row, 2);
    const int index = row;
    connect(r.slider, &QSlider::sliderPressed, this, [this] {
        sliderDown_ = true;
        ++drag_;
    });
    connect(r.slider, &QSlider::sliderReleased, this, [this] { sliderDown_ = false; });
    r.slider->installEventFilter(this);
    connect(r.slider, &QSlider::valueChanged, this, [this, r, index](int v) {
        if (updating_) return;
        updating_ = true;
        r.spin->setValue(v / r.scale);
        updating_ = false;
        // A key on the slider is a gesture of its own; so is a click, but a button held on
        // the groove repeats its page step, which a user took for one change and found
        // as two or more in the History.
        if (!sliderDown_ && !mouseOnSlider_) ++drag_;
        rowEdited(index, v / r.scale);
    });
    connect(r.spin, &QDoubleSpinBox::valueChanged, this, [this, r, index](double v) {
        if (updating_) return;
        updating_ = true;
        r.slider->setValue(static_cast<int>(std::lround(v * r.scale)));
        updating_ = false;
        ++drag_;
        rowEdited(index, v);
    });
    return r;
}

bool ParameterPanel::eventFilter(QObject* watched, QEvent* event) {
    if (qobject_cast<QSlider*>(watched)) {
        // (The second press of a double click comes as a double click, and repeats too.)
        if (event->type() == QEvent::MouseButtonPress ||
            event->type() == QEvent::MouseButtonDblClick) {
            mouseOnSlider_ = true;
            ++drag_;
        } else if (event->type() == QEvent::MouseButtonRelease) {
            mouseOnSlider_ = false;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ParameterPanel::rowEdited(int row, double value) {
    switch (row) {
    case 0:
        emitEdit(QStringLiteral("phi"), [value](SimParams& p) { p.phi = value; });
        break;
    case 1:
        emitEdit(QStringLiteral("psi"), [value](SimParams& p) { p.psi = value; });
        break;
    case 2:
        emitEdit(QStringLiteral("sigma"), [value](SimParams& p) { p.sigma = value; });
        break;
    case 3:
        emit toolRadiusChanged(value / 100.0); // the row is in centimetres
        break;
    default:
        emit pushDepthChanged(value / 100.0); // in per cent
        break;
    }
}

void ParameterPanel::emitEdit(const QString& what, const ParamChange& change) {
    if (updating_) return;
    emit edited(what, drag_, change);
}

void ParameterPanel::showParams(const SimParams& params) {
    updating_ = true;
    phi_.spin->setValue(params.phi);
    phi_.slider->setValue(static_cast<int>(std::lround(params.phi * phi_.scale)));
    psi_.spin->setValue(params.psi);
    psi_.slider->setValue(static_cast<int>(std::lround(params.psi * psi_.scale)));
    sigma_.spin->setValue(params.sigma);
    sigma_.slider->setValue(static_cast<int>(std::lround(params.sigma * sigma_.scale)));
    stiffness_->setValue(params.stiffnessOf(SpringKind::Structural));
    bending_->setValue(params.stiffnessOf(SpringKind::Bending));
    updating_ = false;
}

double ParameterPanel::toolRadius() const {
    return radius_.spin->value() / 100.0;
}

void ParameterPanel::setToolRadius(double metres) {
    updating_ = true;
    radius_.spin->setValue(metres * 100.0);
    radius_.slider->setValue(static_cast<int>(std::lround(metres * 100.0 * radius_.scale)));
    updating_ = false;
}

int ParameterPanel::resolution() const {
    return resolution_->value();
}
double ParameterPanel::sheetWidth() const {
    return width_->value() / 100.0;
}
double ParameterPanel::sheetLength() const {
    return length_->value() / 100.0;
}
double ParameterPanel::foldAngle() const {
    return foldAngle_->value() * std::numbers::pi / 180.0;
}
bool ParameterPanel::foldMountain() const {
    return foldKind_->currentIndex() == 1;
}

void ParameterPanel::fitNote() {
    // A dock sizes its widget from size hints, which for a word-wrapped label assume a
    // line wider than the dock: the note was cut off. Its minimum height is the height
    // it needs at the width it has, so the dock can only squeeze what is below.
    const int need = sheetNote_->isVisible() ? sheetNote_->heightForWidth(sheetNote_->width()) : 0;
    if (need != sheetNote_->minimumHeight()) sheetNote_->setMinimumHeight(need);
}

void ParameterPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitNote();
}

void ParameterPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ParameterPanel::retranslate() {
    phi_.label->setText(tr("φ fragility"));
    phi_.label->setToolTip(tr("Fragility φ scales the normal dot products of the break probability "
                              "(Eq. 10). Larger φ: stiffer paper that breaks only where it is "
                              "already curved; at 1 a flat region never breaks. Smaller φ: softer "
                              "paper that crumples anywhere it is compressed."));
    psi_.label->setText(tr("ψ recursive break"));
    psi_.label->setToolTip(tr("ψ sets how far a new vertex moves out of the surface when a spring "
                              "breaks (Eq. 11). At 1 the two halves keep the rest length and do "
                              "not break again at once; smaller ψ leaves them compressed, so "
                              "breaks repeat into finer crumples."));
    sigma_.label->setText(tr("σ crumple smoothing"));
    sigma_.label->setToolTip(tr("σ shapes the subdivided surface that is drawn (§4.3): 0 keeps "
                                "flat facets and sharp creases, larger values round them off. It "
                                "does not change the simulation."));
    radius_.label->setText(tr("Tool radius"));
    radius_.label->setToolTip(
        tr("Radius of the sphere you push the paper with (Ctrl+wheel in the view)."));
    radius_.spin->setSuffix(tr(" cm"));
    depth_.label->setText(tr("Push depth"));
    depth_.label->setToolTip(tr("How deep a push presses the sphere into the paper, as a share of "
                                "its radius: deeper pushes crease harder."));
    depth_.spin->setSuffix(QStringLiteral(" %"));
    foldLabel_->setText(tr("Fold"));
    foldLabel_->setToolTip(
        tr("The Fold tool (L): draw a line across the paper; the lighter side (or the side without "
           "pins) is carried round "
           "it, pressed flat, opened to this angle and let go. A valley fold turns the flap up "
           "toward you, a mountain fold away from you, under the paper."));
    foldKind_->setItemText(0, tr("Valley"));
    foldKind_->setItemText(1, tr("Mountain"));
    foldKind_->setToolTip(foldLabel_->toolTip());
    foldAngle_->setToolTip(foldLabel_->toolTip());
    for (auto* row : {&phi_, &psi_, &sigma_, &radius_, &depth_}) {
        row->slider->setToolTip(row->label->toolTip());
        row->spin->setToolTip(row->label->toolTip());
    }
    advanced_->setTitle(tr("Advanced"));
    stiffnessLabel_->setText(tr("Stretch stiffness"));
    bendingLabel_->setText(tr("Bending stiffness"));
    resolutionLabel_->setText(tr("Resolution"));
    resolution_->setToolTip(tr("Vertices along the sheet's short side."));
    sizeLabel_->setText(tr("Sheet size"));
    sheetNote_->setText(tr("Resolution and size apply to the next New or Reset."));
    fitNote();
}

} // namespace pf
