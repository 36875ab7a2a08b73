#pragma once

#include "PaperLook.h"

#include <QCommandLineParser>
#include <QStringList>

namespace pf::cli {

// --paper-color and --texture: the paper's look for `render`, `replay` and `export`.
void addLookOptions(QCommandLineParser& parser);

// Throws UsageError, naming the option, for a colour or texture it cannot use. A
// texture file read is appended to `inputs`, so that no output overwrites it.
PaperLook lookFromOptions(const QCommandLineParser& parser, QStringList* inputs);

} // namespace pf::cli
