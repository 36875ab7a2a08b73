#include "UndoCommands.h"

#include "SimulationThread.h"

#include <QCoreApplication>

namespace pf {

PushStrokeCommand::PushStrokeCommand(SimulationThread* sim, int stroke, int events)
    : sim_(sim), stroke_(stroke) {
    setText(QCoreApplication::translate("UndoCommands", "Push (%n break(s) or fold(s))", nullptr,
                                        events));
}

PushStrokeCommand* PushStrokeCommand::settle(SimulationThread* sim, int stroke) {
    auto* c = new PushStrokeCommand(sim, stroke, 0);
    c->setText(QCoreApplication::translate("UndoCommands", "Settle"));
    return c;
}

void PushStrokeCommand::undo() {
    sim_->undoStroke(stroke_);
}

void PushStrokeCommand::redo() {
    if (done_) {
        done_ = false; // it happened live; nothing to do on the push itself
        return;
    }
    sim_->redoStroke(stroke_);
}

ParameterCommand::ParameterCommand(const SimParams& before, const SimParams& after,
                                   const QString& what, int drag, Apply apply)
    : before_(before), after_(after), what_(what), drag_(drag), apply_(std::move(apply)) {
    setText(QCoreApplication::translate("UndoCommands", "Change %1").arg(what));
}

void ParameterCommand::undo() {
    apply_(before_);
}
void ParameterCommand::redo() {
    apply_(after_);
}

bool ParameterCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const ParameterCommand*>(other);
    if (o->what_ != what_ || o->drag_ != drag_) return false;
    after_ = o->after_;
    return true;
}

} // namespace pf
