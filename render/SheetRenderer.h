#pragma once

#include "Camera.h"
#include "DrawnSurface.h"
#include "GlFunctions.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"

#include <QString>
#include <array>
#include <vector>

namespace pf {

// Draws a sheet snapshot with GL 3.3 core into whatever framebuffer is bound: the
// editor's QOpenGLWidget and the headless OSMesa path run this same code. All GL
// calls go through the GlFunctions table it is given.
class SheetRenderer {
  public:
    // Needs a current context; `gl` must outlive the renderer.
    bool initialize(const GlFunctions& gl, QString* error);
    // Deletes the GL objects; needs the same context current.
    void release();
    bool initialized() const { return gl_ != nullptr; }

    void render(const SheetSnapshot& snapshot, const OrbitCamera& camera,
                const RenderOptions& options, int width, int height);

    // The background, also used by legends and tests (the paper's colour is the look's).
    static constexpr float kBackground[3] = {0.80f, 0.82f, 0.85f};
    // The background's shade from the bottom of the view to the top (times kBackground,
    // at screen y from -1 to 1: a + b y); the desk fades into the same.
    static constexpr float kBackgroundShade[2] = {0.92f, 0.1f};

  private:
    struct LineBatch {
        int first = 0, count = 0;
        float halfWidth = 1.0f;
    };
    GLuint program(const char* vert, const char* geom, const char* frag, QString* error);
    void uploadSurface(const SheetSnapshot& snap, const RenderOptions& options);
    void buildLines(const SheetSnapshot& snap, const RenderOptions& options);
    void uploadLines(const SheetSnapshot& snap, const RenderOptions& options);
    // Binds the look's texture to unit 0, uploading it when the image changed; false
    // (nothing bound) for a plain look.
    bool bindPaperTexture(const PaperLook& look);
    void makeSphere();
    // Position, normal, colour of the surface and sphere buffers (the bound VAO and VBO).
    void setSurfaceLayout();
    void setMatrix(GLuint prog, const char* name, const Mat4& m);
    void setVec3(GLuint prog, const char* name, const float* v);

    const GlFunctions* gl_ = nullptr;
    GLuint surfaceProgram_ = 0, linesProgram_ = 0, shadowProgram_ = 0, groundProgram_ = 0,
           backgroundProgram_ = 0;
    GLuint surfaceVao_ = 0, surfaceVbo_ = 0, surfaceEbo_ = 0;
    GLuint linesVao_ = 0, linesVbo_ = 0;
    GLuint groundVao_ = 0, groundVbo_ = 0;
    GLuint sphereVao_ = 0, sphereVbo_ = 0, sphereEbo_ = 0;
    GLuint emptyVao_ = 0;
    GLuint texture_ = 0;
    qint64 textureKey_ = 0; // QImage::cacheKey of what texture_ holds
    bool surfaceHasUvs_ = false;
    GLsizei surfaceIndexCount_ = 0, sphereIndexCount_ = 0;
    // What the surface and line buffers hold, so a repaint with a new camera only
    // neither subdivides nor rebuilds the overlay lines again.
    SurfaceKey surfaceKey_;
    struct LinesKey {
        std::uint64_t serial = 0;
        unsigned overlays = 0;
        bool pins = false;
        bool creases = false;
        std::array<float, 3> paper{};
        double probabilityRange = -1.0;
        friend bool operator==(const LinesKey&, const LinesKey&) = default;
    } linesKey_;
    DrawnSurface surface_;
    std::vector<float> lineData_;
    std::vector<LineBatch> lineBatches_;
};

} // namespace pf
