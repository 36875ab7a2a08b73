#include "OffscreenRenderer.h"

#include "Legend.h"

#include <QPainter>

namespace pf {

std::unique_ptr<OffscreenRenderer> OffscreenRenderer::create(int width, int height,
                                                             QString* error) {
    if (!sizeAllowed(width, height)) {
        if (error)
            *error = QStringLiteral("image size %1x%2 is outside %3..%4")
                         .arg(width)
                         .arg(height)
                         .arg(kMinSize)
                         .arg(kMaxSize);
        return nullptr;
    }
    std::unique_ptr<OffscreenRenderer> r(new OffscreenRenderer);
    r->width_ = width;
    r->height_ = height;
    r->context_ = OsMesaContext::create(width, height, error);
    if (!r->context_) return nullptr;
    std::string missing;
    if (!r->gl_.load(&OsMesaContext::procAddress, &missing)) {
        if (error) *error = QStringLiteral("OSMesa lacks %1").arg(QString::fromStdString(missing));
        return nullptr;
    }
    const GlFunctions& gl = r->gl_;
    gl.GenFramebuffers(1, &r->fbo_);
    gl.GenRenderbuffers(1, &r->color_);
    gl.GenRenderbuffers(1, &r->depth_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, r->fbo_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, r->color_);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r->color_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, r->depth_);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                               r->depth_);
    const bool msaaOk = gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl.GenFramebuffers(1, &r->resolveFbo_);
    gl.GenRenderbuffers(1, &r->resolveColor_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, r->resolveFbo_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, r->resolveColor_);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                               r->resolveColor_);
    if (!msaaOk || gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        if (error)
            *error =
                QStringLiteral("OSMesa could not make a %1x%2 framebuffer").arg(width).arg(height);
        return nullptr;
    }
    QString initError;
    if (!r->renderer_.initialize(r->gl_, &initError)) {
        if (error) *error = initError;
        return nullptr;
    }
    return r;
}

OffscreenRenderer::~OffscreenRenderer() {
    if (!context_ || !context_->makeCurrent()) return;
    renderer_.release();
    if (fbo_) {
        const GLuint fbos[] = {fbo_, resolveFbo_};
        const GLuint rbs[] = {color_, depth_, resolveColor_};
        gl_.DeleteFramebuffers(2, fbos);
        gl_.DeleteRenderbuffers(3, rbs);
    }
}

QString OffscreenRenderer::glVersion() const {
    return QString::fromLatin1(reinterpret_cast<const char*>(gl_.GetString(GL_VERSION))) +
           QStringLiteral(" / ") +
           QString::fromLatin1(reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER)));
}

QImage OffscreenRenderer::render(const SheetSnapshot& snapshot, const OrbitCamera& camera,
                                 const RenderOptions& options) {
    context_->makeCurrent();
    const GlFunctions& gl = gl_;
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    renderer_.render(snapshot, camera, options, width_, height_);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
    gl.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                       GL_NEAREST);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, resolveFbo_);
    QImage image(width_, height_, QImage::Format_RGBA8888);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    // GL rows run bottom-up; images top-down.
    image = image.mirrored(false, true).convertToFormat(QImage::Format_RGB32);
    if (options.legend && options.overlays) {
        QPainter painter(&image);
        drawLegend(painter, image.rect(), options);
    }
    return image;
}

} // namespace pf
