#pragma once
// Draws the sky into a client image generator's frame (docs/client-frame.md): with the client's GL
// context current, for the client's camera given as GL view and projection matrices, into the
// framebuffer the client has bound as GL_DRAW_FRAMEBUFFER, only where the client's depth buffer is
// still at the far plane (behind everything the client drew), for standard depth and reverse-Z.
//
// Conventions. World: the local east-north-up frame at the observer (x east, y north, z up,
// metres); the view matrix takes it to GL's eye space (x right, y up, -z forward). Only the
// view's rotation counts: the sky is at infinity, and the observer's position is the state's.
// The projection is a GL perspective (glFrustum's form, w = -z_eye, any near/far, infinite or
// reverse-Z), possibly off-axis; orthographic, skewed or mirrored cameras are refused.
//
// GL state: every piece the draw changes is saved and restored (render/gl/gl_state_guard.h
// lists it); the client's framebuffer gets colour (RGB of the sky, alpha 1) where the depth test
// passes and nothing else: no depth, no stencil.
#include "render/gl/gl_program.h"
#include "render/client/client_aerial_perspective.h"
#include "render/sky_renderer.h"
#include "sky/camera.h"
#include "sky/channel.h"
#include "sky/sky_state.h"

#include <glad/gl.h>
#include <glm/glm.hpp>

namespace skyig::render {

// How the client's depth buffer marks "nothing drawn here".
enum class DepthConvention {
  Standard,  // far plane at window depth 1 (cleared to 1, GL_LESS/GL_LEQUAL): the sky where depth == 1
  ReverseZ,  // far plane at window depth 0 (cleared to 0, GL_GREATER/GL_GEQUAL): the sky where depth == 0
};

// What the client's framebuffer receives.
enum class ClientOutput {
  DisplayReferred,  // skyig's tone-mapped display values (its tone pass), written unchanged (no sRGB encoding)
  LinearLight,      // the sky's radiance in cd/m^2, linear Rec.709 (a float target; the client tone-maps)
};

// The client's viewport in window pixels (glViewport's arguments); the channel renders at its size.
struct ClientViewport {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

struct ClientFrameOptions {
  DepthConvention depth = DepthConvention::Standard;
  ClientOutput output = ClientOutput::DisplayReferred;
  skyig::sky::DisplayParams display;  // the tone pass's display (DisplayReferred)
  skyig::sky::SpectralBand band = skyig::sky::SpectralBand::Visible;
};

// The skyig camera of a client camera: the eye's attitude in the ENU frame (as an ownship
// attitude with no channel offset) and the frustum's half-angles. An off-axis frustum whose
// forward axis lies outside it has a negative half-angle on that side.
struct ClientCamera {
  skyig::sky::Attitude attitude;
  skyig::sky::Frustum frustum;
};

// Throws std::invalid_argument for a view that is not a rotation (times a uniform scale and a
// translation) or a projection that is not a perspective frustum with half-angles under 89 deg.
ClientCamera clientCamera(const glm::dmat4& view, const glm::dmat4& projection);

// The channel SkyRenderer draws for the client: the camera's frustum at the viewport's size.
skyig::sky::ChannelConfig clientChannel(const ClientCamera& camera, const ClientViewport& viewport,
                                      const ClientFrameOptions& options);

class ClientFrameRenderer {
 public:
  // Needs the client's GL context current, now and for every call.
  ClientFrameRenderer();
  ~ClientFrameRenderer();
  ClientFrameRenderer(const ClientFrameRenderer&) = delete;
  ClientFrameRenderer& operator=(const ClientFrameRenderer&) = delete;

  // Renders the channel of the client camera into skyig's own targets (SkyRenderer::draw), then
  // draws one triangle at the far plane's depth into the client's draw framebuffer, depth test
  // on (GL_LEQUAL for standard depth, GL_GEQUAL for reverse-Z), depth writes off, blending
  // off. Throws std::invalid_argument for a camera clientCamera refuses or a viewport side
  // outside [kMinChannelSide, kMaxChannelSide]; the client's state is restored either way.
  void draw(const skyig::sky::SkyState& state, const glm::dmat4& view, const glm::dmat4& projection,
            const ClientViewport& viewport, const ClientFrameOptions& options = {});

  // Renders the client camera's channel at width x height into skyig's own targets and returns
  // the texture the client composites itself: RGBA32F cd/m^2 (LinearLight) or RGBA8 display
  // values, valid until the next call. The client's GL state is restored as by draw.
  GLuint drawTexture(const skyig::sky::SkyState& state, const glm::dmat4& view, const glm::dmat4& projection,
                     int width, int height, const ClientFrameOptions& options = {});
  // Compiles, before the first frame needs them, the programs of `state`'s day for this camera
  // and viewport: draws its lights and weathers (render/warm_up_states.h) into skyig's own
  // targets, nothing into the client's framebuffer, its GL state restored. Seconds on llvmpipe;
  // without it the first dusk, night or fog costs its frame the compile.
  void prepare(const skyig::sky::SkyState& state, const glm::dmat4& view, const glm::dmat4& projection,
               const ClientViewport& viewport, const ClientFrameOptions& options = {});
  // The eye adaptation skyig's tone mapping used (cd/m^2), for a client that tone-maps the linear
  // output itself and wants the same exposure.
  static double adaptationLuminance(const skyig::sky::SkyState& state) { return state.worldAdaptationLuminance; }

  // Aerial perspective in the client's own shaders (render/client/client_aerial_perspective.h): binds the
  // physical sky's tables, those the sky is drawn with, to texture units firstUnit ..
  // firstUnit + ClientAerialPerspective::kUnits - 1 and sets `program`'s skyig_ uniforms for
  // `state`. Before the first draw the tables are uploaded now (the client's GL state saved and
  // restored around it); after it, a new weather's tables reach the GPU over the next draws, as
  // the drawn sky's do. Throws std::invalid_argument under an analytic sky, and as
  // ClientAerialPerspective::bind.
  void bindAerialPerspective(const skyig::sky::SkyState& state, GLuint program, int firstUnit);

  // The renderer behind it: its last channel's images (readHdr, readDisplay) are the last draw's.
  const SkyRenderer& skyRenderer() const { return sky_; }

 private:
  SkyRenderer sky_;
  ClientAerialPerspective aerial_;
  GlProgram program_;
  GLint farNdcZLocation_ = -1;
  GLint viewportOriginLocation_ = -1;
  GLuint emptyVao_ = 0;
};

}  // namespace skyig::render
