#pragma once

#include <QObject>
#include <QString>

class QUndoStack;

namespace pf {

class SimulationThread;
class StrokeCommand;

// Keeps the History's strokes (StrokeCommand) in step with the session's: names a
// stroke again when its count of breaks and hinges changes (EditSession::takeRecounted),
// and steps the History back when the session refuses an undo or a redo. The History
// moves at the click, before the session answers; a user's showed a push done whose
// redo had been refused, and his next Undo of it took back the steps before it.
class StrokeHistory : public QObject {
    Q_OBJECT

  public:
    StrokeHistory(SimulationThread* simulation, QUndoStack* stack, QObject* parent = nullptr);

  signals:
    void renamed();                    // a step's text changed: the History view redraws
    void said(const QString& message); // for the status bar

  private:
    // The History's step for the session's stroke, and where it stands in the stack.
    struct Step {
        StrokeCommand* command = nullptr;
        int index = -1;
    };
    Step stepOf(int stroke) const;
    void recount(int stroke, int events);
    void undoRefused(int stroke);
    void redoRefused(int stroke);

    QUndoStack* stack_;
};

} // namespace pf
