#pragma once

#include "World.h"

#include <QCommandLineParser>

namespace pf::cli {

// Options of every command that starts from a sheet: where it comes from
// (--scene with --seed and --resolution, or --load) and the parameter overrides
// (--phi, --psi, --sigma, --integrator, --iterations, --dt).
void addWorldOptions(QCommandLineParser& parser);

// Builds the World those options describe. Throws UsageError with a one-line
// message for bad values or a bad file.
World worldFromOptions(const QCommandLineParser& parser);

// The files those options read (the --load sheet, if any): no output of the same
// command may be one of them.
QStringList worldInputs(const QCommandLineParser& parser);

} // namespace pf::cli
