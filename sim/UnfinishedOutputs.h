#pragma once

#include <QByteArray>

namespace pf {

// The temporary files being written, so that a signal that ends the process (Ctrl+C,
// kill) removes them: a write stopped that way left a hidden ".name.pid.n.tmp" beside
// the file it was to replace (121 MB once). The target itself is never touched, as the
// write renames over it only when it is whole.

// While it lives, `path` is one of them.
class UnfinishedOutput {
  public:
    explicit UnfinishedOutput(const QByteArray& path);
    ~UnfinishedOutput();
    UnfinishedOutput(const UnfinishedOutput&) = delete;
    UnfinishedOutput& operator=(const UnfinishedOutput&) = delete;

  private:
    int slot_ = -1; // -1: not registered (too many at once, or too long a name)
};

// On SIGINT, SIGTERM, SIGHUP and SIGQUIT (those not ignored when it is called), removes
// the temporary files being written, then ends the process as the signal would have.
void removeUnfinishedOutputsOnSignals();

} // namespace pf
