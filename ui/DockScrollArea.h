#pragma once

#include <QScrollArea>

namespace pf {

// A dock's contents that scroll up and down when the window is too short for them, as
// wide as they need. Docked straight into a QDockWidget, a panel's minimum height was
// the window's: the editor could not be made shorter than 721 pixels, and where a window
// manager made it so, the Solver dock drew its rows over the status bar.
class DockScrollArea : public QScrollArea {
    Q_OBJECT

  public:
    explicit DockScrollArea(QWidget* content, QWidget* parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  signals:
    // The contents' size hint changed height (a section opened, another language).
    void contentsResized();

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    int scrollBarWidth() const;
    QSize contentsHint_; // the contents' size hint last passed on
};

} // namespace pf
