// OSMesa backend: Mesa's off-screen interface over llvmpipe. The context needs a client
// buffer to be current, but every pass renders into framebuffer objects, so a 1×1 buffer
// is enough.
#include <GL/osmesa.h>

#include <array>

#include "testbed/core/error.h"
#include "testbed/gl/context.h"

namespace testbed {
namespace {

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 8,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw GlError("osmesa: could not create an OpenGL 4.5 core context");
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(context_);
      throw GlError("osmesa: could not make the context current");
    }
    finishSetup([](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }
  std::string_view backendName() const override { return "osmesa"; }

 private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace testbed
