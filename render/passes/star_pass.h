#pragma once
// The GL pass that adds stars and planets (sky/night/star_field.h) to the HDR target, after
// the sky pass: a quad per source carrying a normalised PSF, so each source's energy on screen equals its
// illuminance at any resolution and field of view (shaders/night/star_psf.glsl).
#include "render/gl/gl_program.h"
#include "sky/night/star_field.h"

#include <glm/mat3x3.hpp>

#include <memory>

namespace skyig::render {

class StarPass {
 public:
  StarPass();
  ~StarPass();
  StarPass(const StarPass&) = delete;
  StarPass& operator=(const StarPass&) = delete;

  // Adds the field's sources into the bound target. The frame block must be bound and hold
  // `ndcToWorld`. The field is uploaded when it differs from the last one drawn.
  void draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld);

 private:
  void upload(const skyig::sky::night::StarField& field);
  GlProgram program_;
  GLint worldToNdcLocation_ = -1;
  GLuint vao_ = 0;
  GLuint buffer_ = 0;
  GLsizei count_ = 0;
  std::shared_ptr<const skyig::sky::night::StarField> uploaded_;  // held so its address cannot be reused
};

}  // namespace skyig::render
