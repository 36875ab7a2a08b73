#include "Viewport.h"

#include "Legend.h"
#include "ViewportWindow.h"

#include <QElapsedTimer>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>

namespace pf {

namespace {

// A dark rounded box, bottom centre, wrapped to at most 80 % of the view's width.
void drawHint(QPainter& painter, const QRect& area, const QString& hint) {
    const int margin = 12, pad = 8;
    const int maxWidth = std::max(80, area.width() * 8 / 10);
    const int flags = Qt::AlignCenter | Qt::TextWordWrap;
    const QRect text =
        painter.fontMetrics().boundingRect(QRect(0, 0, maxWidth, area.height()), flags, hint);
    QRect box(0, 0, text.width() + 2 * pad, text.height() + 2 * pad);
    box.moveCenter(QPoint(area.width() / 2, area.height() - margin - box.height() / 2));
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 20, 24, 190));
    painter.drawRoundedRect(box, 6, 6);
    painter.setPen(Qt::white);
    painter.drawText(box.adjusted(pad, pad, -pad, -pad), flags, hint);
}

// Dashed, dark under light, so that it shows on white paper and on the dark desk.
void drawFoldLine(QPainter& painter, const QLine& line) {
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(20, 20, 24, 200), 4, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(line);
    painter.setPen(QPen(QColor(255, 200, 40), 2, Qt::DashLine, Qt::RoundCap));
    painter.drawLine(line);
    painter.setBrush(QColor(255, 200, 40));
    painter.setPen(Qt::NoPen);
    for (const QPoint& end : {line.p1(), line.p2()}) painter.drawEllipse(end, 4, 4);
}

} // namespace

Viewport::Viewport(QWidget* parent) : QWidget(parent), window_(new ViewportWindow(this)) {
    setMinimumSize(160, 120);
    options_.pins = true; // the artist sees where the sheet is held
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(QWidget::createWindowContainer(window_, this));
}

Viewport::~Viewport() {
    releaseGl();
    // The window and its context go with the container, after this object's own part
    // is gone: cut the aboutToBeDestroyed connection here, or releaseGl would run on a
    // destroyed Viewport.
    if (window_->context()) disconnect(window_->context(), nullptr, this, nullptr);
}

bool Viewport::event(QEvent* event) {
    // The cursor shows over the window that covers this widget, so it must be set there.
    if (event->type() == QEvent::CursorChange) window_->setCursor(cursor());
    return QWidget::event(event);
}

QWindow* Viewport::glWindow() const {
    return window_;
}

QSurfaceFormat Viewport::requiredFormat() {
    QSurfaceFormat f;
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(8);
    f.setSamples(4);
    return f;
}

QByteArray Viewport::glRenderer() {
    QOffscreenSurface surface;
    surface.setFormat(requiredFormat());
    surface.create();
    QOpenGLContext context;
    context.setFormat(requiredFormat());
    if (!context.create() || !context.makeCurrent(&surface)) return {};
    const auto* name = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    const QByteArray renderer(name ? name : "");
    context.doneCurrent();
    return renderer;
}

// A window's update is drawn after Qt's idle time, 5 ms, on X11 (Qt 6.4's xcb keeps the
// platform's timer): snapshots that came in that wait replaced each other, and the editor
// drew 40 of the simulation's 59 frames a second while the GUI thread was busy 3 ms a
// frame. Set before the application exists (Qt reads it once, at the first update) and
// before any thread starts; a user's own setting is kept. Where a swap waits for the
// display's refresh, that still paces the view.
void Viewport::prepareProcess() {
    if (!qEnvironmentVariableIsSet("QT_QPA_UPDATE_IDLE_TIME"))
        qputenv("QT_QPA_UPDATE_IDLE_TIME", "0");
}

QSurfaceFormat Viewport::viewFormat() {
    // Drawn by the CPU, 4× multisampling halves the frame rate (bench_render viewport
    // under Xvfb with llvmpipe: 20 ms a frame without, 41 ms with); there the edges
    // go without it.
    static const bool software = [] {
        const QByteArray renderer = glRenderer().toLower();
        return renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
               renderer.contains("swrast");
    }();
    QSurfaceFormat f = requiredFormat();
    if (software) f.setSamples(0);
    return f;
}

void Viewport::releaseGl() {
    if (!renderer_.initialized() || !window_->context()) return;
    window_->makeCurrent();
    renderer_.release();
    window_->doneCurrent();
}

