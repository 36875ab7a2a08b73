#include "TestData.h"

#include "SheetFile.h"

#include <QFile>
#include <QTemporaryDir>

namespace pf::test {

std::optional<World> packedState(const char* name) {
    QFile packed(QStringLiteral(PAPERFOLD_TEST_DATA "/") + QLatin1String(name));
    if (!packed.open(QIODevice::ReadOnly)) return std::nullopt;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("state.paper"));
    QFile sheet(path);
    if (!dir.isValid() || !sheet.open(QIODevice::WriteOnly)) return std::nullopt;
    sheet.write(qUncompress(packed.readAll()));
    sheet.close();
    WorldLoad load = loadWorld(path);
    if (!load.world) qWarning("%s: %s", name, qPrintable(load.error));
    return load.world;
}

} // namespace pf::test
