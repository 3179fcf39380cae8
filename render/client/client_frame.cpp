#include "render/client/client_frame.h"

#include "render/gl/gl_state_guard.h"
#include "render/client/client_aerial_perspective.h"
#include "render/warm_up_states.h"

#include "render/glsl/bindings.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::render {

namespace {

using skyig::kDeg;
constexpr double kMaxHalfAngleDeg = 89.0;  // sky/camera.h's Frustum

double halfAngleDeg(double tangent, const char* side) {
  const double deg = std::atan(tangent) / kDeg;
  if (!(std::abs(deg) < kMaxHalfAngleDeg))
    throw std::invalid_argument(std::string("host projection: the ") + side + " half-angle " + std::to_string(deg) +
                                " deg is not within +-89 deg");
  return deg;
}

}  // namespace

ClientCamera clientCamera(const glm::dmat4& view, const glm::dmat4& projection) {
  // The frustum (glFrustum's matrix, scaled by any positive factor): clip w = -s z_eye, and at
  // z_eye = -1 the NDC x is P00 x_eye - P20, so the edges x_ndc = +-1 lie at
  // x_eye = (+-1 + P20) / P00 (likewise y with P11, P21).
  const double s = -projection[2][3];
  const double scale = std::max({std::abs(projection[0][0]), std::abs(projection[1][1]), std::abs(s)});
  const double eps = 1e-9 * scale;
  if (!(s > eps) || std::abs(projection[3][3]) > eps || std::abs(projection[0][3]) > eps ||
      std::abs(projection[1][3]) > eps || std::abs(projection[1][0]) > eps || std::abs(projection[0][1]) > eps ||
      std::abs(projection[3][0]) > eps || std::abs(projection[3][1]) > eps)
    throw std::invalid_argument("host projection: not a perspective frustum (w = -z_eye, no skew)");
  const glm::dmat4 p = projection / s;
  if (!(p[0][0] > 0.0) || !(p[1][1] > 0.0))
    throw std::invalid_argument("host projection: a mirrored frustum (P00 or P11 not positive)");
  ClientCamera camera;
  camera.frustum.leftDeg = halfAngleDeg((1.0 - p[2][0]) / p[0][0], "left");
  camera.frustum.rightDeg = halfAngleDeg((1.0 + p[2][0]) / p[0][0], "right");
  camera.frustum.downDeg = halfAngleDeg((1.0 - p[2][1]) / p[1][1], "down");
  camera.frustum.upDeg = halfAngleDeg((1.0 + p[2][1]) / p[1][1], "up");

  // The eye's axes in ENU are the rows of the view's rotation. skyig's eye frame (CIGI: x
  // forward, y right, z down) from GL's (x right, y up, -z forward), made orthonormal.
  const glm::dmat3 eyeGlToEnu = glm::transpose(glm::dmat3(view));
  const glm::dvec3 forward = glm::normalize(-eyeGlToEnu[2]);
  glm::dvec3 right = eyeGlToEnu[0] - glm::dot(eyeGlToEnu[0], forward) * forward;
  if (!(glm::length(right) > 1e-9 * glm::length(eyeGlToEnu[0])) || !std::isfinite(glm::length(right)))
    throw std::invalid_argument("host view: the rotation is degenerate");
  right = glm::normalize(right);
  const glm::dvec3 down = glm::cross(forward, right);
  if (!(glm::dot(down, eyeGlToEnu[1]) < 0.0))
    throw std::invalid_argument("host view: a mirrored rotation (its up axis is not forward x right's opposite)");
  // sky/camera.cpp: eye -> ENU = P_ned->enu Rz(yaw) Ry(pitch) Rx(roll); take the NED swap out
  // (its own inverse) and read the Tait-Bryan angles of the rest.
  const glm::dmat3 nedToEnu = skyig::sky::bodyToEnu({});
  const glm::dmat3 n = glm::transpose(nedToEnu) * glm::dmat3(forward, right, down);
  const double sinPitch = std::clamp(-n[0][2], -1.0, 1.0);
  camera.attitude.pitchDeg = std::asin(sinPitch) / kDeg;
  if (std::sqrt(n[0][0] * n[0][0] + n[0][1] * n[0][1]) > 1e-12) {
    camera.attitude.yawDeg = std::atan2(n[0][1], n[0][0]) / kDeg;
    camera.attitude.rollDeg = std::atan2(n[1][2], n[2][2]) / kDeg;
  } else {  // looking straight up or down: yaw and roll turn about one axis; all of it as yaw
    camera.attitude.yawDeg = std::atan2(-n[1][0], n[1][1]) / kDeg;
    camera.attitude.rollDeg = 0.0;
  }
  return camera;
}

