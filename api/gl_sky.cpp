// The public SkyDraw: render::ClientFrameRenderer (render/client/client_frame.h) behind the public types.
#include "skyig/gl_sky.h"

#include "api/sky_impl.h"
#include "render/client/client_aerial_perspective.h"
#include "render/client/client_frame.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>

namespace skyig {

struct SkyDraw::Impl {
  render::ClientFrameRenderer renderer;
};

namespace {

glm::dmat4 matrix(const float* m, const char* name) {
  if (!m) throw Error(std::string("skyig::SkyDraw: the ") + name + " matrix is null");
  return glm::dmat4(glm::make_mat4(m));
}

render::ClientFrameOptions options(const Sky& sky, const DrawOptions& o) {
  render::ClientFrameOptions r;
  r.depth = o.depth == DepthConvention::ReverseZ ? render::DepthConvention::ReverseZ : render::DepthConvention::Standard;
  r.output = o.output == Output::LinearLight ? render::ClientOutput::LinearLight : render::ClientOutput::DisplayReferred;
  // The configuration's first channel's display (its tone curve's): the one its worker maps for.
  const auto channels = sky.impl().config.channelsOf(sky.impl().config.nodeName);
  if (!channels.empty()) r.display = channels.front().display;
  return r;
}

}  // namespace

SkyDraw::SkyDraw(GlProcAddress getProcAddress) {
  if (!getProcAddress) throw Error("skyig::SkyDraw: getProcAddress is null");
  // glad is the library's own (hidden) copy: the host's loader, whatever it is, is not touched.
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress)))
    throw Error("skyig::SkyDraw: no OpenGL context is current, or it cannot load OpenGL 4.5 core functions");
  try {
    impl_ = std::make_unique<Impl>();
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw: ") + e.what());
  }
}

SkyDraw::~SkyDraw() = default;

void SkyDraw::draw(const Sky& sky, const float* view, const float* projection, const Viewport& viewport,
                   const DrawOptions& o) {
  try {
    impl_->renderer.draw(sky.impl().state, matrix(view, "view"), matrix(projection, "projection"),
                         render::ClientViewport{viewport.x, viewport.y, viewport.width, viewport.height}, options(sky, o));
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw::draw: ") + e.what());
  }
}

void SkyDraw::prepare(const Sky& sky, const float* view, const float* projection, const Viewport& viewport,
                      const DrawOptions& o) {
  try {
    impl_->renderer.prepare(sky.impl().state, matrix(view, "view"), matrix(projection, "projection"),
                            render::ClientViewport{viewport.x, viewport.y, viewport.width, viewport.height},
                            options(sky, o));
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw::prepare: ") + e.what());
  }
}

unsigned SkyDraw::texture(const Sky& sky, const float* view, const float* projection, int width, int height,
                          Output output) {
  try {
    return impl_->renderer.drawTexture(sky.impl().state, matrix(view, "view"), matrix(projection, "projection"), width,
                                       height, options(sky, DrawOptions{DepthConvention::Standard, output}));
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw::texture: ") + e.what());
  }
}

std::string SkyDraw::aerialPerspectiveGlsl() {
  try {
    return render::clientAerialPerspectiveGlsl();
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw::aerialPerspectiveGlsl: ") + e.what());
  }
}

void SkyDraw::bindAerialPerspective(const Sky& sky, unsigned program, int firstTextureUnit) {
  try {
    impl_->renderer.bindAerialPerspective(sky.impl().state, program, firstTextureUnit);
  } catch (const std::exception& e) {
    throw Error(std::string("skyig::SkyDraw::bindAerialPerspective: ") + e.what());
  }
}

}  // namespace skyig
