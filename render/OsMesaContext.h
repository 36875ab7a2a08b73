#pragma once

#include <QString>
#include <memory>
#include <vector>

namespace pf {

// A GL 3.3 core context with no window, no display and no GPU (Mesa's llvmpipe).
// The only file that includes osmesa.h, whose <GL/gl.h> must not meet glcorearb.h.
class OsMesaContext {
  public:
    static std::unique_ptr<OsMesaContext> create(int width, int height, QString* error);
    ~OsMesaContext();
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    bool makeCurrent();
    static void* procAddress(const char* name);

  private:
    OsMesaContext() = default;
    void* context_ = nullptr;
    std::vector<unsigned char> buffer_;
    int width_ = 0, height_ = 0;
};

} // namespace pf
