#include "ClampingSpinBox.h"

#include <optional>

namespace pf {

namespace {

// The typed number without prefix, suffix and group separators, if it is one.
std::optional<qlonglong> typedNumber(const QSpinBox& box, QString text) {
    if (text.startsWith(box.prefix())) text.remove(0, box.prefix().size());
    if (text.endsWith(box.suffix())) text.chop(box.suffix().size());
    bool ok = false;
    const qlonglong n = box.locale().toLongLong(text.trimmed(), &ok);
    return ok ? std::optional<qlonglong>(n) : std::nullopt;
}

} // namespace

QValidator::State ClampingSpinBox::validate(QString& text, int& pos) const {
    const QValidator::State state = QSpinBox::validate(text, pos);
    if (state != QValidator::Invalid) return state;
    const auto n = typedNumber(*this, text);
    return n && *n > maximum() ? QValidator::Intermediate : state;
}

void ClampingSpinBox::fixup(QString& text) const {
    if (const auto n = typedNumber(*this, text); n && *n > maximum()) {
        text = textFromValue(maximum());
        return;
    }
    QSpinBox::fixup(text);
}

} // namespace pf