skyig::sky::ChannelConfig clientChannel(const ClientCamera& camera, const ClientViewport& viewport,
                                      const ClientFrameOptions& options) {
  for (int side : {viewport.width, viewport.height})
    if (side < skyig::sky::kMinChannelSide || side > skyig::sky::kMaxChannelSide)
      throw std::invalid_argument("host viewport: a side of " + std::to_string(side) + " pixels is not within [" +
                                  std::to_string(skyig::sky::kMinChannelSide) + ", " +
                                  std::to_string(skyig::sky::kMaxChannelSide) + "]");
  skyig::sky::ChannelConfig channel;
  channel.name = "host";
  channel.frustum = camera.frustum;
  channel.width = viewport.width;
  channel.height = viewport.height;
  channel.display = options.display;
  channel.band = options.band;
  return channel;
}

ClientFrameRenderer::ClientFrameRenderer() : program_("render/client/client_frame.vert", "render/client/client_frame.frag") {
  farNdcZLocation_ = glGetUniformLocation(program_.id(), "farNdcZ");
  viewportOriginLocation_ = glGetUniformLocation(program_.id(), "viewportOrigin");
  glCreateVertexArrays(1, &emptyVao_);  // made without binding it: the client's stays bound
}

ClientFrameRenderer::~ClientFrameRenderer() { glDeleteVertexArrays(1, &emptyVao_); }

void ClientFrameRenderer::draw(const skyig::sky::SkyState& state, const glm::dmat4& view, const glm::dmat4& projection,
                             const ClientViewport& viewport, const ClientFrameOptions& options) {
  const ClientCamera camera = clientCamera(view, projection);
  const skyig::sky::ChannelConfig channel = clientChannel(camera, viewport, options);
  const GlStateGuard guard;
  const bool hostEncodesSrgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  guard.setSkyigDefaults();
  sky_.draw(state, camera.attitude, channel);

  // The composite into the client's framebuffer, at the far plane's depth.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(guard.drawFramebuffer()));
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(options.depth == DepthConvention::Standard ? GL_LEQUAL : GL_GEQUAL);
  glDepthMask(GL_FALSE);
  // No clipping at the far plane the triangle lies on; its depth is the far plane's exactly.
  glEnable(GL_DEPTH_CLAMP);
  // Linear light is encoded as the client asked (an sRGB target it encodes); display values are
  // already encoded for the display.
  if (options.output == ClientOutput::LinearLight && hostEncodesSrgb) glEnable(GL_FRAMEBUFFER_SRGB);
  program_.use();
  // GL's default clip control and depth range (setSkyigDefaults): NDC depth 1 is window depth 1.
  glProgramUniform1f(program_.id(), farNdcZLocation_, options.depth == DepthConvention::Standard ? 1.0f : -1.0f);
  glProgramUniform2i(program_.id(), viewportOriginLocation_, viewport.x, viewport.y);
  glBindTextureUnit(SKYIG_UNIT_HOST_SOURCE,
                    options.output == ClientOutput::LinearLight ? sky_.hdrTexture() : sky_.displayTexture());
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ClientFrameRenderer::prepare(const skyig::sky::SkyState& state, const glm::dmat4& view,
                                  const glm::dmat4& projection, const ClientViewport& viewport,
                                  const ClientFrameOptions& options) {
  const ClientCamera camera = clientCamera(view, projection);
  const skyig::sky::ChannelConfig channel = clientChannel(camera, viewport, options);
  const GlStateGuard guard;
  guard.setSkyigDefaults();
  for (const skyig::sky::SkyState& s : warmUpStates(state, {options.display}))
    for (const skyig::sky::Attitude& a : warmUpAttitudes(s, camera.attitude)) sky_.draw(s, a, channel);
  glFinish();  // a driver may compile at the first draw rather than at the link: done by now
}

GLuint ClientFrameRenderer::drawTexture(const skyig::sky::SkyState& state, const glm::dmat4& view,
                                      const glm::dmat4& projection, int width, int height,
                                      const ClientFrameOptions& options) {
  const ClientCamera camera = clientCamera(view, projection);
  const skyig::sky::ChannelConfig channel = clientChannel(camera, ClientViewport{0, 0, width, height}, options);
  const GlStateGuard guard;
  guard.setSkyigDefaults();
  sky_.draw(state, camera.attitude, channel);
  return options.output == ClientOutput::LinearLight ? sky_.hdrTexture() : sky_.displayTexture();
}

void ClientFrameRenderer::bindAerialPerspective(const skyig::sky::SkyState& state, GLuint program, int firstUnit) {
  if (state.conditions.model != skyig::sky::SkyModel::Physical || !state.conditions.atmosphere)
    throw std::invalid_argument("aerial perspective needs the physical sky");
  const PhysicalSkyPass* pass = sky_.physicalPass();
  if (!pass || !pass->tables().model || aerial_.needsUpload(pass->tables())) {
    const GlStateGuard guard;  // compiling the pass, uploading tables
    guard.setSkyigDefaults();
    pass = &sky_.physicalPassFor(state);
    aerial_.upload(pass->tables());
  }
  aerial_.bind(pass->tables(), state, program, firstUnit);
}

}  // namespace skyig::render
