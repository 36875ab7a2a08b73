#pragma once

#include <QOpenGLWindow>

namespace pf {

class Viewport;

// The native GL window inside a Viewport. It draws straight into its own window
// surface: a QOpenGLWidget renders into a framebuffer object that the widget stack
// then composites into the main window every frame, which under software GL (Xvfb,
// llvmpipe) cost more than drawing the sheet (docs/safety.md has the measurements).
// It owns no state: drawing and input go to its Viewport, which stays the widget the
// editor, its input handling and the tests talk to. It never takes keyboard focus, so
// keys and shortcuts keep reaching the widgets.
class ViewportWindow final : public QOpenGLWindow {
  public:
    explicit ViewportWindow(Viewport* view);

  protected:
    void initializeGL() override;
    void paintGL() override;
    bool event(QEvent* event) override;

  private:
    Viewport* view_;
};

} // namespace pf
