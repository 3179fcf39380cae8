#include "render/passes/star_pass.h"

#include "shaders/common/bindings.h"
#include "sky/nvis_weights.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <vector>

namespace skyig::render {

StarPass::StarPass()
    : program_("passes/star.vert", "passes/star.frag"), displayProgram_("passes/star_display.vert", "passes/star.frag") {
  worldToNdcLocation_ = glGetUniformLocation(program_.id(), "uWorldToNdc");
  displayWorldToNdcLocation_ = glGetUniformLocation(displayProgram_.id(), "uWorldToNdc");
  glCreateVertexArrays(1, &vao_);
  for (Instances& i : instances_) glCreateBuffers(1, &i.buffer);
  glVertexArrayBindingDivisor(vao_, 0, 1);  // one source per instance of the quad
  // Per source: direction (3 floats), then illuminance (3 floats); see instanceData().
  const GLuint attributes[][2] = {{SKYIG_ATTRIB_STAR_DIRECTION, 0}, {SKYIG_ATTRIB_STAR_REC709_LUX, 3 * sizeof(float)}};
  for (const auto& [location, offset] : attributes) {
    glEnableVertexArrayAttrib(vao_, location);
    glVertexArrayAttribFormat(vao_, location, 3, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(vao_, location, 0);
  }
}

StarPass::~StarPass() {
  for (Instances& i : instances_) glDeleteBuffers(1, &i.buffer);
  glDeleteVertexArrays(1, &vao_);
}

std::vector<const skyig::sky::night::PointSource*> StarPass::brightestFirst(const skyig::sky::night::StarField& field) {
  std::vector<const skyig::sky::night::PointSource*> sources;
  sources.reserve(field.stars.size() + field.planets.size());
  for (const auto* list : {&field.stars, &field.planets})
    for (const skyig::sky::night::PointSource& p : *list) sources.push_back(&p);
  std::stable_sort(sources.begin(), sources.end(),
                   [](const auto* a, const auto* b) { return a->illuminanceLux > b->illuminanceLux; });
  return sources;
}

std::vector<float> StarPass::instanceData(const std::vector<const skyig::sky::night::PointSource*>& sources,
                                          skyig::sky::SpectralBand band) {
  std::vector<float> data;
  data.reserve(sources.size() * 6);
  for (const skyig::sky::night::PointSource* p : sources) {
    glm::dvec3 light = p->rec709Lux;
    if (band != skyig::sky::SpectralBand::Visible)
      light = glm::dvec3(p->illuminanceLux * skyig::sky::nvisPerLuxOfBlackbody(p->temperatureK, skyig::sky::nvisClassOf(band)));
    for (double v : {p->direction.x, p->direction.y, p->direction.z, light.r, light.g, light.b})
      data.push_back(static_cast<float>(v));
  }
  return data;
}

GLsizei StarPass::prepare(const std::shared_ptr<const skyig::sky::night::StarField>& field, skyig::sky::SpectralBand band,
                          const GlProgram& program, GLint worldToNdcLocation, const glm::dmat3& ndcToWorld,
                          double floorLux) {
  if (!field) return 0;
  Instances& in = instances_[static_cast<std::size_t>(band)];
  if (field != in.field) {
    // A new store per state: states change at most at the host's rate, and the size varies.
    const std::vector<const skyig::sky::night::PointSource*> sources = brightestFirst(*field);
    const std::vector<float> data = instanceData(sources, band);
    glNamedBufferData(in.buffer, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    in.count = static_cast<GLsizei>(sources.size());
    in.lux.resize(sources.size());
    for (std::size_t i = 0; i < sources.size(); ++i) in.lux[i] = sources[i]->illuminanceLux;
    in.field = field;
  }
  // The sources above the floor: a prefix of the brightest-first instances.
  const auto above = std::partition_point(in.lux.begin(), in.lux.end(), [floorLux](double lux) { return lux > floorLux; });
  const GLsizei count = static_cast<GLsizei>(above - in.lux.begin());
  if (count == 0) return 0;
  glVertexArrayVertexBuffer(vao_, 0, in.buffer, 0, 6 * sizeof(float));
  program.use();
  const glm::mat3 worldToNdc(glm::inverse(ndcToWorld));
  glUniformMatrix3fv(worldToNdcLocation, 1, GL_FALSE, glm::value_ptr(worldToNdc));
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(vao_);
  return count;
}

void StarPass::draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                    skyig::sky::SpectralBand band) {
  // Every source, however faint: the HDR image holds the scene's light in absolute units.
  const GLsizei count = prepare(field, band, program_, worldToNdcLocation_, ndcToWorld, -1.0);
  if (count == 0) return;
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glDisable(GL_BLEND);
}

int StarPass::drawDisplayed(const std::shared_ptr<const skyig::sky::night::StarField>& field,
                            const glm::dmat3& ndcToWorld, GLuint background, double floorLux) {
  const GLsizei count =
      prepare(field, skyig::sky::SpectralBand::Visible, displayProgram_, displayWorldToNdcLocation_, ndcToWorld, floorLux);
  if (count == 0) return 0;
  glBindTextureUnit(SKYIG_UNIT_STAR_BACKGROUND, background);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glDisable(GL_BLEND);
  return count;
}

void StarPass::drawFootprints(const std::shared_ptr<const skyig::sky::night::StarField>& field,
                              const glm::dmat3& ndcToWorld, GLuint background, const GlProgram& program,
                              double floorLux) {
  const GLsizei count = prepare(field, skyig::sky::SpectralBand::Visible, program,
                                glGetUniformLocation(program.id(), "uWorldToNdc"), ndcToWorld, floorLux);
  glDisable(GL_BLEND);  // the program writes what the pixel shows, once or again: nothing adds
  if (count == 0) return;
  glBindTextureUnit(SKYIG_UNIT_STAR_BACKGROUND, background);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
}

}  // namespace skyig::render
