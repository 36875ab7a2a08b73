#pragma once

#include "Camera.h"
#include "GlFunctions.h"
#include "RenderOptions.h"
#include "SheetRenderer.h"
#include "SheetSnapshot.h"

#include <QImage>
#include <QSurfaceFormat>
#include <QWidget>
#include <memory>

class QOpenGLContext;

namespace pf {

class ViewportWindow;

// The editor's 3D view: draws the newest snapshot with the shared SheetRenderer, in a
// native GL window (ViewportWindow) that fills it, with the legend, the hint and the
// fold line painted over the picture. Input that reaches the window is delivered to
// this widget. GL is resolved through QOpenGLContext::getProcAddress into the same
// function table the headless path fills from OSMesa.
class Viewport : public QWidget {
    Q_OBJECT

  public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    // The surface format every viewport asks for: GL 3.3 core, depth, stencil, 4× MSAA.
    static QSurfaceFormat requiredFormat();
    // Process settings the view needs, before the application is made: a new frame is
    // drawn at the next turn of the event loop.
    static void prepareProcess();
    // What the view draws with: the same, without MSAA where GL is drawn by the CPU.
    // Needs the application.
    static QSurfaceFormat viewFormat();
    // GL_RENDERER of a context made with requiredFormat(); empty if none can be made.
    static QByteArray glRenderer();

    void setSnapshot(std::shared_ptr<const SheetSnapshot> snapshot);
    const SheetSnapshot* snapshot() const { return snapshot_.get(); }
    // The same, kept alive by the caller: for work that outlives the next frame.
    std::shared_ptr<const SheetSnapshot> sharedSnapshot() const { return snapshot_; }
    void setCamera(const OrbitCamera& camera);
    const OrbitCamera& camera() const { return camera_; }
    void setRenderOptions(const RenderOptions& options);
    const RenderOptions& renderOptions() const { return options_; }

    // A line of help shown at the bottom of the view (the first-run hint); empty hides it.
    void setHint(const QString& hint);
    const QString& hint() const { return hint_; }
    // The fold line being drawn, in the view's pixels; a null line hides it.
    void setFoldLine(const QLine& line);
    // Where the hovering tool is drawn on the picture shown (RenderOptions::hoverCenter);
    // none: where the simulation has it.
    void setHoverCenter(const std::optional<Vec3>& center);
    const std::optional<Vec3>& hoverCenter() const { return hoverCenter_; }
    const QLine& foldLine() const { return foldLine_; }

    // The native window the view draws in (input that reaches it comes to this widget).
    QWindow* glWindow() const;

    // Empty if GL came up; otherwise why not.
    QString glError() const { return glError_; }
    // Seconds the last frame took to draw.
    double lastFrameSeconds() const { return lastFrameSeconds_; }
    // The picture the view shows, drawn afresh with 4× MSAA as the headless renderer
    // draws it (empty before GL is up).
    QImage grabFramebuffer();

  signals:
    void frameDrawn();

  protected:
    bool event(QEvent* event) override;

  private:
    friend class ViewportWindow;
    void initializeGl(QOpenGLContext* context);
    // Draws the frame into `framebuffer` (bound), at the window's size in pixels.
    void paintGl(unsigned framebuffer);
    void paintOverlay(QPainter& painter, const QRect& area) const;
    void releaseGl();

    ViewportWindow* window_ = nullptr; // owned by its container, a child of this widget

    GlFunctions gl_;
    SheetRenderer renderer_;
    std::shared_ptr<const SheetSnapshot> snapshot_;
    OrbitCamera camera_;
    RenderOptions options_;
    QString glError_;
    QString hint_;
    QLine foldLine_;
    std::optional<Vec3> hoverCenter_;
    double lastFrameSeconds_ = 0.0;
};

} // namespace pf
