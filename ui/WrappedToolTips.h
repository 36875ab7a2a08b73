#pragma once

#include <QObject>

namespace pf {

// Long plain tooltips shown as a paragraph that wraps. Qt draws a plain tooltip on one
// line as wide as its text: the φ slider's explanation ran 1,450 px across a 1,280 px
// window. Rich text wraps, so a plain tip longer than kWrapFrom characters is shown
// escaped, as rich text kLineCharacters wide; short tips and rich ones are shown as Qt
// shows them.
// Installed on the application, it applies to every widget's tip.
class WrappedToolTips final : public QObject {
  public:
    using QObject::QObject;
    static constexpr int kWrapFrom = 80;
    static constexpr int kLineCharacters = 60;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace pf
