#include "render/passes/night/moon_pass.h"

#include "sky/camera.h"
#include "render/gl/mip_chain.h"
#include "sky/sky_state.h"
#include "render/glsl/bindings.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace skyig::render {

namespace {

void set3(GLuint p, const char* name, const glm::dvec3& v) {
  glProgramUniform3f(p, glGetUniformLocation(p, name), static_cast<float>(v.x), static_cast<float>(v.y),
                     static_cast<float>(v.z));
}

void set1(GLuint p, const char* name, double v) {
  glProgramUniform1f(p, glGetUniformLocation(p, name), static_cast<float>(v));
}

}  // namespace

MoonPass::MoonPass() : program_("render/passes/night/moon.vert", "render/passes/night/moon.frag") {
  glCreateVertexArrays(1, &emptyVao_);
  const skyig::sky::night::MoonAlbedo& map = skyig::sky::night::MoonAlbedo::standard();
  glCreateTextures(GL_TEXTURE_2D, 1, &albedoTexture_);
  glTextureStorage2D(albedoTexture_, mipLevelCount(map.width(), map.height()), GL_R32F, map.width(), map.height());
  // The disc spans tens of pixels, so the map is minified.
  forEachMipLevel(map.texels(), map.width(), map.height(),
                  [&](int level, int w, int h, const std::vector<float>& texels) {
                    glTextureSubImage2D(albedoTexture_, level, 0, 0, w, h, GL_RED, GL_FLOAT, texels.data());
                  });
  glTextureParameteri(albedoTexture_, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(albedoTexture_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(albedoTexture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(albedoTexture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

MoonPass::~MoonPass() {
  glDeleteTextures(1, &albedoTexture_);
  glDeleteVertexArrays(1, &emptyVao_);
}

glm::ivec4 MoonPass::draw(const skyig::sky::SkyState& state, const skyig::sky::Attitude& attitude,
                          const skyig::sky::ChannelConfig& channel) {
  // Well below the horizon (more than the largest dip of the horizon, 5 deg at 25 km) nothing
  // of it can be seen: skip the pass.
  const skyig::sky::night::MoonDisc* d = state.moonDisc.get();
  if (!d || d->centreSeen.z < -std::sin(5.5 * std::numbers::pi / 180.0)) return glm::ivec4(0);
  return draw(*d, skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(attitude, channel.offset), channel.frustum), channel);
}

glm::ivec4 MoonPass::draw(const skyig::sky::night::MoonDisc& d, const glm::dmat3& ndcToWorldMatrix,
                          const skyig::sky::ChannelConfig& channel) {
  extinction_.use(d.extinction);
  const GLuint p = program_.id();
  // The quad: the disc's radius plus three pixels for the limb ramp (the widest pixel of the
  // channel, from its frustum's largest half-angle), at least 20% for the refractive flattening.
  const double pixel = skyig::sky::largestPixelAngleRad(channel.frustum, channel.width, channel.height);
  const double halfSize = 1.2 * std::tan(d.angularRadiusRad) + 3.0 * pixel;
  const glm::dvec3 up = std::abs(d.centreSeen.z) < 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 right = glm::normalize(glm::cross(d.centreSeen, up));
  const glm::dvec3 quadUp = glm::cross(right, d.centreSeen);
  set3(p, "moonCentreSeen", d.centreSeen);
  set3(p, "quadRight", right);
  set3(p, "quadUp", quadUp);
  set1(p, "quadHalfSize", halfSize);
  const glm::dmat3 toNdc = glm::inverse(ndcToWorldMatrix);
  const glm::mat3 worldToNdc(toNdc);
  glProgramUniformMatrix3fv(p, glGetUniformLocation(p, "worldToNdc"), 1, GL_FALSE, &worldToNdc[0][0]);
  set3(p, "moonCentre", d.centre);
  set1(p, "moonSinRadius", std::sin(d.angularRadiusRad));
  set3(p, "towardSun", d.towardSun);
  set3(p, "moonNorth", d.north);
  set3(p, "moonEast", d.east);
  set3(p, "sunlitScale", d.sunlitScale);
  set3(p, "earthshineScale", d.earthshineScale);
  const glm::vec4 refraction(d.refraction);
  glProgramUniform4fv(p, glGetUniformLocation(p, "refraction"), 1, &refraction[0]);
  glBindTextureUnit(SKYIG_UNIT_MOON_ALBEDO, albedoTexture_);
  extinction_.bind(SKYIG_UNIT_MOON_EXTINCTION);
  glBindVertexArray(emptyVao_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);  // light adds: the moon in front of the sky's scattered light
  program_.use();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
  // The quad as moon.vert places it, in eye coordinates (z the depth along the view axis),
  // clipped to the half-space in front of the eye as the rasteriser clips it, then projected.
  std::array<glm::dvec3, 4> quad;
  const glm::dvec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (std::size_t i = 0; i < quad.size(); ++i)
    quad[i] = toNdc * (d.centreSeen + halfSize * (corners[i].x * right + corners[i].y * quadUp));
  constexpr double kNear = 1e-6;
  glm::dvec2 lo(1e300), hi(-1e300);
  bool inFront = false;
  const auto extend = [&](const glm::dvec3& q) {
    const glm::dvec2 px = (glm::dvec2(q) / q.z * 0.5 + 0.5) * glm::dvec2(channel.width, channel.height);
    lo = glm::min(lo, px);
    hi = glm::max(hi, px);
    inFront = true;
  };
  for (std::size_t i = 0; i < quad.size(); ++i) {
    const glm::dvec3& a = quad[i];
    const glm::dvec3& b = quad[(i + 1) % quad.size()];
    if (a.z >= kNear) extend(a);
    if ((a.z >= kNear) != (b.z >= kNear)) extend(a + (b - a) * ((kNear - a.z) / (b.z - a.z)));
  }
  if (!inFront) return glm::ivec4(0);  // behind the eye
  // A pixel of margin (the rasteriser covers the pixels whose centres are inside), clamped to
  // the channel in double before the integers.
  const auto clampTo = [](double v, int n) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(n))); };
  const int x0 = clampTo(std::floor(lo.x) - 1.0, channel.width), x1 = clampTo(std::ceil(hi.x) + 1.0, channel.width);
  const int y0 = clampTo(std::floor(lo.y) - 1.0, channel.height), y1 = clampTo(std::ceil(hi.y) + 1.0, channel.height);
  return glm::ivec4(x0, y0, x1 - x0, y1 - y0);
}

}  // namespace skyig::render
