#pragma once
// The GL passes of stars and planets (physics/stars/star_field.h), a quad per source carrying a
// normalised PSF:
// - draw(): into the HDR target, after the sky, in absolute units: each source's energy on
//   screen equals its illuminance at any resolution and field of view (physics/stars/star_psf.glsl);
// - drawDisplayed(): into the display's point-source target, in display luminance, as the eye
//   sees them: visibility against the sky behind them kept on the display, a PSF of a fixed
//   angle (physics/eye/point_source_visibility.glsl, docs/night-sky-stars.md).
#include "render/gl/gl_program.h"
#include "sky/channel.h"
#include "physics/stars/star_field.h"

#include <glm/mat3x3.hpp>

#include <array>
#include <cstdint>
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
  // `ndcToWorld`. In a goggle's `band`, each source gives its NVIS irradiance (W m^-2) in all
  // three channels instead of its colour: its illuminance times the NVIS per lux of a blackbody
  // of its temperature (sky/nvis_weights.h), as the probe weighs it.
  // Every pass sends only the sources whose quads can touch the bound viewport (star_culling.h).
  void draw(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
            skyig::sky::SpectralBand band = skyig::sky::SpectralBand::Visible);
  // Adds the field's sources as displayed into the bound target. The frame and tone blocks must
  // be bound; `background` is the HDR image of the sky without the sources (cd/m^2). Only the
  // sources brighter than `floorLux` (illuminance at the eye) are sent to the GPU: those at or
  // below it cannot pass the eye's threshold anywhere in the view (ShownLayers::
  // pointSourceFloorLux), and the pass's own test would leave them out.
  void drawDisplayed(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                     GLuint background, double floorLux = 0.0);
  // The quads drawDisplayed() drew with the same arguments, drawn again without blending by
  // `program`: render/passes/night/star_display.vert compiled as drawDisplayed() compiles it, with another
  // fragment (the tone pass's, where the sky pass mapped its own pixels: TonePass::drawOver).
  void drawFootprints(const std::shared_ptr<const skyig::sky::night::StarField>& field, const glm::dmat3& ndcToWorld,
                      GLuint background, const GlProgram& program, double floorLux = 0.0);
  // Whether the passes leave out the sources outside the view (default); off, every source is
  // sent, as the tests compare.
  void setViewCulling(bool on) { viewCulling_ = on; }

 private:
  // The field's sources for `band`, brightest first (illuminance at the eye), so that those
  // above a floor are the first instances: 6 floats each (direction, light), and the lux.
  struct Sources {
    std::shared_ptr<const skyig::sky::night::StarField> field;
    std::uint64_t fill = 0;  // which filling of these sources (an upload names the one it holds)
    std::vector<float> data;
    std::vector<double> lux;
  };
  static void fill(Sources& sources, const skyig::sky::night::StarField& field, skyig::sky::SpectralBand band);
  // What an instance buffer holds: its sources, so an identical draw reuses it.
  struct Upload {
    GLuint buffer = 0;
    GLsizei count = 0;
    std::uint64_t fill = 0;  // Sources::fill of the band's sources it holds (0: none)
    skyig::sky::SpectralBand band = skyig::sky::SpectralBand::Visible;
    glm::dmat3 ndcToWorld{0.0};
    double floorLux = 0.0;
    int width = 0, height = 0;
    bool culled = true;
  };
  // Sends into `upload` the sources of `field` in `band` brighter than `floorLux` whose quads
  // can touch the bound viewport (unless it holds them already), sets the blending and the
  // program's view; the number of sources to draw (0: nothing).
  GLsizei prepare(Upload& upload, const std::shared_ptr<const skyig::sky::night::StarField>& field,
                  skyig::sky::SpectralBand band, const GlProgram& program, GLint worldToNdcLocation,
                  const glm::dmat3& ndcToWorld, double floorLux);

  GlProgram program_;
  GlProgram displayProgram_;
  GLint worldToNdcLocation_ = -1;
  GLint displayWorldToNdcLocation_ = -1;
  GLuint vao_ = 0;
  bool viewCulling_ = true;
  // Per band (the eye's, NVIS class A and B: a node with a goggle channel beside the eye's
  // draws both every frame), sorted once per field.
  std::array<Sources, 3> sources_{};
  // The HDR pass's buffer per band, and the displayed passes' (the eye's band only).
  std::array<Upload, 3> hdr_{};
  Upload displayed_;
  std::vector<float> inView_;  // scratch: the sources sent, reused from frame to frame
  std::uint64_t fills_ = 0;
};

}  // namespace skyig::render
