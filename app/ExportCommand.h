#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold export ...`: writes the subdivided surface as OBJ, PLY or GLB.
int runExport(const QStringList& arguments);

} // namespace pf::cli
