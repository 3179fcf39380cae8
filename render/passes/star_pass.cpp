#include "render/passes/star_pass.h"

#include "shaders/common/bindings.h"
#include "sky/nvis_weights.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace skyig::render {

StarPass::StarPass()
    : program_("passes/star.vert", "passes/star.frag"), displayProgram_("passes/star_display.vert", "passes/star.frag") {
  worldToNdcLocation_ = glGetUniformLocation(program_.id(), "uWorldToNdc");
  displayWorldToNdcLocation_ = glGetUniformLocation(displayProgram_.id(), "uWorldToNdc");
  glCreateVertexArrays(1, &vao_);
  glCreateBuffers(1, &buffer_);
  glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, 6 * sizeof(float));
  glVertexArrayBindingDivisor(vao_, 0, 1);  // one source per instance of the quad
  // Per source: direction (3 floats), then illuminance (3 floats); see upload().
  const GLuint attributes[][2] = {{SKYIG_ATTRIB_STAR_DIRECTION, 0}, {SKYIG_ATTRIB_STAR_REC709_LUX, 3 * sizeof(float)}};
  for (const auto& [location, offset] : attributes) {
    glEnableVertexArrayAttrib(vao_, location);
    glVertexArrayAttribFormat(vao_, location, 3, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(vao_, location, 0);
  }
}

StarPass::~StarPass() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vao_);
}

void StarPass::upload(const skyig::sky::night::StarField& field, skyig::sky::SpectralBand band) {
  std::vector<float> data;
  data.reserve((field.stars.size() + field.planets.size()) * 6);
  for (const auto* list : {&field.stars, &field.planets})
    for (const skyig::sky::night::PointSource& p : *list) {
      glm::dvec3 light = p.rec709Lux;
      if (band != skyig::sky::SpectralBand::Visible)
        light = glm::dvec3(p.illuminanceLux * skyig::sky::nvisPerLuxOfBlackbody(p.temperatureK, skyig::sky::nvisClassOf(band)));
      for (double v : {p.direction.x, p.direction.y, p.direction.z, light.r, light.g, light.b})
        data.push_back(static_cast<float>(v));
    }
  // A new store per state: states change at most at the host's rate, and the size varies.
  glNamedBufferData(buffer_, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
  count_ = static_cast<GLsizei>(data.size() / 6);
}

bool StarPass::prepare(const std::shared_ptr<const skyig::sky::night::StarField>& field, skyig::sky::SpectralBand band,
                       const GlProgram& program, GLint worldToNdcLocation, const glm::dmat3& ndcToWorld) {
  if (!field) return false;
  if (field != uploaded_ || band != uploadedBand_) {
    upload(*field, band);
    uploaded_ = field;
    uploadedBand_ = band;
  }
  if (count_ == 0) return false;
  program.use();
  const glm::mat3 worldToNdc(glm::inverse(ndcToWorld));
  glUniformMatrix3fv(worldToNdcLocation, 1, GL_FALSE, glm::value_ptr(worldToNdc));
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(vao_);
  return true;
}

void StarPass::draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                    skyig::sky::SpectralBand band) {
  if (!prepare(field, band, program_, worldToNdcLocation_, ndcToWorld)) return;
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count_);
  glDisable(GL_BLEND);
}

void StarPass::drawDisplayed(const std::shared_ptr<const skyig::sky::night::StarField>& field,
                             const glm::dmat3& ndcToWorld, GLuint background) {
  if (!prepare(field, skyig::sky::SpectralBand::Visible, displayProgram_, displayWorldToNdcLocation_, ndcToWorld)) return;
  glBindTextureUnit(SKYIG_UNIT_STAR_BACKGROUND, background);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count_);
  glDisable(GL_BLEND);
}

}  // namespace skyig::render
