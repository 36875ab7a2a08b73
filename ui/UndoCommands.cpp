#include "UndoCommands.h"

#include "EditSession.h"
#include "SimulationThread.h"

#include <QCoreApplication>

namespace pf {

StrokeCommand::StrokeCommand(SimulationThread* sim, int stroke, int events, int kind)
    : sim_(sim), stroke_(stroke), events_(events), kind_(kind) {
    retranslate();
}

void StrokeCommand::retranslate() {
    const int events = events_;
    // Each text spelled out at its call, where lupdate finds it.
    switch (static_cast<EditSession::StrokeKind>(kind_)) {
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
    retranslate();
}

void ParameterCommand::retranslate() {
    // The panels name a parameter by a fixed key; the History says it in the user's words.
    QString name = what_;
    if (what_ == QLatin1String("phi"))
        name = QStringLiteral("φ");
    else if (what_ == QLatin1String("psi"))
        name = QStringLiteral("ψ");
    else if (what_ == QLatin1String("sigma"))
        name = QStringLiteral("σ");
    else if (what_ == QLatin1String("stiffness"))
        name = QCoreApplication::translate("UndoCommands", "stretch stiffness");
    else if (what_ == QLatin1String("bending"))
        name = QCoreApplication::translate("UndoCommands", "bending stiffness");
    else if (what_ == QLatin1String("integrator"))
        name = QCoreApplication::translate("UndoCommands", "integrator");
    else if (what_ == QLatin1String("material"))
        name = QCoreApplication::translate("UndoCommands", "paper");
    else if (what_ == QLatin1String("iterations"))
        name = QCoreApplication::translate("UndoCommands", "Jacobi sweeps");
    else if (what_ == QLatin1String("dt"))
        name = QCoreApplication::translate("UndoCommands", "steps per second");
    else if (what_ == QLatin1String("gravity"))
        name = QCoreApplication::translate("UndoCommands", "gravity outside the filter");
    setText(QCoreApplication::translate("UndoCommands", "Change %1").arg(name));
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
