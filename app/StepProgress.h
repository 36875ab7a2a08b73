#pragma once

#include <QElapsedTimer>
#include <QString>
#include <QTextStream>

namespace pf::cli {

// The step a long headless run has reached, on one line of a terminal: "replaying: step
// 1200 of 14400 (8 %)", redrawn at most five times a second and once at the last step. A
// run of minutes showed nothing until it ended. Nothing is shown when standard error is
// not a terminal: a pipe's or a file's reader wants the result alone.
class StepProgress {
  public:
    StepProgress(QTextStream& err, QString doing, long long total);
    // Shows `done` if a fifth of a second has passed since the last one was shown (or the
    // progress was made), or it is the last.
    void at(long long done);
    // Ends the line, so that what follows starts on a new one. Call before any message.
    void end();
    // Whether standard error is a terminal, where the steps are shown.
    bool shown() const { return terminal_; }

  private:
    void show(long long done);
    QTextStream& err_;
    QString doing_;
    long long total_;
    bool terminal_;
    bool open_ = false; // a progress line stands unfinished
    QElapsedTimer sinceShown_;
};

} // namespace pf::cli
