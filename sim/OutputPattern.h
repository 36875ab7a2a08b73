#pragma once

#include <QString>
#include <optional>

namespace pf {

// A file name for an image sequence, such as frame_%04d.png: at most one field, written
// %d or %0Nd (N from 1 to 9), that becomes the frame number. Nothing else with a '%' is
// accepted, so no text a user types ever reaches a printf-style format.
class OutputPattern {
  public:
    // The pattern, or nothing with *error saying what is wrong.
    static std::optional<OutputPattern> parse(const QString& text, QString* error);

    bool hasField() const { return hasField_; }
    // The name of frame `index` (index ≥ 0); the text itself when there is no field.
    QString path(long long index) const;

  private:
    QString prefix_, suffix_;
    int width_ = 0; // zero-padded to this many digits; 0 means no padding
    bool hasField_ = false;
};

} // namespace pf
