#include "OutputPattern.h"

namespace pf {

std::optional<OutputPattern> OutputPattern::parse(const QString& text, QString* error) {
    auto refuse = [&](const QString& why) -> std::optional<OutputPattern> {
        // Concatenated, not QString::arg: the text itself may hold '%' markers.
        if (error)
            *error = QLatin1Char('\'') + text + QStringLiteral("': ") + why +
                     QStringLiteral("; a sequence needs one %d or %0Nd field (N 1-9), "
                                    "e.g. frame_%04d.png");
        return std::nullopt;
    };
    OutputPattern p;
    qsizetype i = 0;
    while (i < text.size()) {
        const QChar c = text[i];
        if (c != QLatin1Char('%')) {
            (p.hasField_ ? p.suffix_ : p.prefix_).append(c);
            ++i;
            continue;
        }
        if (p.hasField_) return refuse(QStringLiteral("more than one '%' field"));
        qsizetype j = i + 1;
        int width = 0;
        if (j < text.size() && text[j] == QLatin1Char('0')) {
            ++j;
            if (j >= text.size() || !text[j].isDigit() || text[j] == QLatin1Char('0'))
                return refuse(QStringLiteral("'%0' must be followed by a width from 1 to 9"));
            width = text[j].digitValue();
            ++j;
        }
        if (j >= text.size() || text[j] != QLatin1Char('d'))
            return refuse(QStringLiteral("'%' starts something other than %d or %0Nd"));
        p.width_ = width;
        p.hasField_ = true;
        i = j + 1;
    }
    return p;
}

QString OutputPattern::path(long long index) const {
    if (!hasField_) return prefix_;
    return prefix_ + QStringLiteral("%1").arg(index, width_, 10, QLatin1Char('0')) + suffix_;
}

} // namespace pf
