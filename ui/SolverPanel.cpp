#include "SolverPanel.h"

#include "ClampingSpinBox.h"
#include "Integrator.h"
#include "Material.h"
#include "SimulationThread.h"
#include "WorkerPool.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <cmath>

namespace pf {

SolverPanel::SolverPanel(QWidget* parent) : QWidget(parent) {
    auto* grid = new QGridLayout(this);
    integratorLabel_ = new QLabel(this);
    integrator_ = new QComboBox(this);
    for (const auto& name : integratorNames()) integrator_->addItem(QString::fromStdString(name));
    materialLabel_ = new QLabel(this);
    material_ = new QComboBox(this);
    // The preset's name is its item's data, as files and the command line say it; the
    // text shown is the name in the window's language (retranslate).
    for (const auto& name : materialNames())
        material_->addItem(QString::fromStdString(name), QString::fromStdString(name));
    iterationsLabel_ = new QLabel(this);
    iterations_ = new ClampingSpinBox(this);
    iterations_->setRange(0, 50);
    dtLabel_ = new QLabel(this);
    stepsPerSecond_ = new ClampingSpinBox(this);
    stepsPerSecond_->setRange(60, 7680);
    stepsPerSecond_->setSingleStep(60);
    gravityOutside_ = new QCheckBox(this);
    threadsLabel_ = new QLabel(this);
    threads_ = new ClampingSpinBox(this);
    threads_->setRange(1, WorkerPool::machineThreads());
    threads_->setValue(WorkerPool::machineThreads());
    stepTimeLabel_ = new QLabel(this);
    stepTime_ = new QLabel(this);
    stretchTitle_ = new QLabel(this);
    stretch_ = new QLabel(this);
    breakRateTitle_ = new QLabel(this);
    breakRate_ = new QLabel(this);
    openChart_ = new QPushButton(this);
    int r = 0;
    for (auto [label, field] :
         std::initializer_list<std::pair<QLabel*, QWidget*>>{{integratorLabel_, integrator_},
                                                             {materialLabel_, material_},
                                                             {iterationsLabel_, iterations_},
                                                             {dtLabel_, stepsPerSecond_},
                                                             {threadsLabel_, threads_}}) {
        grid->addWidget(label, r, 0);
        grid->addWidget(field, r++, 1);
    }
    grid->addWidget(gravityOutside_, r++, 0, 1, 2);
    grid->addWidget(stepTimeLabel_, r, 0);
    grid->addWidget(stepTime_, r++, 1);
    grid->addWidget(stretchTitle_, r, 0);
    grid->addWidget(stretch_, r++, 1);
    grid->addWidget(breakRateTitle_, r, 0);
    grid->addWidget(breakRate_, r++, 1);
    grid->addWidget(openChart_, r++, 0, 1, 2);
    grid->setRowStretch(r, 1);

    connect(integrator_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        enableWhatItUses(name.toStdString());
        emitEdit(QStringLiteral("integrator"),
                 [n = name.toStdString()](SimParams& p) { p.integrator = n; });
    });
    connect(material_, &QComboBox::currentIndexChanged, this, [this](int index) {
        Material m;
        if (materialPreset(material_->itemData(index).toString().toStdString(), m))
            emitEdit(QStringLiteral("material"), [m](SimParams& p) { p.material = m; });
    });
    // A number typed out of range becomes the nearest one allowed on Enter: left as it
    // was, a user's 10 steps a second was dropped without a word.
    for (QSpinBox* box : {iterations_, stepsPerSecond_, threads_}) {
        box->setKeyboardTracking(false);
        box->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
    }
    connect(threads_, &QSpinBox::valueChanged, this, [this](int n) {
        if (!updating_) emit threadsChanged(n);
    });
    connect(iterations_, &QSpinBox::valueChanged, this, [this](int k) {
        emitEdit(QStringLiteral("iterations"), [k](SimParams& p) { p.iterations = k; });
    });
    connect(stepsPerSecond_, &QSpinBox::valueChanged, this, [this](int n) {
        emitEdit(QStringLiteral("dt"), [n](SimParams& p) { p.dt = 1.0 / n; });
    });
    connect(gravityOutside_, &QCheckBox::toggled, this, [this](bool on) {
        emitEdit(QStringLiteral("gravity"), [on](SimParams& p) { p.gravityOutsideFilter = on; });
    });
    connect(openChart_, &QPushButton::clicked, this, &SolverPanel::openChartRequested);
    retranslate();
}

void SolverPanel::emitEdit(const QString& what, const ParamChange& change) {
    if (updating_) return;
    emit edited(what, --edits_, change); // each edit is its own undo step
}

