#include "StepProgress.h"

#include <cstdio>
#include <unistd.h>

namespace pf::cli {

StepProgress::StepProgress(QTextStream& err, QString doing, long long total)
    : err_(err), doing_(std::move(doing)), total_(total), terminal_(isatty(fileno(stderr))) {
    sinceShown_.start(); // a run shorter than that shows its last step alone
}

void StepProgress::at(long long done) {
    if (terminal_ && (done == total_ || sinceShown_.elapsed() >= 200)) show(done);
}

void StepProgress::end() {
    if (!open_) return;
    err_ << '\n' << Qt::flush;
    open_ = false;
}

void StepProgress::show(long long done) {
    err_ << QStringLiteral("\r%1: step %2 of %3 (%4 %)")
                .arg(doing_)
                .arg(done)
                .arg(total_)
                .arg(total_ > 0 ? 100 * done / total_ : 100)
         << Qt::flush;
    open_ = true;
    sinceShown_.restart();
}

} // namespace pf::cli
