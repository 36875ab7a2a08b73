#pragma once

#include <QSpinBox>

namespace pf {

// A spin box that takes a number typed past its maximum and makes it the maximum on
// Enter. QSpinBox refuses the keystroke that takes the text past the maximum, so a
// user's 8000 steps a second (at most 7680) became 800 without a word.
class ClampingSpinBox : public QSpinBox {
  public:
    using QSpinBox::QSpinBox;

  protected:
    QValidator::State validate(QString& text, int& pos) const override;
    void fixup(QString& text) const override;
};

} // namespace pf
