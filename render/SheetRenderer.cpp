#include "SheetRenderer.h"

#include "HeatColor.h"
#include "Picking.h"
#include "Subdivision.h"

#include <QFile>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {

namespace {

QByteArray shaderSource(const char* name) {
    QFile f(QStringLiteral(":/shaders/") + QLatin1String(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

constexpr int kLineFloats = 7; // position 3, colour 4
// A crease's line: this share of the paper's colour, blended at 0.6.
constexpr float kCreaseShade = 0.75f;

void pushLine(std::vector<float>& out, const Vec3& a, const Vec3& b, const float* rgba) {
    for (const Vec3* p : {&a, &b}) {
        out.insert(out.end(), {static_cast<float>(p->x()), static_cast<float>(p->y()),
                               static_cast<float>(p->z())});
        out.insert(out.end(), rgba, rgba + 4);
    }
}

} // namespace

GLuint SheetRenderer::program(const char* vert, const char* geom, const char* frag,
                              QString* error) {
    const GlFunctions& gl = *gl_;
    const GLuint prog = gl.CreateProgram();
    for (auto [name, type] :
         {std::pair{vert, GL_VERTEX_SHADER}, std::pair{geom, GL_GEOMETRY_SHADER},
          std::pair{frag, GL_FRAGMENT_SHADER}}) {
        if (!name) continue;
        const QByteArray src = shaderSource(name);
        if (src.isEmpty()) {
            *error =
                QStringLiteral("shader %1 is missing from the resources").arg(QLatin1String(name));
            return 0;
        }
        const GLuint sh = gl.CreateShader(type);
        const char* text = src.constData();
        gl.ShaderSource(sh, 1, &text, nullptr);
        gl.CompileShader(sh);
        GLint ok = 0;
        gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[2048];
            gl.GetShaderInfoLog(sh, sizeof log, nullptr, log);
            *error = QStringLiteral("shader %1: %2")
                         .arg(QLatin1String(name), QString::fromUtf8(log).trimmed());
            gl.DeleteShader(sh);
            return 0;
        }
        gl.AttachShader(prog, sh);
        gl.DeleteShader(sh); // stays alive while attached
    }
    gl.LinkProgram(prog);
    GLint ok = 0;
    gl.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        gl.GetProgramInfoLog(prog, sizeof log, nullptr, log);
        *error = QStringLiteral("linking %1: %2")
                     .arg(QLatin1String(vert), QString::fromUtf8(log).trimmed());
        return 0;
    }
    return prog;
}

bool SheetRenderer::initialize(const GlFunctions& gl, QString* error) {
    gl_ = &gl;
    // New buffers hold nothing yet: a paused sheet's next frame (same snapshot) refills them.
    surfaceKey_ = SurfaceKey{};
    linesKey_ = LinesKey{};
    QString err;
    surfaceProgram_ = program("surface.vert", nullptr, "surface.frag", &err);
    if (surfaceProgram_) linesProgram_ = program("lines.vert", "lines.geom", "lines.frag", &err);
    if (linesProgram_) shadowProgram_ = program("shadow.vert", nullptr, "shadow.frag", &err);
    if (shadowProgram_) groundProgram_ = program("ground.vert", nullptr, "ground.frag", &err);
    if (groundProgram_)
        backgroundProgram_ = program("background.vert", nullptr, "background.frag", &err);
    if (!backgroundProgram_) {
        if (error) *error = err;
        gl_ = nullptr;
        return false;
    }

    gl.GenVertexArrays(1, &surfaceVao_);
    gl.GenBuffers(1, &surfaceVbo_);
    gl.GenBuffers(1, &surfaceEbo_);
    gl.BindVertexArray(surfaceVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, surfaceVbo_);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, surfaceEbo_);
    setSurfaceLayout();

    gl.GenVertexArrays(1, &linesVao_);
    gl.GenBuffers(1, &linesVbo_);
    gl.BindVertexArray(linesVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, linesVbo_);
    const GLsizei lstride = kLineFloats * sizeof(float);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, lstride, nullptr);
    gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, lstride,
                           reinterpret_cast<void*>(3 * sizeof(float)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);

    // In units of the desk's reach (ground.vert): the fade is complete at 1.
    const float ground[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, -1, 1, 0, 1, -1, 0, 1};
    gl.GenVertexArrays(1, &groundVao_);
    gl.GenBuffers(1, &groundVbo_);
    gl.BindVertexArray(groundVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, groundVbo_);
    gl.BufferData(GL_ARRAY_BUFFER, sizeof ground, ground, GL_STATIC_DRAW);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(0);

    gl.GenVertexArrays(1, &emptyVao_);
    makeSphere();
    gl.BindVertexArray(0);
    return true;
}