// A sheet at rest is published at every frame with nothing to draw anew: redrawing it
// kept a core 85 % busy under software GL. A snapshot that draws the same picture as the
// one shown replaces it without a repaint.
void Viewport::setSnapshot(std::shared_ptr<const SheetSnapshot> snapshot) {
    const bool same =
        snapshot_ && snapshot && (snapshot_ == snapshot || drawsTheSame(*snapshot_, *snapshot));
    snapshot_ = std::move(snapshot);
    if (!same) window_->update();
}

void Viewport::setCamera(const OrbitCamera& camera) {
    camera_ = camera;
    window_->update();
}

void Viewport::setHoverCenter(const std::optional<Vec3>& center) {
    if (center == hoverCenter_) return;
    hoverCenter_ = center;
    window_->update();
}

void Viewport::setFoldLine(const QLine& line) {
    foldLine_ = line;
    window_->update();
}

void Viewport::setHint(const QString& hint) {
    hint_ = hint;
    window_->update();
}

void Viewport::setRenderOptions(const RenderOptions& options) {
    options_ = options;
    window_->update();
}

void Viewport::initializeGl(QOpenGLContext* ctx) {
    connect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl,
            Qt::UniqueConnection);
    std::string missing;
    const bool loaded = gl_.load(
        [ctx](const char* name) { return reinterpret_cast<void*>(ctx->getProcAddress(name)); },
        &missing);
    if (!loaded) {
        glError_ =
            tr("OpenGL 3.3 is not available (missing %1)").arg(QString::fromStdString(missing));
        return;
    }
    QString error;
    if (!renderer_.initialize(gl_, &error)) glError_ = error;
}

void Viewport::paintGl(unsigned framebuffer) {
    QElapsedTimer timer;
    timer.start();
    const qreal dpr = window_->devicePixelRatio();
    const int w = static_cast<int>(width() * dpr), h = static_cast<int>(height() * dpr);
    if (renderer_.initialized() && snapshot_) {
        RenderOptions options = interactiveOptions(options_, snapshot_->tris.size());
        options.hoverCenter = hoverCenter_;
        renderer_.render(*snapshot_, camera_, options, w, h);
    } else {
        QOpenGLFunctions* f = QOpenGLContext::currentContext()->functions();
        f->glClearColor(0.2f, 0.2f, 0.22f, 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
    }
    // QPainter draws the legend, the hint and the fold line over the picture, into the
    // same framebuffer. It leaves its GL state behind; the renderer sets all it needs.
    const bool overlay = !glError_.isEmpty() || !hint_.isEmpty() || !foldLine_.isNull() ||
                         (options_.legend && options_.overlays);
    if (overlay) {
        QOpenGLPaintDevice device(w, h);
        device.setDevicePixelRatio(dpr);
        QPainter painter(&device);
        paintOverlay(painter, rect());
    }
    // QPainter may leave another framebuffer bound; the caller reads or swaps this one.
    QOpenGLContext::currentContext()->functions()->glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    lastFrameSeconds_ = timer.nsecsElapsed() * 1e-9;
}

void Viewport::paintOverlay(QPainter& painter, const QRect& area) const {
    if (!glError_.isEmpty()) {
        painter.fillRect(area, palette().window());
        painter.setPen(palette().windowText().color());
        painter.drawText(area, Qt::AlignCenter | Qt::TextWordWrap, glError_);
        return;
    }
    if (options_.legend && options_.overlays) drawLegend(painter, area, options_);
    if (!hint_.isEmpty()) drawHint(painter, area, hint_);
    if (!foldLine_.isNull()) drawFoldLine(painter, foldLine_);
}

QImage Viewport::grabFramebuffer() {
    if (!window_->isValid()) return {};
    window_->makeCurrent();
    const qreal dpr = window_->devicePixelRatio();
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setSamples(requiredFormat().samples()); // as OSMesa and the exports draw it
    QOpenGLFramebufferObject fbo(static_cast<int>(width() * dpr), static_cast<int>(height() * dpr),
                                 format);
    fbo.bind();
    paintGl(fbo.handle());
    QImage picture = fbo.toImage();
    fbo.release();
    window_->doneCurrent();
    picture.setDevicePixelRatio(dpr);
    return picture;
}

} // namespace pf
