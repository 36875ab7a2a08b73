#pragma once

#include "OsMesaContext.h"
#include "SheetRenderer.h"

#include <QImage>
#include <memory>

namespace pf {

// Renders snapshots to images with no display: an OSMesa context, a 4× multisampled
// framebuffer, and the same SheetRenderer the editor uses.
class OffscreenRenderer {
  public:
    static constexpr int kMinSize = 16;
    static constexpr int kMaxSize = 8192;
    // Whether it renders an image of that size (each side kMinSize..kMaxSize).
    static constexpr bool sizeAllowed(int width, int height) {
        return width >= kMinSize && height >= kMinSize && width <= kMaxSize && height <= kMaxSize;
    }

    static std::unique_ptr<OffscreenRenderer> create(int width, int height, QString* error);
    ~OffscreenRenderer();

    // The picture, with the legend of the active overlays when options.legend is set.
    QImage render(const SheetSnapshot& snapshot, const OrbitCamera& camera,
                  const RenderOptions& options);
    QString glVersion() const;
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    OffscreenRenderer() = default;
    std::unique_ptr<OsMesaContext> context_;
    GlFunctions gl_;
    SheetRenderer renderer_;
    GLuint fbo_ = 0, color_ = 0, depth_ = 0, resolveFbo_ = 0, resolveColor_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace pf