void SheetRenderer::setSurfaceLayout() {
    const GlFunctions& gl = *gl_;
    const GLsizei stride = DrawnSurface::kFloatsPerVertex * sizeof(float);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(3 * sizeof(float)));
    gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(6 * sizeof(float)));
    gl.VertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(10 * sizeof(float)));
    for (GLuint a = 0; a < 4; ++a) gl.EnableVertexAttribArray(a);
}

void SheetRenderer::makeSphere() {
    const GlFunctions& gl = *gl_;
    std::vector<float> v;
    std::vector<std::uint32_t> idx;
    // Fine enough that its outline is round at the editor's size (32 segments showed
    // their corners).
    const int rings = 32, segments = 64;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const double th = std::numbers::pi * r / rings,
                         ph = 2 * std::numbers::pi * s / segments;
            const float n[3] = {static_cast<float>(std::sin(th) * std::cos(ph)),
                                static_cast<float>(std::cos(th)),
                                static_cast<float>(std::sin(th) * std::sin(ph))};
            v.insert(v.end(), {n[0], n[1], n[2], n[0], n[1], n[2], 0, 0, 0, 0, 0, 0});
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            idx.insert(idx.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    sphereIndexCount_ = static_cast<GLsizei>(idx.size());
    gl.GenVertexArrays(1, &sphereVao_);
    gl.GenBuffers(1, &sphereVbo_);
    gl.GenBuffers(1, &sphereEbo_);
    gl.BindVertexArray(sphereVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, sphereVbo_);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(),
                  GL_STATIC_DRAW);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphereEbo_);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * 4), idx.data(),
                  GL_STATIC_DRAW);
    setSurfaceLayout();
}

void SheetRenderer::release() {
    if (!gl_) return;
    const GlFunctions& gl = *gl_;
    for (GLuint p :
         {surfaceProgram_, linesProgram_, shadowProgram_, groundProgram_, backgroundProgram_})
        if (p) gl.DeleteProgram(p);
    const GLuint buffers[] = {surfaceVbo_, surfaceEbo_, linesVbo_,
                              groundVbo_,  sphereVbo_,  sphereEbo_};
    gl.DeleteBuffers(6, buffers);
    const GLuint arrays[] = {surfaceVao_, linesVao_, groundVao_, sphereVao_, emptyVao_};
    gl.DeleteVertexArrays(5, arrays);
    if (texture_) gl.DeleteTextures(1, &texture_);
    texture_ = 0;
    textureKey_ = 0;
    gl_ = nullptr;
}

void SheetRenderer::setMatrix(GLuint prog, const char* name, const Mat4& m) {
    const Eigen::Matrix4f f = m.cast<float>();
    gl_->UniformMatrix4fv(gl_->GetUniformLocation(prog, name), 1, GL_FALSE, f.data());
}

void SheetRenderer::setVec3(GLuint prog, const char* name, const float* v) {
    gl_->Uniform3fv(gl_->GetUniformLocation(prog, name), 1, v);
}

void SheetRenderer::uploadSurface(const SheetSnapshot& snap, const RenderOptions& options) {
    const SurfaceKey key = surfaceKeyOf(snap, options);
    if (snap.serial != 0 && key == surfaceKey_) return;
    surfaceKey_ = key;
    buildDrawnSurface(snap, options, surface_);
    surfaceHasUvs_ = surface_.hasUvs;
    surfaceIndexCount_ = static_cast<GLsizei>(surface_.indices.size());
    const GlFunctions& gl = *gl_;
    gl.BindVertexArray(surfaceVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, surfaceVbo_);
    gl.BufferData(GL_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(surface_.vertices.size() * sizeof(float)),
                  surface_.vertices.data(), GL_STREAM_DRAW);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(surface_.indices.size() * 4),
                  surface_.indices.data(), GL_STREAM_DRAW);
}

