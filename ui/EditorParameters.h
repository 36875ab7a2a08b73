#pragma once

#include "Params.h"

#include <QObject>
#include <functional>

class QUndoStack;

namespace pf {

// A user's edit of the parameters: what it does to them.
using ParamChange = std::function<void(SimParams&)>;

// The editor's parameters, held here and nowhere else in the window. The panels show them
// and turn a user's edit into a change here; every change is an undo step. σ is a look:
// a change of σ alone goes to the renderer, never to the simulation.
class EditorParameters : public QObject {
    Q_OBJECT

  public:
    explicit EditorParameters(QUndoStack* undo, QObject* parent = nullptr);

    const SimParams& params() const { return params_; }

    // A user's edit, named `what` in the history. Consecutive edits of the same parameter
    // with the same `drag` number (one slider drag) are one undo step.
    void edit(const QString& what, int drag, const ParamChange& change);
    // All of them at once, without an undo step, for a new or opened sheet: the
    // simulation has them already (in its new World), so only the panels and σ hear.
    void set(const SimParams& params);

  signals:
    // Every change: what the panels show.
    void changed(const pf::SimParams& params);
    // A change of anything the simulation uses (σ is not).
    void simulationChanged(const pf::SimParams& params);
    void sigmaChanged(double sigma);

  private:
    void apply(const SimParams& params);

    QUndoStack* undo_;
    SimParams params_;
};

} // namespace pf
