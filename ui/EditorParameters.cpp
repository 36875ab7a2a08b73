#include "EditorParameters.h"

#include "UndoCommands.h"

#include <QUndoStack>

namespace pf {

namespace {

bool sameForSimulation(SimParams a, const SimParams& b) {
    a.sigma = b.sigma;
    return a == b;
}

} // namespace

EditorParameters::EditorParameters(QUndoStack* undo, QObject* parent)
    : QObject(parent), undo_(undo) {}

void EditorParameters::edit(const QString& what, int drag, const ParamChange& change) {
    SimParams after = params_;
    change(after);
    if (after == params_) return;
    // The command applies `after` at once (its first redo).
    undo_->push(
        new ParameterCommand(params_, after, what, drag, [this](const SimParams& p) { apply(p); }));
}

void EditorParameters::set(const SimParams& params) {
    params_ = params;
    emit sigmaChanged(params.sigma);
    emit changed(params);
}

void EditorParameters::apply(const SimParams& params) {
    const SimParams before = params_;
    params_ = params;
    if (!sameForSimulation(before, params)) emit simulationChanged(params);
    if (before.sigma != params.sigma) emit sigmaChanged(params.sigma);
    emit changed(params);
}

} // namespace pf
