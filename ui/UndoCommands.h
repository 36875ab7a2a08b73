#pragma once

#include "Params.h"

#include <QUndoCommand>
#include <functional>

namespace pf {

class SimulationThread;

// An editor step whose text the History shows: said again in a new language when the
// user switches (it is made in the language of its time).
class EditorCommand : public QUndoCommand {
  public:
    virtual void retranslate() = 0;
};

// One of EditSession's undo steps: a push or grab stroke, a pin, or a Settle. It has
// already happened when pushed, so the first redo does nothing; undo recovers the
// stroke's broken edges in reverse order (§4.2) and gives back the sheet from before
// it, and redo breaks the same edges again.
class StrokeCommand : public EditorCommand {
  public:
    // `kind` is an EditSession::StrokeKind; `events` the breaks and hinges it made, or
    // for a pin the vertices.
    StrokeCommand(SimulationThread* sim, int stroke, int events, int kind);
    void undo() override;
    void redo() override;
    void retranslate() override;
    int stroke() const { return stroke_; }
    // Named again with the breaks and hinges it holds now (EditSession::takeRecounted).
    void recount(int events);
    // The session refused this step's redo (or undo): the History's next undo (or redo) of
    // it only moves the History back, and tells the session nothing.
    void redoWasRefused() { redoRefused_ = true; }
    void undoWasRefused() { done_ = true; }

  private:
    SimulationThread* sim_;
    int stroke_, events_, kind_;
    bool done_ = true;
    bool redoRefused_ = false;
};

// A parameter change. Consecutive edits of the same parameter within one slider
// drag merge into one step.
class ParameterCommand : public EditorCommand {
  public:
    using Apply = std::function<void(const SimParams&)>;
    ParameterCommand(const SimParams& before, const SimParams& after, const QString& what, int drag,
                     Apply apply);
    void undo() override;
    void redo() override;
    int id() const override { return 1; }
    bool mergeWith(const QUndoCommand* other) override;
    void retranslate() override;

  private:
    SimParams before_, after_;
    QString what_;
    int drag_;
    Apply apply_;
};

} // namespace pf
