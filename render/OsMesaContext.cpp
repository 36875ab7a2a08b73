#include "OsMesaContext.h"

#include <GL/osmesa.h>

namespace pf {

std::unique_ptr<OsMesaContext> OsMesaContext::create(int width, int height, QString* error) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    std::unique_ptr<OsMesaContext> c(new OsMesaContext);
    c->context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!c->context_) {
        if (error) *error = QStringLiteral("OSMesa could not create a GL 3.3 core context");
        return nullptr;
    }
    c->width_ = width;
    c->height_ = height;
    c->buffer_.resize(static_cast<std::size_t>(width) * height * 4);
    if (!c->makeCurrent()) {
        if (error)
            *error = QStringLiteral("OSMesa could not make a %1x%2 context current")
                         .arg(width)
                         .arg(height);
        return nullptr;
    }
    return c;
}

OsMesaContext::~OsMesaContext() {
    if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

bool OsMesaContext::makeCurrent() {
    return OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                             width_, height_) == GL_TRUE;
}

void* OsMesaContext::procAddress(const char* name) {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

} // namespace pf
