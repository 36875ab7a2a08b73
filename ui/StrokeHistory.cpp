#include "StrokeHistory.h"

#include "SimulationThread.h"
#include "UndoCommands.h"

#include <QUndoStack>

namespace pf {

StrokeHistory::StrokeHistory(SimulationThread* simulation, QUndoStack* stack, QObject* parent)
    : QObject(parent), stack_(stack) {
    connect(simulation, &SimulationThread::strokeRecounted, this, &StrokeHistory::recount);
    connect(simulation, &SimulationThread::strokeUndoRefused, this, &StrokeHistory::undoRefused);
    connect(simulation, &SimulationThread::strokeRedoRefused, this, &StrokeHistory::redoRefused);
}

StrokeHistory::Step StrokeHistory::stepOf(int stroke) const {
    for (int i = stack_->count() - 1; i >= 0; --i) {
        // (The stack hands its steps out const; their names and refusals are theirs.)
        auto* command = dynamic_cast<StrokeCommand*>(const_cast<QUndoCommand*>(stack_->command(i)));
        if (command && command->stroke() == stroke) return {command, i};
    }
    return {};
}

void StrokeHistory::recount(int stroke, int events) {
    // A push that broke 12 edges was named "Push (12 breaks or hinges)" for good, while its
    // undo also took what the sheet broke settling after it.
    const Step step = stepOf(stroke);
    if (!step.command) return;
    step.command->recount(events);
    emit renamed();
    // The Edit menu's "Undo Push (…)" reads the stack's text only when the stack says it
    // changed, which it says at a move of its index alone.
    if (step.index == stack_->index() - 1) emit stack_->undoTextChanged(stack_->undoText());
    if (step.index == stack_->index()) emit stack_->redoTextChanged(stack_->redoText());
}

void StrokeHistory::undoRefused(int stroke) {
    const Step step = stepOf(stroke);
    if (!step.command) return;
    // Stepped back only while it is the step the click undid: past it, the History has
    // moved on since (several steps at one click of the History), and stepping back would
    // skip what the later ones asked the session. Shown undone, its next redo tells the
    // session nothing, as it still has it done.
    if (stack_->index() <= step.index) step.command->undoWasRefused();
    if (stack_->index() == step.index) stack_->redo();
    emit said(tr("Could not undo “%1”: the paper is no longer as this step left it.")
                  .arg(step.command->text()));
}

void StrokeHistory::redoRefused(int stroke) {
    const Step step = stepOf(stroke);
    if (!step.command) return;
    if (stack_->index() > step.index) step.command->redoWasRefused();
    if (stack_->index() == step.index + 1) stack_->undo();
    emit said(tr("Could not redo “%1”: the paper is no longer as this step found it.")
                  .arg(step.command->text()));
}

} // namespace pf
