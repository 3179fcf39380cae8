#include "render/passes/night/star_pass.h"

#include "render/passes/night/star_culling.h"
#include "render/glsl/bindings.h"
#include "sky/nvis_weights.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace skyig::render {

StarPass::StarPass()
    : program_("render/passes/night/star.vert", "render/passes/night/star.frag"), displayProgram_("render/passes/night/star_display.vert", "render/passes/night/star.frag") {
  worldToNdcLocation_ = glGetUniformLocation(program_.id(), "uWorldToNdc");
  displayWorldToNdcLocation_ = glGetUniformLocation(displayProgram_.id(), "uWorldToNdc");
  glCreateVertexArrays(1, &vao_);
  for (Upload& u : hdr_) glCreateBuffers(1, &u.buffer);
  glCreateBuffers(1, &displayed_.buffer);
  glVertexArrayBindingDivisor(vao_, 0, 1);  // one source per instance of the quad
  // Per source: direction (3 floats), then illuminance (3 floats); see fill().
  const GLuint attributes[][2] = {{SKYIG_ATTRIB_STAR_DIRECTION, 0}, {SKYIG_ATTRIB_STAR_REC709_LUX, 3 * sizeof(float)}};
  for (const auto& [location, offset] : attributes) {
    glEnableVertexArrayAttrib(vao_, location);
    glVertexArrayAttribFormat(vao_, location, 3, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(vao_, location, 0);
  }
}

StarPass::~StarPass() {
  for (Upload& u : hdr_) glDeleteBuffers(1, &u.buffer);
  glDeleteBuffers(1, &displayed_.buffer);
  glDeleteVertexArrays(1, &vao_);
}

void StarPass::fill(Sources& sources, const skyig::sky::night::StarField& field, skyig::sky::SpectralBand band) {
  std::vector<const skyig::sky::night::PointSource*> sorted;
  sorted.reserve(field.stars.size() + field.planets.size());
  for (const auto* list : {&field.stars, &field.planets})
    for (const skyig::sky::night::PointSource& p : *list) sorted.push_back(&p);
  // A source without a finite illuminance sorts last, below every floor, and is not drawn (a
  // NaN key would break the ordering and a NaN light every pixel it touched).
  auto key = [](const skyig::sky::night::PointSource* p) {
    return std::isfinite(p->illuminanceLux) ? p->illuminanceLux : -1.0;
  };
  std::stable_sort(sorted.begin(), sorted.end(), [&key](const auto* a, const auto* b) { return key(a) > key(b); });
  sources.data.clear();
  sources.lux.clear();
  for (const skyig::sky::night::PointSource* p : sorted) {
    glm::dvec3 light = p->rec709Lux;
    if (band != skyig::sky::SpectralBand::Visible)
      light = glm::dvec3(p->illuminanceLux * skyig::sky::nvisPerLuxOfBlackbody(p->temperatureK, skyig::sky::nvisClassOf(band)));
    for (double v : {p->direction.x, p->direction.y, p->direction.z, light.r, light.g, light.b})
      sources.data.push_back(static_cast<float>(v));
    sources.lux.push_back(key(p));
  }
}

GLsizei StarPass::prepare(Upload& upload, const std::shared_ptr<const skyig::sky::night::StarField>& field,
                          skyig::sky::SpectralBand band, const GlProgram& program, GLint worldToNdcLocation,
                          const glm::dmat3& ndcToWorld, double floorLux) {
  if (!field) return 0;
  Sources& sources = sources_[static_cast<std::size_t>(band)];
  if (field != sources.field) {
    fill(sources, *field, band);
    sources.field = field;
    sources.fill = ++fills_;
  }
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const glm::dmat3 worldToNdc = glm::inverse(ndcToWorld);
  if (upload.fill != sources.fill || upload.band != band || upload.ndcToWorld != ndcToWorld ||
      upload.floorLux != floorLux || upload.width != viewport[2] || upload.height != viewport[3] ||
      upload.culled != viewCulling_) {
    // The sources above the floor: a prefix of the brightest-first list; of those, the ones
    // whose quads can touch the viewport.
    const std::size_t above = static_cast<std::size_t>(
        std::partition_point(sources.lux.begin(), sources.lux.end(), [floorLux](double lux) { return lux > floorLux; }) -
        sources.lux.begin());
    const double reachPx = starQuadReachPx(ndcToWorld, std::max(viewport[2], 1), std::max(viewport[3], 1));
    const double reachX = 2.0 * reachPx / std::max(viewport[2], 1), reachY = 2.0 * reachPx / std::max(viewport[3], 1);
    inView_.clear();
    for (std::size_t i = 0; i < above; ++i) {
      const float* f = &sources.data[6 * i];
      if (viewCulling_ && !starMayBeInView(worldToNdc, glm::dvec3(f[0], f[1], f[2]), reachX, reachY)) continue;
      inView_.insert(inView_.end(), f, f + 6);
    }
    // A new store each time (GL orphans the old one while a draw may still read it).
    glNamedBufferData(upload.buffer, static_cast<GLsizeiptr>(inView_.size() * sizeof(float)), inView_.data(),
                      GL_STREAM_DRAW);
    upload.count = static_cast<GLsizei>(inView_.size() / 6);
    upload.fill = sources.fill;
    upload.band = band;
    upload.ndcToWorld = ndcToWorld;
    upload.floorLux = floorLux;
    upload.width = viewport[2];
    upload.height = viewport[3];
    upload.culled = viewCulling_;
  }
  if (upload.count == 0) return 0;
  glVertexArrayVertexBuffer(vao_, 0, upload.buffer, 0, 6 * sizeof(float));
  program.use();
  const glm::mat3 worldToNdcF(worldToNdc);
  glUniformMatrix3fv(worldToNdcLocation, 1, GL_FALSE, glm::value_ptr(worldToNdcF));
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(vao_);
  return upload.count;
}

void StarPass::draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                    skyig::sky::SpectralBand band) {
  // Every source, however faint: the HDR image holds the scene's light in absolute units.
  const GLsizei count =
      prepare(hdr_[static_cast<std::size_t>(band)], field, band, program_, worldToNdcLocation_, ndcToWorld, -1.0);
  if (count == 0) return;
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glDisable(GL_BLEND);
}

void StarPass::drawDisplayed(const std::shared_ptr<const skyig::sky::night::StarField>& field,
                             const glm::dmat3& ndcToWorld, GLuint background, double floorLux) {
  const GLsizei count = prepare(displayed_, field, skyig::sky::SpectralBand::Visible, displayProgram_,
                                displayWorldToNdcLocation_, ndcToWorld, floorLux);
  if (count == 0) return;
  glBindTextureUnit(SKYIG_UNIT_STAR_BACKGROUND, background);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glDisable(GL_BLEND);
}

void StarPass::drawFootprints(const std::shared_ptr<const skyig::sky::night::StarField>& field,
                              const glm::dmat3& ndcToWorld, GLuint background, const GlProgram& program,
                              double floorLux) {
  // The displayed pass's own buffer: the same sources, unless the arguments differ.
  const GLsizei count = prepare(displayed_, field, skyig::sky::SpectralBand::Visible, program,
                                glGetUniformLocation(program.id(), "uWorldToNdc"), ndcToWorld, floorLux);
  glDisable(GL_BLEND);  // the program writes what the pixel shows, once or again: nothing adds
  if (count == 0) return;
  glBindTextureUnit(SKYIG_UNIT_STAR_BACKGROUND, background);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
}

}  // namespace skyig::render
