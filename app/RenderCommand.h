#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold render ...`: screenshots and image sequences through OSMesa.
int runRender(const QStringList& arguments);

} // namespace pf::cli
