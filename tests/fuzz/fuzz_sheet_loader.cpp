// libFuzzer target for the .paper loader: any input must give either a valid World
// or an error message, without crashing, hanging or allocating without bound.
#include "SheetFile.h"
#include "SheetValidation.h"
#include "Simulation.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes =
        QByteArray::fromRawData(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    pf::WorldLoad load = pf::decodeWorld(bytes);
    if (load.world) {
        // Whatever the loader accepts must be a valid sheet that can be stepped.
        if (!pf::validateSheet(load.world->sheet).empty()) std::abort();
        pf::Simulation sim(std::move(*load.world));
        sim.step();
    } else if (load.error.isEmpty()) {
        std::abort();
    }
    return 0;
}
