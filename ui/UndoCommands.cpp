#include "UndoCommands.h"

#include "EditSession.h"
#include "SimulationThread.h"

#include <QCoreApplication>

namespace pf {

StrokeCommand::StrokeCommand(SimulationThread* sim, int stroke, int events, int kind)
    : sim_(sim), stroke_(stroke) {
    // Each text spelled out at its call, where lupdate finds it.
    switch (static_cast<EditSession::StrokeKind>(kind)) {
    case EditSession::StrokeKind::Push:
        setText(QCoreApplication::translate("UndoCommands", "Push (%n break(s) or fold(s))",
                                            nullptr, events));
        break;
    case EditSession::StrokeKind::Grab:
        setText(QCoreApplication::translate("UndoCommands", "Grab (%n break(s) or fold(s))",
                                            nullptr, events));
        break;
    case EditSession::StrokeKind::Pin:
        setText(QCoreApplication::translate("UndoCommands", "Pin %n vertex(es)", nullptr, events));
        break;
    case EditSession::StrokeKind::Unpin:
        setText(
            QCoreApplication::translate("UndoCommands", "Unpin %n vertex(es)", nullptr, events));
        break;
    case EditSession::StrokeKind::Settle:
        setText(QCoreApplication::translate("UndoCommands", "Settle"));
        break;
    case EditSession::StrokeKind::Reset:
        setText(QCoreApplication::translate("UndoCommands", "Reset"));
        break;
    case EditSession::StrokeKind::Fold:
        setText(QCoreApplication::translate("UndoCommands", "Fold (%n break(s) or fold(s))",
                                            nullptr, events));
        break;
    }
}

void StrokeCommand::undo() {
    sim_->undoStroke(stroke_);
}

void StrokeCommand::redo() {
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
