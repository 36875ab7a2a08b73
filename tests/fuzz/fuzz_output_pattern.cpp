// libFuzzer target for the output-name pattern (render --output frame_%04d.png): any
// text must be refused with a message or give names with no '%' left in them, so no
// user text can ever act as a format.
#include "OutputPattern.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QString text =
        QString::fromUtf8(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const auto pattern = pf::OutputPattern::parse(text, &error);
    if (!pattern) {
        if (error.isEmpty()) std::abort();
        return 0;
    }
    for (long long frame : {0LL, 7LL, 123456789LL}) {
        const QString name = pattern->path(frame);
        if (name.contains(QLatin1Char('%'))) std::abort();
        if (!pattern->hasField() && name != text) std::abort();
    }
    if (pattern->hasField() && pattern->path(1) == pattern->path(2)) std::abort();
    return 0;
}
