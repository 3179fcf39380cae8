#pragma once
// The GL passes of stars and planets (sky/night/star_field.h), a quad per source carrying a
// normalised PSF:
// - draw(): into the HDR target, after the sky, in absolute units: each source's energy on
//   screen equals its illuminance at any resolution and field of view (shaders/night/star_psf.glsl);
// - drawDisplayed(): into the display's point-source target, in display luminance, as the eye
//   sees them: visibility against the sky behind them kept on the display, a PSF of a fixed
//   angle (shaders/night/point_source_visibility.glsl, docs/night-sky-stars.md).
#include "render/gl/gl_program.h"
#include "sky/channel.h"
#include "sky/night/star_field.h"

#include <glm/mat3x3.hpp>

#include <array>
#include <memory>
#include <vector>

namespace skyig::render {

class StarPass {
 public:
  StarPass();
  ~StarPass();
  StarPass(const StarPass&) = delete;
  StarPass& operator=(const StarPass&) = delete;

  // Adds the field's sources into the bound target. The frame block must be bound and hold
  // `ndcToWorld`. The field is uploaded when it differs from the last one drawn. In a goggle's
  // `band`, each source gives its NVIS irradiance (W m^-2) in all three channels instead of its
  // colour: its illuminance times the NVIS per lux of a blackbody of its temperature
  // (sky/nvis_weights.h), as the probe weighs it.
  void draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
            skyig::sky::SpectralBand band = skyig::sky::SpectralBand::Visible);
  // Adds the field's sources as displayed into the bound target. The frame and tone blocks must
  // be bound; `background` is the HDR image of the sky without the sources (cd/m^2). Only the
  // sources brighter than `floorLux` (illuminance at the eye) are sent to the GPU: those at or
  // below it cannot pass the eye's threshold anywhere in the view (ShownLayers::
  // pointSourceFloorLux), and the pass's own test would leave them out. Returns how many were sent.
  int drawDisplayed(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                    GLuint background, double floorLux = 0.0);
  // The quads drawDisplayed() drew with the same arguments, drawn again without blending by
  // `program`: passes/star_display.vert compiled as drawDisplayed() compiles it, with another
  // fragment (the tone pass's, where the sky pass mapped its own pixels: TonePass::drawOver).
  void drawFootprints(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                      GLuint background, const GlProgram& program, double floorLux = 0.0);

 private:
  // The field's sources, brightest first (illuminance at the eye), so that those above a floor
  // are the first instances.
  static std::vector<const skyig::sky::night::PointSource*> brightestFirst(const skyig::sky::night::StarField& field);
  static std::vector<float> instanceData(const std::vector<const skyig::sky::night::PointSource*>& sources,
                                         skyig::sky::SpectralBand band);
  // Uploads a new field for `band`, sets the blending and the program's view; the number of
  // sources brighter than `floorLux` to draw (0: nothing).
  GLsizei prepare(const std::shared_ptr<const skyig::sky::night::StarField>& field, skyig::sky::SpectralBand band,
                  const GlProgram& program, GLint worldToNdcLocation, const glm::dmat3& ndcToWorld, double floorLux);
  GlProgram program_;
  GlProgram displayProgram_;
  GLint worldToNdcLocation_ = -1;
  GLint displayWorldToNdcLocation_ = -1;
  GLuint vao_ = 0;
  // One instance buffer per band (the eye's, NVIS class A and B): a node with a goggle channel
  // beside the eye's draws both every frame, and each is uploaded once per field.
  struct Instances {
    GLuint buffer = 0;
    GLsizei count = 0;
    std::vector<double> lux;  // each instance's illuminance at the eye, brightest first
    std::shared_ptr<const skyig::sky::night::StarField> field;  // held so its address cannot be reused
  };
  std::array<Instances, 3> instances_{};
};

}  // namespace skyig::render
