#include "BoundedCbor.h"

#include <QCborArray>
#include <QCborMap>
#include <QCborStreamReader>

namespace pf {

namespace {

// Longest map key read as a key; a longer one cannot be known and is skipped.
constexpr qsizetype kMaxKeyBytes = 64;
// Recursion allowed while skipping an unknown value (QCborStreamReader::next's default
// of 10000 nested calls could overflow the stack of a sanitizer build).
constexpr int kMaxSkipDepth = 64;

class BoundedReader {
  public:
    BoundedReader(const QByteArray& bytes, const CborBounds& bounds)
        : reader_(bytes), bounds_(bounds), size_(bytes.size()) {}

    std::optional<QCborValue> read(QString* error) {
        QCborValue root = value(0);
        if (failed()) {
            if (error) *error = problem_.isEmpty() ? readerProblem() : problem_;
            return std::nullopt;
        }
        // One document per file: bytes after it were read without a word (a sheet padded
        // with 500 MB of zeros loaded, and held the memory to read them).
        if (const qint64 after = size_ - reader_.currentOffset(); after > 0) {
            if (error)
                *error = QStringLiteral("the file goes on for %1 bytes after its data ends (two "
                                        "files joined, or something appended?)")
                             .arg(after);
            return std::nullopt;
        }
        return root;
    }

  private:
    // A file that stops in the middle is the likeliest bad file a user meets (a copy or
    // a download cut short): said in those words, not as the reader's "unexpected end of
    // input data".
    QString readerProblem() {
        const QCborError e = reader_.lastError();
        if (e == QCborError::EndOfFile && size_ == 0) return QStringLiteral("the file is empty");
        // (The reader's offset is where the value that ran out began, not the end.)
        if (e == QCborError::EndOfFile)
            return QStringLiteral("the file ends after %1 %2, in the middle of its data: it "
                                  "was cut short (an interrupted copy or download?)")
                .arg(size_)
                .arg(size_ == 1 ? QStringLiteral("byte") : QStringLiteral("bytes"));
        return QStringLiteral("not a valid CBOR file at byte %1: %2")
            .arg(reader_.currentOffset())
            .arg(e.toString());
    }

    bool failed() { return !problem_.isEmpty() || reader_.lastError() != QCborError::NoError; }
    QCborValue fail(const QString& message) {
        if (problem_.isEmpty()) problem_ = message;
        return {};
    }

    template <typename Chunk, typename Out>
    bool readChunks(Chunk (QCborStreamReader::*next)(), Out* out) {
        auto chunk = (reader_.*next)();
        while (chunk.status == QCborStreamReader::Ok) {
            *out += chunk.data;
            chunk = (reader_.*next)();
        }
        return chunk.status == QCborStreamReader::EndOfString;
    }

    void skip() { reader_.next(kMaxSkipDepth); }

    QCborValue value(int depth) {
        if (failed()) return {};
        // Every container and every tag nests one level: a file of nested tags must not
        // recurse without bound either.
        if (depth > bounds_.maxDepth)
            return fail(QStringLiteral("values nested more than %1 deep").arg(bounds_.maxDepth));
        if (++values_ > bounds_.maxValues)
            return fail(QStringLiteral("more than %1 values in the file's structure")
                            .arg(bounds_.maxValues));
        switch (reader_.type()) {
        case QCborStreamReader::UnsignedInteger: {
            const quint64 u = reader_.toUnsignedInteger();
            reader_.next();
            return u > quint64(std::numeric_limits<qint64>::max()) ? QCborValue(double(u))
                                                                   : QCborValue(qint64(u));
        }
        case QCborStreamReader::NegativeInteger: {
            // Qt gives the value's magnitude (5 for -5; 0 for -2⁶⁴), not the n of CBOR's
            // -1 - n: read as -1 - n, every negative integer in a file came one too low.
            const quint64 n = quint64(reader_.toNegativeInteger());
            reader_.next();
            constexpr quint64 kLargest = quint64(std::numeric_limits<qint64>::max());
            if (n == 0) return QCborValue(-18446744073709551616.0);
            if (n <= kLargest) return QCborValue(-qint64(n));
            if (n == kLargest + 1) return QCborValue(std::numeric_limits<qint64>::min());
            return QCborValue(-double(n));
        }
        case QCborStreamReader::ByteArray: {
            QByteArray b;
            if (!readChunks(&QCborStreamReader::readByteArray, &b)) return {};
            return b;
        }
        case QCborStreamReader::String: {
            QString s;
            if (!readChunks(&QCborStreamReader::readString, &s)) return {};
            return s;
        }
        case QCborStreamReader::Array: {
            if (depth >= bounds_.maxDepth)
                return fail(
                    QStringLiteral("containers nested more than %1 deep").arg(bounds_.maxDepth));
            if (reader_.isLengthKnown() && reader_.length() > quint64(bounds_.maxValues))
                return fail(QStringLiteral("an array of %1 values").arg(reader_.length()));
            QCborArray array;
            reader_.enterContainer();
            while (!failed() && reader_.hasNext()) array.append(value(depth + 1));
            if (failed()) return {};
            reader_.leaveContainer();
            return array;
        }
        case QCborStreamReader::Map: {
            if (depth >= bounds_.maxDepth)
                return fail(
                    QStringLiteral("containers nested more than %1 deep").arg(bounds_.maxDepth));
            QCborMap map;
            reader_.enterContainer();
            while (!failed() && reader_.hasNext()) {
                QString key;
                const bool shortText = reader_.isString() && reader_.isLengthKnown() &&
                                       reader_.length() <= quint64(kMaxKeyBytes);
                if (shortText) {
                    if (!readChunks(&QCborStreamReader::readString, &key)) break;
                } else {
                    skip();
                }
                if (failed() || !reader_.hasNext()) break; // a key needs a value
                if (shortText && bounds_.knownKeys.contains(key))
                    map.insert(key, value(depth + 1));
                else
                    skip();
            }
            if (failed()) return {};
            reader_.leaveContainer();
            return map;
        }
        case QCborStreamReader::Tag: {
            const QCborTag tag = reader_.toTag();
            reader_.next();
            return QCborValue(tag, value(depth + 1));
        }
        case QCborStreamReader::SimpleType: {
            const QCborSimpleType t = reader_.toSimpleType();
            reader_.next();
            return QCborValue(t);
        }
        case QCborStreamReader::Float16: {
            const double d = double(reader_.toFloat16());
            reader_.next();
            return d;
        }
        case QCborStreamReader::Float: {
            const double d = reader_.toFloat();
            reader_.next();
            return d;
        }
        case QCborStreamReader::Double: {
            const double d = reader_.toDouble();
            reader_.next();
            return d;
        }
        case QCborStreamReader::Invalid:
            break;
        }
        if (reader_.lastError() == QCborError::NoError)
            return fail(QStringLiteral("not a valid CBOR file at byte %1: unexpected data")
                            .arg(reader_.currentOffset()));
        return {};
    }

    QCborStreamReader reader_;
    const CborBounds& bounds_;
    qsizetype size_ = 0;
    qint64 values_ = 0;
    QString problem_;
};

} // namespace

std::optional<QCborValue> parseBoundedCbor(const QByteArray& bytes, const CborBounds& bounds,
                                           QString* error) {
    return BoundedReader(bytes, bounds).read(error);
}

} // namespace pf
