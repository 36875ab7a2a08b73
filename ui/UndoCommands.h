#pragma once

#include "Params.h"

#include <QUndoCommand>
#include <functional>

namespace pf {

class SimulationThread;

// One push stroke, or a Settle (an undo step of the same kind in EditSession). It has
// already happened when pushed, so the first redo does nothing; undo recovers the
// stroke's broken edges in reverse order (§4.2) and gives back the sheet from before
// it, and redo breaks the same edges again.
class PushStrokeCommand : public QUndoCommand {
  public:
    PushStrokeCommand(SimulationThread* sim, int stroke, int events);
    // A Settle: nothing broken, the sheet kept as it came to rest.
    static PushStrokeCommand* settle(SimulationThread* sim, int stroke);
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
