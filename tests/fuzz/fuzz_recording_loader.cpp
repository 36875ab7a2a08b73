// libFuzzer target for the .paperrec loader: any input must give either a recording
// whose start is a valid sheet and whose commands replay without crashing, or an error
// message; never a crash, a hang or an allocation without bound.
#include "RecordingFile.h"
#include "SheetValidation.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes =
        QByteArray::fromRawData(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const pf::RecordingLoad load = pf::decodeRecording(bytes);
    if (!load.log) {
        if (load.error.isEmpty()) std::abort();
        return 0;
    }
    if (!pf::validateSheet(load.log->start.sheet).empty()) std::abort();
    // A recording may be long; a fuzzer input replays only when it is short.
    if (load.log->endStep - load.log->start.stepCount <= 32) {
        pf::EditSession session(*load.log);
        pf::replay(*load.log, session);
        if (!pf::validateSheet(session.world().sheet).empty()) std::abort();
    }
    return 0;
}