bool SheetRenderer::bindPaperTexture(const PaperLook& look) {
    const QImage image = paperTextureImage(look);
    const GlFunctions& gl = *gl_;
    if (image.isNull()) return false;
    if (!texture_) gl.GenTextures(1, &texture_);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, texture_);
    if (image.cacheKey() != textureKey_) {
        textureKey_ = image.cacheKey();
        const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
        // Rows go up as they are: GL's t = 0 is the first row, the image's top, which
        // is where the texture coordinates (Subdivision.h) put v = 0.
        gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.width(), rgba.height(), 0, GL_RGBA,
                      GL_UNSIGNED_BYTE, rgba.constBits());
        gl.GenerateMipmap(GL_TEXTURE_2D);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return true;
}

void SheetRenderer::buildLines(const SheetSnapshot& snap, const RenderOptions& options) {
    lineData_.clear();
    lineBatches_.clear();
    const auto& x = snap.x;
    const auto batch = [&](float halfWidth, auto&& fill) {
        LineBatch b;
        b.first = static_cast<int>(lineData_.size() / kLineFloats);
        b.halfWidth = halfWidth;
        fill();
        b.count = static_cast<int>(lineData_.size() / kLineFloats) - b.first;
        if (b.count > 0) lineBatches_.push_back(b);
    };
    const std::size_t n = snap.springEnds.size();
    if (options.creases)
        batch(0.5f, [&] {
            const float shade = kCreaseShade;
            const auto& paper = options.look.color;
            const float c[4] = {shade * paper[0], shade * paper[1], shade * paper[2], 0.6f};
            for (std::size_t s = 0; s < snap.creaseHalf.size(); ++s)
                if (snap.creaseHalf[s])
                    pushLine(lineData_, x[snap.springEnds[s][0]], x[snap.springEnds[s][1]], c);
        });
    if (options.overlays & OverlayWireframe)
        batch(0.6f, [&] {
            const float c[4] = {0.12f, 0.12f, 0.14f, 0.6f};
            for (std::size_t s = 0; s < n; ++s)
                if (snap.springKind[s] == SpringKind::Structural)
                    pushLine(lineData_, x[snap.springEnds[s][0]], x[snap.springEnds[s][1]], c);
        });
    if (options.overlays & OverlaySpringKinds)
        batch(1.0f, [&] {
            // Fig. 4: breakable springs blue, auxiliary springs red; hinges green.
            const float breakable[4] = {0.10f, 0.30f, 0.95f, 0.9f};
            const float fixed[4] = {0.45f, 0.65f, 1.00f, 0.9f};
            const float crease[4] = {0.90f, 0.10f, 0.10f, 1.0f};
            const float hinge[4] = {0.10f, 0.70f, 0.20f, 1.0f};
            for (std::size_t s = 0; s < n; ++s) {
                const float* c = nullptr;
                switch (snap.springKind[s]) {
                case SpringKind::Structural:
                    c = snap.breakable[s] ? breakable : fixed;
                    break;
                case SpringKind::Crease:
                    c = crease;
                    break;
                case SpringKind::Hinge:
                    c = hinge;
                    break;
                case SpringKind::Bending:
                    break;
                }
                if (c) pushLine(lineData_, x[snap.springEnds[s][0]], x[snap.springEnds[s][1]], c);
            }
        });
    if (options.overlays & OverlayBreakProbability)
        batch(1.4f, [&] {
            // Below a thousandth of the scale an edge is drawn in the colour of its 0, and
            // there it is rounding, not load: a flat sheet at rest reads P of 1e-16 on a
            // scattered zigzag of edges, which was drawn as a dark-blue lattice.
            const double shown = options.probabilityRange / 1000.0;
            for (std::size_t s = 0; s < n; ++s) {
                if (!(snap.breakProbability[s] >= shown)) continue;
                const auto h = heatColor(snap.breakProbability[s] / options.probabilityRange);
                const float c[4] = {h[0], h[1], h[2], 1.0f};
                pushLine(lineData_, x[snap.springEnds[s][0]], x[snap.springEnds[s][1]], c);
            }
        });
    // A small three-axis cross on each pin, in the pin's red, and on each vertex a hand
    // holds for a while (a fold's carry) in blue.
    const auto crosses = [&](const std::vector<Index>& vertices, const float(&c)[4]) {
        for (Index i : vertices)
            for (int axis = 0; axis < 3; ++axis) {
                const Vec3 d = kPinMarkArm * Vec3::Unit(axis);
                pushLine(lineData_, x[i] - d, x[i] + d, c);
            }
    };
    if (options.pins && !snap.pinned.empty())
        batch(2.0f, [&] { crosses(snap.pinned, {0.85f, 0.12f, 0.20f, 1.0f}); });
    if (options.pins && !snap.held.empty())
        batch(2.0f, [&] { crosses(snap.held, {0.15f, 0.35f, 0.85f, 1.0f}); });
    if (options.overlays & OverlayRecentBreaks)
        batch(2.2f, [&] {
            const float c[4] = {1.0f, 0.0f, 0.75f, 1.0f};
            for (std::size_t s = 0; s < n; ++s)
                if (snap.recentlyBroken[s])
                    pushLine(lineData_, x[snap.springEnds[s][0]], x[snap.springEnds[s][1]], c);
        });
    // No keeping the lines of a much larger (or more overlaid) sheet.
    if (lineData_.capacity() > 2 * lineData_.size()) lineData_.shrink_to_fit();
}

