#include "UndoCommands.h"

#include "EditSession.h"
#include "SimulationThread.h"

#include <QCoreApplication>
#include <utility>

namespace pf {

namespace {

// The panels name a parameter by a fixed key; the History says it in the user's words.
QString parameterName(const QString& key) {
    static const std::pair<const char*, const char*> symbols[] = {
        {"phi", "φ"}, {"psi", "ψ"}, {"sigma", "σ"}};
    static const std::pair<const char*, const char*> words[] = {
        {"stiffness", QT_TRANSLATE_NOOP("UndoCommands", "stretch stiffness")},
        {"bending", QT_TRANSLATE_NOOP("UndoCommands", "bending stiffness")},
        {"integrator", QT_TRANSLATE_NOOP("UndoCommands", "integrator")},
        {"material", QT_TRANSLATE_NOOP("UndoCommands", "paper")},
        {"iterations", QT_TRANSLATE_NOOP("UndoCommands", "Jacobi sweeps")},
        {"dt", QT_TRANSLATE_NOOP("UndoCommands", "steps per second")},
        {"gravity", QT_TRANSLATE_NOOP("UndoCommands", "gravity outside the filter")}};
    for (const auto& [k, symbol] : symbols)
        if (key == QLatin1String(k)) return QString::fromUtf8(symbol);
    for (const auto& [k, word] : words)
        if (key == QLatin1String(k)) return QCoreApplication::translate("UndoCommands", word);
    return key;
}

} // namespace

StrokeCommand::StrokeCommand(SimulationThread* sim, int stroke, int events, int kind)
    : sim_(sim), stroke_(stroke), events_(events), kind_(kind) {
    retranslate();
}

void StrokeCommand::retranslate() {
    const int events = events_;
    // Each text spelled out at its call, where lupdate finds it.
    switch (static_cast<EditSession::StrokeKind>(kind_)) {
    case EditSession::StrokeKind::Push:
        setText(QCoreApplication::translate("UndoCommands", "Push (%n break(s) or hinge(s))",
                                            nullptr, events));
        break;
    case EditSession::StrokeKind::Grab:
        setText(QCoreApplication::translate("UndoCommands", "Grab (%n break(s) or hinge(s))",
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
        // A fold that kept its crease without a break or a hinge (card bends plastically)
        // read "Fold (0 breaks or folds)" (hinges were called folds then).
        if (events == 0)
            setText(QCoreApplication::translate("UndoCommands", "Fold"));
        else
            setText(QCoreApplication::translate("UndoCommands", "Fold (%n break(s) or hinge(s))",
                                                nullptr, events));
        break;
    }
}

void StrokeCommand::recount(int events) {
    events_ = events;
    retranslate();
}

void StrokeCommand::undo() {
    if (std::exchange(redoRefused_, false)) return; // the session never did it again
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
    setText(QCoreApplication::translate("UndoCommands", "Change %1").arg(parameterName(what_)));
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
