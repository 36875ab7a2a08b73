#include "FidelityCommand.h"

#include "CommandLine.h"
#include "Fidelity.h"
#include "OutputFile.h"

#include <QTextStream>
#include <algorithm>
#include <cmath>

namespace pf::cli {

int runFidelity(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Check the sheet against physics: stretch in press, drape, compress, drop, "
        "crumple-cycles and push strokes, free fall in four "
        "orientations, momentum, Peirce's cantilever, Coulomb's incline, contact in press "
        "and rest. Prints one table (value, bound, pass/fail); exit 3 if a check fails."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("fidelity"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("quick"), QStringLiteral("Shorter runs, one crumple cycle (for CI).")},
        {QStringLiteral("integrator"), QStringLiteral("Integrator to check (default xpbd)."),
         QStringLiteral("name"), QStringLiteral("xpbd")},
        {QStringLiteral("material"),
         QStringLiteral("Paper: tissue, office, card (default office)."), QStringLiteral("name"),
         QStringLiteral("office")},
        {QStringLiteral("substeps"), QStringLiteral("xpbd: sub-steps per step (default 40)."),
         QStringLiteral("n")},
        {QStringLiteral("gravity-outside-filter"),
         QStringLiteral("The jacobi family: integrate gravity outside the implicit filter (the "
                        "editor's setting).")},
        {QStringLiteral("no-self-contact"),
         QStringLiteral("xpbd: let the paper's layers pass through each other.")},
        {QStringLiteral("csv"), QStringLiteral("Also write the table as CSV to this file."),
         QStringLiteral("file")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    FidelityOptions o;
    o.quick = parser.isSet(QStringLiteral("quick"));
    o.integrator = integratorOption(parser);
    refuseOptionsTheIntegratorIgnores(parser, o.integrator);
    if (!materialPreset(parser.value(QStringLiteral("material")).toStdString(), o.material))
        throw UsageError{QStringLiteral("--material: unknown material '%1' (tissue, office, card)")
                             .arg(parser.value(QStringLiteral("material")))};
    o.gravityOutsideFilter = parser.isSet(QStringLiteral("gravity-outside-filter"));
    o.selfContact = !parser.isSet(QStringLiteral("no-self-contact"));
    o.substeps =
        static_cast<int>(integerOption(parser, QStringLiteral("substeps"), 1, 1000).value_or(0));
    const QString csvPath = parser.value(QStringLiteral("csv"));
    if (!csvPath.isEmpty()) requireWritable(QStringLiteral("csv"), csvPath);

    const std::vector<FidelityRow> rows = runFidelity(o);
    QTextStream out(stdout);
    QString csv = QStringLiteral("check,measure,value,bound,relation,unit,pass\n");
    int failed = 0;
    out << QStringLiteral("fidelity of %1%2 with %3 paper%4\n")
               .arg(QString::fromStdString(o.integrator),
                    o.gravityOutsideFilter ? QStringLiteral(", gravity outside the filter")
                                           : QString(),
                    QString::fromStdString(o.material.name),
                    o.quick ? QStringLiteral(" (quick)") : QString());
    out << QStringLiteral("%1 %2 %3 %4  %5\n")
               .arg(QStringLiteral("check"), -30)
               .arg(QStringLiteral("value"), 12)
               .arg(QStringLiteral("bound"), 12)
               .arg(QStringLiteral(""), -5)
               .arg(QStringLiteral("measure"));
    for (const FidelityRow& r : rows) {
        failed += r.pass() ? 0 : 1;
        const QString unit = QString::fromStdString(r.unit);
        // (A stretch row of a run that blew up is infinite; the rest row's "never" is 1e9.)
        const QString value = std::isinf(r.value) ? QStringLiteral("blew up")
                              : r.value >= 1e8    ? QStringLiteral("never")
                                                  : QString::number(r.value, 'g', 4) + ' ' + unit;
        out << QStringLiteral("%1 %2 %3 %4  %5\n")
                   .arg(QString::fromStdString(r.check), -30)
                   .arg(value, 12)
                   .arg((r.atMost ? QStringLiteral("≤ ") : QStringLiteral("≥ ")) +
                            QString::number(r.bound, 'g', 4) + ' ' + unit,
                        12)
                   .arg(r.pass() ? QStringLiteral("pass") : QStringLiteral("FAIL"), -5)
                   .arg(QString::fromStdString(r.measure));
        QString measure = QString::fromStdString(r.measure);
        measure.replace('"', QStringLiteral("\"\""));
        csv += QStringLiteral("%1,\"%2\",%3,%4,%5,%6,%7\n")
                   .arg(QString::fromStdString(r.check), measure)
                   .arg(r.value, 0, 'g', 8)
                   .arg(r.bound, 0, 'g', 8)
                   .arg(r.atMost ? QStringLiteral("<=") : QStringLiteral(">="), unit,
                        r.pass() ? QStringLiteral("pass") : QStringLiteral("fail"));
    }
    out << QStringLiteral("%1 of %2 checks pass\n").arg(rows.size() - failed).arg(rows.size());
    out.flush();
    if (!csvPath.isEmpty()) {
        QString error;
        if (!writeOutputFile(csvPath, csv.toUtf8(), &error)) {
            QTextStream(stderr) << "paperfold: " << error << '\n';
            return 2;
        }
    }
    return failed == 0 ? 0 : 3;
}

} // namespace pf::cli
