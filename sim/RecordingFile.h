#pragma once

#include "EditSession.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace pf {

// The .paperrec file: an editing session as a CBOR map — the sheet it started from (a
// whole .paper file), the tool's target and button then, every command stamped with its
// step, and the step it ended at (docs/recording.md).
inline constexpr int kRecordingVersion = 1;
inline constexpr const char* kRecordingMagic = "PaperFold recording";
inline constexpr qint64 kMaxRecordingBytes = 1024LL * 1024 * 1024;
// Parameter changes (a slider drag makes one per move) and commands beyond these are
// refused before anything is allocated for them.
inline constexpr qint64 kMaxRecordedParams = 200'000;
inline constexpr qint64 kMaxRecordedCommands = 20'000'000;
// Each Reset carries the sheet it starts from (a whole sheet file's worth).
inline constexpr qint64 kMaxRecordedResets = 1'000;
// As `simulate --steps` at most: a recording may not ask for more steps than that.
inline constexpr qint64 kMaxRecordedSteps = 1'000'000'000;

QByteArray encodeRecording(const EditLog& log);

struct RecordingLoad {
    std::optional<EditLog> log;
    QString error; // one line naming what is wrong, when log is empty
};

// Checks everything, the start sheet as the sheet loader does; never trusts a count, an
// index or a step it was given.
RecordingLoad decodeRecording(const QByteArray& bytes);

// Through the checked output path (OutputFile.h), like saveWorld.
bool saveRecording(const EditLog& log, const QString& path, QString* error,
                   const QStringList& inputs = {});
RecordingLoad loadRecording(const QString& path);

} // namespace pf
