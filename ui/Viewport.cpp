#include "Viewport.h"

#include "Legend.h"
#include "Subdivision.h"

#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QPainter>

namespace pf {

// The legend and any GL error, drawn by a transparent child widget over the GL
// picture. Painting them with QPainter inside paintGL would leave QPainter's GL
// state (blending, programs, buffers) behind for the next frame.
class Viewport::Overlay : public QWidget {
  public:
    explicit Overlay(Viewport* view) : QWidget(view), view_(view) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
    }

  protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        if (!view_->glError_.isEmpty()) {
            painter.fillRect(rect(), palette().window());
            painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, view_->glError_);
            return;
        }
        if (view_->options_.legend && view_->options_.overlays)
            drawLegend(painter, rect(), view_->options_);
        if (!view_->hint_.isEmpty()) drawHint(painter);
        if (!view_->foldLine_.isNull()) drawFoldLine(painter);
    }

  private:
    // A dark rounded box, bottom centre, wrapped to at most 80 % of the view's width.
    void drawHint(QPainter& painter) {
        const int margin = 12, pad = 8;
        const int maxWidth = std::max(80, width() * 8 / 10);
        const int flags = Qt::AlignCenter | Qt::TextWordWrap;
        const QRect text = painter.fontMetrics().boundingRect(QRect(0, 0, maxWidth, height()),
                                                              flags, view_->hint_);
        QRect box(0, 0, text.width() + 2 * pad, text.height() + 2 * pad);
        box.moveCenter(QPoint(width() / 2, height() - margin - box.height() / 2));
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(20, 20, 24, 190));
        painter.drawRoundedRect(box, 6, 6);
        painter.setPen(Qt::white);
        painter.drawText(box.adjusted(pad, pad, -pad, -pad), flags, view_->hint_);
    }

    // Dashed, dark under light, so that it shows on white paper and on the dark desk.
    void drawFoldLine(QPainter& painter) {
        const QLine& line = view_->foldLine_;
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(QPen(QColor(20, 20, 24, 200), 4, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(line);
        painter.setPen(QPen(QColor(255, 200, 40), 2, Qt::DashLine, Qt::RoundCap));
        painter.drawLine(line);
        painter.setBrush(QColor(255, 200, 40));
        painter.setPen(Qt::NoPen);
        for (const QPoint& end : {line.p1(), line.p2()}) painter.drawEllipse(end, 4, 4);
    }

  private:
    Viewport* view_;
};

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent), overlay_(new Overlay(this)) {
    setFormat(requiredFormat());
    setMinimumSize(160, 120);
    options_.pins = true; // the artist sees where the sheet is held
}

void Viewport::resizeEvent(QResizeEvent* event) {
    QOpenGLWidget::resizeEvent(event);
    overlay_->setGeometry(rect());
}

Viewport::~Viewport() {
    releaseGl();
    // ~QOpenGLWidget destroys the context after this object's own part is gone, and the
    // automatic disconnect of a receiver comes later still (in ~QObject): cut the
    // aboutToBeDestroyed connection here, or releaseGl would run on a destroyed Viewport.
    if (context()) disconnect(context(), nullptr, this, nullptr);
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

void Viewport::releaseGl() {
    if (!renderer_.initialized() || !context()) return;
    makeCurrent();
    renderer_.release();
    doneCurrent();
}

void Viewport::setSnapshot(std::shared_ptr<const SheetSnapshot> snapshot) {
    snapshot_ = std::move(snapshot);
    update();
}

void Viewport::setCamera(const OrbitCamera& camera) {
    camera_ = camera;
    update();
}

void Viewport::setFoldLine(const QLine& line) {
    foldLine_ = line;
    overlay_->update();
}

void Viewport::setHint(const QString& hint) {
    hint_ = hint;
    overlay_->update();
}

void Viewport::setRenderOptions(const RenderOptions& options) {
    options_ = options;
    update();
    overlay_->update();
}

void Viewport::initializeGL() {
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl,
            Qt::UniqueConnection);
    QOpenGLContext* ctx = context();
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
    overlay_->update();
}

void Viewport::paintGL() {
    QElapsedTimer timer;
    timer.start();
    const qreal dpr = devicePixelRatioF();
    const int w = static_cast<int>(width() * dpr), h = static_cast<int>(height() * dpr);
    if (renderer_.initialized() && snapshot_) {
        // The editor draws at most kInteractiveTriangles: a crumpled sheet is drawn one
        // level coarser rather than multiplying the frame time, and the software GL
        // driver's memory (which keeps the largest recent frames) stays bounded.
        RenderOptions drawn = options_;
        drawn.subdivision =
            subdivisionWithin(options_.subdivision, snapshot_->tris.size(), kInteractiveTriangles);
        renderer_.render(*snapshot_, camera_, drawn, w, h);
    }
    lastFrameSeconds_ = timer.nsecsElapsed() * 1e-9;
    emit frameDrawn();
}

} // namespace pf