// Sweeps and gravity outside the filter steer the Jacobi iteration only, the paper
// preset only xpbd: the others stay visible, with their values, but cannot be edited.
void SolverPanel::enableWhatItUses(const std::string& integrator) {
    const bool jacobi = integrator == "jacobi" || integrator == "jacobi-scalar";
    iterations_->setEnabled(jacobi);
    gravityOutside_->setEnabled(jacobi);
    material_->setEnabled(integrator == "xpbd");
}

void SolverPanel::showParams(const SimParams& params) {
    updating_ = true;
    integrator_->setCurrentText(QString::fromStdString(params.integrator));
    enableWhatItUses(params.integrator);
    material_->setCurrentIndex(material_->findData(QString::fromStdString(params.material.name)));
    iterations_->setValue(params.iterations);
    stepsPerSecond_->setValue(static_cast<int>(std::lround(1.0 / params.dt)));
    gravityOutside_->setChecked(params.gravityOutsideFilter);
    updating_ = false;
}

void SolverPanel::showThreads(int threads) {
    updating_ = true;
    threads_->setValue(threads);
    updating_ = false;
}

void SolverPanel::showStatus(const SimulationStatus& status) {
    stepTime_->setText(status.stepSeconds > 0.0
                           ? tr("%1 µs").arg(status.stepSeconds * 1e6, 0, 'f', 0)
                           : QStringLiteral("–"));
    // In the language's own digits (a decimal comma in German), as the spin boxes are.
    const QLocale locale;
    stretch_->setText(tr("max %1 %, RMS %2 %")
                          .arg(locale.toString(100.0 * status.maxStretch, 'f', 2),
                               locale.toString(100.0 * status.rmsStretch, 'f', 3)));
    breakRate_->setText(tr("%n per second", nullptr, status.breaksLastSecond));
}

void SolverPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

QString SolverPanel::paperName(const QString& preset) {
    if (preset == QLatin1String("tissue")) return tr("tissue");
    if (preset == QLatin1String("office")) return tr("office");
    if (preset == QLatin1String("card")) return tr("card");
    return preset;
}

void SolverPanel::retranslate() {
    integratorLabel_->setText(tr("Integrator"));
    integrator_->setToolTip(tr("jacobi: the paper's approximate implicit step (Eq. 6); "
                               "jacobi-scalar: the same with k·I blocks; symplectic: explicit; "
                               "backward-euler: the exact implicit step (slow, the reference); "
                               "xpbd: paper from its physical constants (docs/material.md)."));
    materialLabel_->setText(tr("Paper"));
    for (int i = 0; i < material_->count(); ++i)
        material_->setItemText(i, paperName(material_->itemData(i).toString()));
    material_->setToolTip(tr("The paper's weight, stretch and bending stiffness and friction, "
                             "used by the xpbd integrator: tissue 20 g/m², office 80 g/m², "
                             "card 250 g/m²."));
    iterationsLabel_->setText(tr("Jacobi sweeps"));
    dtLabel_->setText(tr("Steps per second"));
    stepsPerSecond_->setToolTip(
        tr("How many steps one simulated second takes (the step h = 1/N s). More steps are "
           "more accurate and cost more: the sheet moves in real time while the computer "
           "can take them that fast. The paper's behaviour is checked at 240 ('paperfold "
           "fidelity')."));
    gravityOutside_->setText(tr("Gravity outside the implicit filter"));
    gravityOutside_->setToolTip(tr("Start the Jacobi iteration at Δv = h·g. The paper's step "
                                   "divides gravity by W, so a hanging sheet falls at a fraction "
                                   "of g; this keeps free fall exact at the same stability."));
    threadsLabel_->setText(tr("Cores used"));
    threads_->setToolTip(tr("How many of this computer's %n cores step the sheet. The sheet "
                            "moves the same, to the last bit, on any number; by default one core "
                            "is left to draw the view.",
                            nullptr, WorkerPool::machineThreads()));
    stepTimeLabel_->setText(tr("Step time"));
    stretchTitle_->setText(tr("Stretch"));
    stretch_->setToolTip(tr("max(l/l0 - 1, 0) over the uncreased structural springs, live: how "
                            "far the paper is pulled longer (edges that paper bending between "
                            "two vertices shortens do not count)"));
    breakRateTitle_->setText(tr("Breaks"));
    breakRate_->setToolTip(tr("Breaks in the last second of simulated time: paper breaks "
                              "while it is loaded further, and stops when the load stops"));
    openChart_->setText(tr("Open Latest Chart…"));
    openChart_->setToolTip(
        tr("Show the newest speed–accuracy chart written by 'paperfold bench'."));
}

} // namespace pf
