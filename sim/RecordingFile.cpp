#include "RecordingFile.h"

#include "BoundedCbor.h"
#include "InputFile.h"
#include "LittleEndian.h"
#include "OutputFile.h"
#include "SheetFile.h"

#include <QCborArray>
#include <QCborMap>
#include <QCborValue>
#include <QtEndian>
#include <algorithm>
#include <cmath>

namespace pf {

namespace {

// One command: step i64, kind u8, flags u8 (1 visible, 2 pressed, 4 a mountain fold), 2
// zero bytes, argument i32 (the stroke of an undo or redo, the params entry of a change,
// the worlds entry of a reset, the folds entry of a fold), target 3 × f64, radius f64;
// little-endian.
constexpr qsizetype kCommandBytes = 48;
// A fold's line end 3 × f64, angle f64 and viewer 3 × f64, in the "folds" bytes.
constexpr qsizetype kFoldBytes = 56;

using le::put;
using le::putF64;
using le::take;
using le::takeF64;

const CborBounds& recordingBounds() {
    static const CborBounds bounds = [] {
        CborBounds b;
        for (const char* key : {"magic", "version", "start", "toolTarget", "pressed", "endStep",
                                "endState", "commands", "params", "worlds", "folds"})
            b.knownKeys.insert(QLatin1String(key));
        b.maxDepth = 3;
        b.maxValues = kMaxRecordedParams + kMaxRecordedResets + 64;
        return b;
    }();
    return bounds;
}

bool finiteWithin(double v, double limit) {
    return std::isfinite(v) && std::abs(v) <= limit;
}

} // namespace

QByteArray encodeRecording(const EditLog& log) {
    QCborMap root;
    root[QLatin1String("magic")] = QLatin1String(kRecordingMagic);
    root[QLatin1String("version")] = kRecordingVersion;
    root[QLatin1String("start")] = encodeWorld(log.start);
    QByteArray target;
    for (int k = 0; k < 3; ++k) putF64(target, log.toolTarget[k]);
    root[QLatin1String("toolTarget")] = target;
    root[QLatin1String("pressed")] = log.pressed;
    root[QLatin1String("endStep")] = static_cast<qint64>(log.endStep);
    if (log.endState)
        root[QLatin1String("endState")] =
            QStringLiteral("%1").arg(*log.endState, 16, 16, QLatin1Char('0'));
    QByteArray commands;
    commands.reserve(static_cast<qsizetype>(log.commands.size()) * kCommandBytes);
    QCborArray params, worlds;
    QByteArray folds;
    for (const EditCommand& c : log.commands) {
        std::int32_t argument = c.stroke;
        if (c.kind == EditCommand::Kind::Params) {
            argument = static_cast<std::int32_t>(params.size());
            params.append(encodeParams(*c.params));
        } else if (c.kind == EditCommand::Kind::Reset) {
            argument = static_cast<std::int32_t>(worlds.size());
            worlds.append(encodeWorld(*c.world));
        } else if (c.kind == EditCommand::Kind::Fold) {
            argument = static_cast<std::int32_t>(folds.size() / kFoldBytes);
            for (int k = 0; k < 3; ++k) putF64(folds, c.fold->to[k]);
            putF64(folds, c.fold->angle);
            for (int k = 0; k < 3; ++k) putF64(folds, c.fold->viewer[k]);
        }
        put<std::int64_t>(commands, c.step);
        put<std::uint8_t>(commands, static_cast<std::uint8_t>(c.kind));
        const bool mountain = c.fold && c.fold->mountain;
        put<std::uint8_t>(commands, (c.visible ? 1 : 0) | (c.pressed ? 2 : 0) | (mountain ? 4 : 0));
        put<std::uint16_t>(commands, 0);
        put<std::int32_t>(commands, argument);
        const Vec3 target = c.fold ? c.fold->from : c.target;
        for (int k = 0; k < 3; ++k) putF64(commands, target[k]);
        putF64(commands, c.radius);
    }
    root[QLatin1String("commands")] = commands;
    root[QLatin1String("params")] = params;
    if (!worlds.isEmpty()) root[QLatin1String("worlds")] = worlds;
    if (!folds.isEmpty()) root[QLatin1String("folds")] = folds;
    return root.toCborValue().toCbor();
}

RecordingLoad decodeRecording(const QByteArray& bytes) {
    QString error;
    const std::optional<QCborValue> parsed = parseBoundedCbor(bytes, recordingBounds(), &error);
    if (!parsed) return {std::nullopt, error};
    if (!parsed->isMap()) return {std::nullopt, QStringLiteral("not a PaperFold recording")};
    const QCborMap root = parsed->toMap();
    auto bad = [](const QString& what) { return RecordingLoad{std::nullopt, what}; };
    const QString magic = root.value(QLatin1String("magic")).toString();
    if (magic == QLatin1String(kSheetFileMagic))
        return bad(QStringLiteral("a PaperFold sheet, not a recording: open it in the editor, or "
                                  "with --load"));
    if (magic != QLatin1String(kRecordingMagic))
        return bad(QStringLiteral("not a PaperFold recording (wrong magic)"));
    const QCborValue version = root.value(QLatin1String("version"));
    if (!version.isInteger() || version.toInteger() != kRecordingVersion)
        return bad(QStringLiteral("unsupported recording version (this build reads version %1)")
                       .arg(kRecordingVersion));
    const QCborValue start = root.value(QLatin1String("start"));
    if (!start.isByteArray()) return bad(QStringLiteral("recording.start: missing"));
    WorldLoad world = decodeWorld(start.toByteArray());
    if (!world.world) return bad(QStringLiteral("recording.start: %1").arg(world.error));

    EditLog log;
    log.start = std::move(*world.world);
    const QByteArray target = root.value(QLatin1String("toolTarget")).toByteArray();
    if (target.size() != 24) return bad(QStringLiteral("recording.toolTarget: not 3 numbers"));
    for (int k = 0; k < 3; ++k) log.toolTarget[k] = takeF64(target.constData() + 8 * k);
    if (!finiteWithin(log.toolTarget.norm(), kDivergenceRadius))
        return bad(QStringLiteral("recording.toolTarget: not a finite point near the sheet"));
    const QCborValue pressed = root.value(QLatin1String("pressed"));
    if (!pressed.isBool()) return bad(QStringLiteral("recording.pressed: not true or false"));
    log.pressed = pressed.toBool();
    const QCborValue end = root.value(QLatin1String("endStep"));
    // Written as a difference: a start step near the largest integer must not overflow.
    if (!end.isInteger() || end.toInteger() < log.start.stepCount ||
        end.toInteger() - log.start.stepCount > kMaxRecordedSteps)
        return bad(QStringLiteral("recording.endStep: not a step at or after the start's"));
    log.endStep = end.toInteger();
    if (const QCborValue state = root.value(QLatin1String("endState")); !state.isUndefined()) {
        // Hex text, as `state_hash` is printed: 16 lower-case digits.
        const QString text = state.toString();
        bool ok = state.isString() && text.size() == 16 && std::ranges::all_of(text, [](QChar ch) {
                      return (ch >= u'0' && ch <= u'9') || (ch >= u'a' && ch <= u'f');
                  });
        const std::uint64_t hash = ok ? text.toULongLong(&ok, 16) : 0;
        if (!ok) return bad(QStringLiteral("recording.endState: not 16 hexadecimal digits"));
        log.endState = hash;
    }

    const QCborValue paramsValue = root.value(QLatin1String("params"));
    if (!paramsValue.isArray()) return bad(QStringLiteral("recording.params: missing"));
    std::vector<std::shared_ptr<const SimParams>> params;
    for (const QCborValue& p : paramsValue.toArray()) {
        if (!p.isByteArray()) return bad(QStringLiteral("recording.params: not encoded params"));
        std::optional<SimParams> decoded = decodeParams(p.toByteArray(), &error);
        if (!decoded)
            return bad(QStringLiteral("recording.params[%1]: %2").arg(params.size()).arg(error));
        params.push_back(std::make_shared<const SimParams>(std::move(*decoded)));
    }

    // Optional: a session without a Reset has none (and recordings made before Reset
    // was an undo step read as they did).
    std::vector<std::shared_ptr<const World>> worlds;
    const QCborValue worldsValue = root.value(QLatin1String("worlds"));
    if (!worldsValue.isUndefined()) {
        if (!worldsValue.isArray() || worldsValue.toArray().size() > kMaxRecordedResets)
            return bad(QStringLiteral("recording.worlds: not a list of at most %1 sheets")
                           .arg(kMaxRecordedResets));
        for (const QCborValue& w : worldsValue.toArray()) {
            if (!w.isByteArray()) return bad(QStringLiteral("recording.worlds: not a sheet"));
            WorldLoad decoded = decodeWorld(w.toByteArray());
            if (!decoded.world)
                return bad(QStringLiteral("recording.worlds[%1]: %2")
                               .arg(worlds.size())
                               .arg(decoded.error));
            worlds.push_back(std::make_shared<const World>(std::move(*decoded.world)));
        }
    }
    // Optional too: recordings made before the Fold tool have none.
    const QCborValue foldsValue = root.value(QLatin1String("folds"));
    const QByteArray folds = foldsValue.toByteArray();
    if (!foldsValue.isUndefined() && (!foldsValue.isByteArray() || folds.size() % kFoldBytes != 0))
        return bad(QStringLiteral("recording.folds: not whole folds of %1 bytes").arg(kFoldBytes));
    const QByteArray commands = root.value(QLatin1String("commands")).toByteArray();
    if (commands.size() % kCommandBytes != 0 ||
        commands.size() / kCommandBytes > kMaxRecordedCommands)
        return bad(QStringLiteral("recording.commands: not whole commands of %1 bytes")
                       .arg(kCommandBytes));
    log.commands.reserve(static_cast<std::size_t>(commands.size() / kCommandBytes));
    std::int64_t lastStep = log.start.stepCount;
    for (qsizetype offset = 0; offset < commands.size(); offset += kCommandBytes) {
        const char* p = commands.constData() + offset;
        const QString where = QStringLiteral("recording.commands[%1]").arg(offset / kCommandBytes);
        EditCommand c;
        c.step = take<std::int64_t>(p);
        if (c.step < lastStep || c.step > log.endStep)
            return bad(where + QStringLiteral(": step out of order"));
        lastStep = c.step;
        const auto kind = take<std::uint8_t>(p + 8);
        const auto flags = take<std::uint8_t>(p + 9);
        if (kind < 1 || kind > 11) return bad(where + QStringLiteral(": unknown command"));
        c.kind = static_cast<EditCommand::Kind>(kind);
        const int knownFlags = c.kind == EditCommand::Kind::Fold ? 7 : 3;
        if ((flags & ~knownFlags) != 0 || take<std::uint16_t>(p + 10) != 0)
            return bad(where + QStringLiteral(": unknown flags"));
        c.visible = flags & 1;
        c.pressed = flags & 2;
        const std::int32_t argument = take<std::int32_t>(p + 12);
        for (int k = 0; k < 3; ++k) c.target[k] = takeF64(p + 16 + 8 * k);
        c.radius = takeF64(p + 40);
        if (!finiteWithin(c.target.norm(), kDivergenceRadius) || !(c.radius >= 0.0) ||
            !(c.radius <= 1.0))
            return bad(where + QStringLiteral(": tool outside the scene"));
        if (c.kind == EditCommand::Kind::Params) {
            if (argument < 0 || argument >= static_cast<std::int32_t>(params.size()))
                return bad(where + QStringLiteral(": no such parameter change"));
            c.params = params[static_cast<std::size_t>(argument)];
        } else if (c.kind == EditCommand::Kind::Reset) {
            if (argument < 0 || argument >= static_cast<std::int32_t>(worlds.size()))
                return bad(where + QStringLiteral(": no such sheet to reset to"));
            c.world = worlds[static_cast<std::size_t>(argument)];
        } else if (c.kind == EditCommand::Kind::Fold) {
            if (argument < 0 || argument >= folds.size() / kFoldBytes)
                return bad(where + QStringLiteral(": no such fold"));
            const char* f = folds.constData() + qsizetype(argument) * kFoldBytes;
            FoldRequest fold;
            fold.from = c.target;
            for (int k = 0; k < 3; ++k) fold.to[k] = takeF64(f + 8 * k);
            fold.angle = takeF64(f + 24);
            for (int k = 0; k < 3; ++k) fold.viewer[k] = takeF64(f + 32 + 8 * k);
            fold.mountain = flags & 4;
            // The session refuses an angle out of range, as the editor does; only what
            // could not be computed with is refused here.
            if (!finiteWithin(fold.to.norm(), kDivergenceRadius) ||
                !finiteWithin(fold.angle, 10.0) || !finiteWithin(fold.viewer.norm(), 10.0))
                return bad(where + QStringLiteral(": fold line or angle out of range"));
            c.fold = std::make_shared<const FoldRequest>(fold);
        } else {
            // An undo of a stroke that does not exist does nothing, as in the editor.
            c.stroke = argument;
        }
        log.commands.push_back(std::move(c));
    }
    return {std::move(log), {}};
}

bool saveRecording(const EditLog& log, const QString& path, QString* error,
                   const QStringList& inputs) {
    // What could not be loaded again is not written.
    qint64 params = 0, resets = 0;
    for (const EditCommand& c : log.commands) {
        params += c.kind == EditCommand::Kind::Params;
        resets += c.kind == EditCommand::Kind::Reset;
    }
    if (resets > kMaxRecordedResets) {
        *error = QStringLiteral("the session has too many resets to record (%1; at most %2): "
                                "start a new one with New or Open")
                     .arg(resets)
                     .arg(kMaxRecordedResets);
        return false;
    }
    if (params > kMaxRecordedParams ||
        static_cast<qint64>(log.commands.size()) > kMaxRecordedCommands ||
        log.endStep - log.start.stepCount > kMaxRecordedSteps) {
        *error = QStringLiteral("the session is too long to record (%1 commands, %2 parameter "
                                "changes; at most %3 and %4): start a new one with New or Open")
                     .arg(log.commands.size())
                     .arg(params)
                     .arg(kMaxRecordedCommands)
                     .arg(kMaxRecordedParams);
        return false;
    }
    return writeOutputFile(path, encodeRecording(log), error, inputs);
}

RecordingLoad loadRecording(const QString& path) {
    QString error;
    const std::optional<QByteArray> bytes = readInputFile(path, kMaxRecordingBytes, &error);
    if (!bytes) return {std::nullopt, error};
    RecordingLoad load = decodeRecording(*bytes);
    if (!load.log) load.error = QStringLiteral("%1: %2").arg(path, load.error);
    return load;
}

} // namespace pf