void SheetRenderer::uploadLines(const SheetSnapshot& snap, const RenderOptions& options) {
    const LinesKey key{snap.serial,     options.overlays,   options.pins,
                       options.creases, options.look.color, options.probabilityRange};
    if (snap.serial != 0 && key == linesKey_) return;
    linesKey_ = key;
    buildLines(snap, options);
    const GlFunctions& gl = *gl_;
    gl.BindVertexArray(linesVao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, linesVbo_);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lineData_.size() * sizeof(float)),
                  lineData_.data(), GL_STREAM_DRAW);
}

void SheetRenderer::render(const SheetSnapshot& snap, const OrbitCamera& camera,
                           const RenderOptions& options, int width, int height) {
    if (!gl_ || width <= 0 || height <= 0) return;
    const GlFunctions& gl = *gl_;
    const Mat4 viewProj = camera.projection(double(width) / height) * camera.view();
    const Vec3 e = camera.eye();
    const float eye[3] = {float(e.x()), float(e.y()), float(e.z())};
    const float ground = static_cast<float>(snap.groundHeight);

    gl.Viewport(0, 0, width, height);
    gl.ClearColor(kBackground[0], kBackground[1], kBackground[2], 1.0f);
    gl.ClearStencil(0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.Disable(GL_CULL_FACE);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    // Blend colour only: destination alpha stays 1, because the editor's widget is
    // composited into the window as premultiplied alpha.
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);

    uploadSurface(snap, options);
    const bool drawGround = options.ground && snap.groundEnabled;
    if (drawGround) {
        gl.UseProgram(groundProgram_);
        setMatrix(groundProgram_, "uViewProj", viewProj);
        gl.Uniform1f(gl.GetUniformLocation(groundProgram_, "uGround"), ground);
        setVec3(groundProgram_, "uBackground", kBackground);
        // Around where the camera looks (OrbitCamera::deskReach).
        const Vec3& t = camera.target;
        gl.Uniform2f(gl.GetUniformLocation(groundProgram_, "uCenter"), float(t.x()), float(t.z()));
        gl.Uniform1f(gl.GetUniformLocation(groundProgram_, "uReach"), float(camera.deskReach()));
        gl.Uniform1f(gl.GetUniformLocation(groundProgram_, "uHeight"), float(height));
        gl.Uniform2f(gl.GetUniformLocation(groundProgram_, "uShade"), kBackgroundShade[0],
                     kBackgroundShade[1]);
        gl.BindVertexArray(groundVao_);
        gl.DrawArrays(GL_TRIANGLES, 0, 6);

        // Contact shadow: each pixel darkened once (stencil), no depth writes.
        gl.Enable(GL_BLEND);
        gl.Enable(GL_STENCIL_TEST);
        gl.StencilFunc(GL_EQUAL, 0, 0xFF);
        gl.StencilOp(GL_KEEP, GL_KEEP, GL_INCR);
        gl.DepthMask(GL_FALSE);
        gl.UseProgram(shadowProgram_);
        setMatrix(shadowProgram_, "uViewProj", viewProj);
        gl.Uniform1f(gl.GetUniformLocation(shadowProgram_, "uGround"), ground);
        gl.BindVertexArray(surfaceVao_);
        gl.DrawElements(GL_TRIANGLES, surfaceIndexCount_, GL_UNSIGNED_INT, nullptr);
        gl.DepthMask(GL_TRUE);
        gl.Disable(GL_STENCIL_TEST);
        gl.Disable(GL_BLEND);
    }

    gl.UseProgram(surfaceProgram_);
    setMatrix(surfaceProgram_, "uViewProj", viewProj);
    setMatrix(surfaceProgram_, "uModel", Mat4::Identity());
    setVec3(surfaceProgram_, "uEye", eye);
    setVec3(surfaceProgram_, "uBaseColor", options.look.color.data());
    // Without material coordinates every point would take one texel's colour.
    const bool textured = surfaceHasUvs_ && bindPaperTexture(options.look);
    gl.Uniform1i(gl.GetUniformLocation(surfaceProgram_, "uTexture"), 0);
    gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uTextured"), textured ? 1.0f : 0.0f);
    gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uAlpha"), 1.0f);
    gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uFacet"), float(options.facet));
    gl.BindVertexArray(surfaceVao_);
    gl.DrawElements(GL_TRIANGLES, surfaceIndexCount_, GL_UNSIGNED_INT, nullptr);

    // The background after the desk and the paper, on the far plane, where neither was
    // drawn: drawn first, every pixel of it was shaded and then mostly painted over (a
    // tenth of the frame under software GL). Before the lines, which blend over it where
    // they stick out past the paper.
    gl.DepthMask(GL_FALSE);
    gl.DepthFunc(GL_LEQUAL);
    gl.UseProgram(backgroundProgram_);
    setVec3(backgroundProgram_, "uBackground", kBackground);
    gl.Uniform2f(gl.GetUniformLocation(backgroundProgram_, "uShade"), kBackgroundShade[0],
                 kBackgroundShade[1]);
    gl.BindVertexArray(emptyVao_);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.DepthFunc(GL_LESS);
    gl.DepthMask(GL_TRUE);

    uploadLines(snap, options);
    if (!lineBatches_.empty()) {
        // The lines (quads from the geometry shader) are pulled toward the eye so that
        // they win against the surface they lie on.
        gl.Enable(GL_BLEND);
        gl.Enable(GL_POLYGON_OFFSET_FILL);
        gl.PolygonOffset(-1.0f, -4.0f);
        gl.DepthFunc(GL_LEQUAL);
        gl.UseProgram(linesProgram_);
        setMatrix(linesProgram_, "uViewProj", viewProj);
        gl.Uniform2f(gl.GetUniformLocation(linesProgram_, "uViewport"), width * 0.5f,
                     height * 0.5f);
        gl.BindVertexArray(linesVao_);
        const float scale = std::max(1.0f, height / 720.0f);
        for (const LineBatch& b : lineBatches_) {
            gl.Uniform1f(gl.GetUniformLocation(linesProgram_, "uWidth"), b.halfWidth * scale);
            gl.DrawArrays(GL_LINES, b.first, b.count);
        }
        gl.DepthFunc(GL_LESS);
        gl.Disable(GL_POLYGON_OFFSET_FILL);
        gl.Disable(GL_BLEND);
    }

    if (options.sphere && (snap.sphere.active || snap.sphere.hovering)) {
        const SphereTool& sp = snap.sphere;
        Mat4 model = Mat4::Identity();
        model.block<3, 3>(0, 0) *= sp.radius;
        model.block<3, 1>(0, 3) =
            sp.hovering && options.hoverCenter ? *options.hoverCenter : sp.center;
        const float tool[3] = {0.35f, 0.52f, 0.82f};
        gl.Enable(GL_BLEND);
        gl.DepthMask(GL_FALSE);
        gl.UseProgram(surfaceProgram_);
        setMatrix(surfaceProgram_, "uModel", model);
        setVec3(surfaceProgram_, "uBaseColor", tool);
        gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uTextured"), 0.0f);
        gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uAlpha"), 0.45f);
        gl.Uniform1f(gl.GetUniformLocation(surfaceProgram_, "uFacet"), 0.0f);
        gl.BindVertexArray(sphereVao_);
        // The far half first, then the near half over it, so that each pixel blends the
        // two in the same order: blended as listed, a back face drawn after the front one
        // shaded its pixels differently, in bands across the sphere.
        // (makeSphere winds its triangles counter-clockwise seen from outside: GL's front.)
        gl.Enable(GL_CULL_FACE);
        for (const GLenum culled : {GL_FRONT, GL_BACK}) {
            gl.CullFace(culled);
            gl.DrawElements(GL_TRIANGLES, sphereIndexCount_, GL_UNSIGNED_INT, nullptr);
        }
        gl.Disable(GL_CULL_FACE);
        gl.DepthMask(GL_TRUE);
        gl.Disable(GL_BLEND);
    }
    gl.BindVertexArray(0);
}

} // namespace pf
