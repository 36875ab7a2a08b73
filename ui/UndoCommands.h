#pragma once

#include "Params.h"

#include <QUndoCommand>
#include <functional>

namespace pf {

class SimulationThread;

// One of EditSession's undo steps: a push or grab stroke, a pin, or a Settle. It has
// already happened when pushed, so the first redo does nothing; undo recovers the
// stroke's broken edges in reverse order (§4.2) and gives back the sheet from before
// it, and redo breaks the same edges again.
class StrokeCommand : public QUndoCommand {
  public:
    // `kind` is an EditSession::StrokeKind; `events` the breaks and hinges it made, or
    // for a pin the vertices.
    StrokeCommand(SimulationThread* sim, int stroke, int events, int kind);
    void undo() override;
    void redo() override;

  private:
    SimulationThread* sim_;
    int stroke_;
    bool done_ = true;
};

// A parameter change. Consecutive edits of the same parameter within one slider
// drag merge into one step.
class ParameterCommand : public QUndoCommand {
  public:
    using Apply = std::function<void(const SimParams&)>;
    ParameterCommand(const SimParams& before, const SimParams& after, const QString& what, int drag,
                     Apply apply);
    void undo() override;
    void redo() override;
    int id() const override { return 1; }
    bool mergeWith(const QUndoCommand* other) override;

  private:
    SimParams before_, after_;
    QString what_;
    int drag_;
    Apply apply_;
};

} // namespace pf
