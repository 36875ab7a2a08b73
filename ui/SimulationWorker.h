#pragma once

#include "EditSession.h"

#include <QObject>
#include <QTimer>
#include <vector>

namespace pf {

class SimulationThread;

// Owns the Simulation; lives on the simulation thread. Every slot runs there,
// between frames, so commands never interleave with a step.
class SimulationWorker : public QObject {
    Q_OBJECT

  public:
    SimulationWorker(World world, SimulationThread* owner);
    ~SimulationWorker() override;

    static constexpr double kFrameSeconds = 1.0 / 60.0;

    void start();
    void setPlaying(bool playing);
    void stepOnce();
    void setParams(const SimParams& params);
    void replaceWorld(const World& world);
    void setTool(const Vec3& target, double radius, bool visible, bool pressed);
    void undoStroke(int stroke);
    void redoStroke(int stroke);
    void copyWorld(quint64 requestId);
    void copyRecording(quint64 requestId);

    // Applies every command the GUI queued (SimulationThread::post).
    void runCommands();

  private:
    void frame();
    void advance(int steps);
    void publish(double stepSeconds);

    EditSession session_;
    SimulationThread* owner_;
    QTimer timer_;
    bool playing_ = true;
};

} // namespace pf
