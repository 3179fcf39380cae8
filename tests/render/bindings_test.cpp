// The numbers that tie a pass's C++ to its GLSL (uniform-block bindings, texture and image units,
// attribute and output locations) are named once, in render/glsl/bindings.h. These tests
// check that both sides use those names and agree: every program the renderer links reports,
// for each of its samplers, images, blocks, inputs and outputs, the number the header gives
// the C++ that binds it; and neither the shaders nor the renderer's C++ binds by a bare number.
#include "render/gl/embedded_shaders.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_program.h"
#include "render/glsl/bindings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace skyig::render;

namespace {

// What a program should report, by kind and GLSL name. `mayBeInactive`: the compiler may drop
// it from this program (declared in a shared include, or read only by a vertex-stage output
// that the fragment stage ignores); when it is active its number must still match.
struct Expect {
  std::string kind;
  std::string name;
  GLint value;
  bool mayBeInactive = false;
};

Expect sampler(const char* name, GLint unit) { return {"sampler", name, unit}; }
Expect image(const char* name, GLint unit) { return {"image", name, unit}; }
Expect block(const char* name, GLint binding) { return {"uniform block", name, binding}; }
Expect input(const char* name, GLint location) { return {"input", name, location}; }
Expect output(const char* name, GLint location) { return {"output", name, location}; }
Expect optional(Expect e) {
  e.mayBeInactive = true;
  return e;
}

// Every program the renderer links, with the units its C++ binds (render/sky_renderer.cpp,
// render/passes/*.cpp). One file: a compute program.
struct ProgramCase {
  std::vector<std::string> files;
  std::vector<Expect> expect;
  std::string defines = {};  // a variant of the files (assembleShader)
};

std::vector<ProgramCase> programs() {
  const Expect frame = block("FrameBlock", SKYIG_BINDING_FRAME);
  const Expect radiance = output("outRadiance", SKYIG_OUTPUT_COLOR);
  const Expect band = block("BandBlock", SKYIG_BINDING_BAND);
  // The physical sky pass's inputs; what a variant does not read is allowed to be inactive (the
  // 3D tables always are inside the atmosphere: it reads this frame's slices of them).
  auto physicalSky = [&](bool transmittance, bool irradiance, bool moon, bool sun = true) {
    auto needed = [](bool read, Expect e) { return read ? e : optional(e); };
    // The band block: every variant reads it but the frozen reference, which predates it.
    return std::vector<Expect>{frame, optional(band),
                               needed(transmittance, sampler("transmittanceXyz", SKYIG_UNIT_TRANSMITTANCE)),
                               optional(sampler("scatteringPacked", SKYIG_UNIT_SCATTERING)),
                               optional(sampler("singleMieRG", SKYIG_UNIT_SINGLE_MIE)),
                               needed(irradiance, sampler("irradianceXyz", SKYIG_UNIT_IRRADIANCE)),
                               needed(sun, sampler("sunSliceScattering", SKYIG_UNIT_SUN_SLICE_SCATTERING)),
                               needed(sun, sampler("sunSliceSingleMie", SKYIG_UNIT_SUN_SLICE_SINGLE_MIE)),
                               needed(moon, sampler("moonSliceScattering", SKYIG_UNIT_MOON_SLICE_SCATTERING)),
                               needed(moon, sampler("moonSliceSingleMie", SKYIG_UNIT_MOON_SLICE_SINGLE_MIE)),
                               radiance};
  };
  // A variant's inputs: its sky's and what its defines add.
  auto with = [](std::vector<Expect> e, std::initializer_list<Expect> more) {
    e.insert(e.end(), more);
    return e;
  };
  std::vector<ProgramCase> cases = {
      // SkyRenderer: the analytic sky and the tone pass.
      {{"render/glsl/fullscreen.vert", "render/passes/sky/analytic_sky.frag"},
       {frame, block("AnalyticSkyBlock", SKYIG_BINDING_SKY), band, radiance}},
      {{"render/glsl/fullscreen.vert", "render/passes/tone/tone.frag"},
       {optional(frame), block("ToneBlock", SKYIG_BINDING_TONE), sampler("hdrImage", SKYIG_UNIT_HDR_IMAGE),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 2\n#define SKYIG_PHOTOPIC\n"},
      {{"render/glsl/fullscreen.vert", "render/passes/tone/tone.frag"},
       {optional(frame), block("ToneBlock", SKYIG_BINDING_TONE), sampler("hdrImage", SKYIG_UNIT_HDR_IMAGE),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_TUMBLIN_RUSHMEIER\n"},
      // TonePass: the veil read from its grid, and the grid's veil.
      {{"render/glsl/fullscreen.vert", "render/passes/tone/tone.frag"},
       {optional(frame), block("ToneBlock", SKYIG_BINDING_TONE), sampler("hdrImage", SKYIG_UNIT_HDR_IMAGE),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), sampler("glareVeilGrid", SKYIG_UNIT_GLARE_VEIL),
        output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX 8.0\n"},
      // The same on a night whose layer holds the veil (the tone pass over every pixel: the sky
      // from space).
      {{"render/glsl/fullscreen.vert", "render/passes/tone/tone.frag"},
       {optional(frame), block("ToneBlock", SKYIG_BINDING_TONE), sampler("hdrImage", SKYIG_UNIT_HDR_IMAGE),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
        output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n#define SKYIG_GLARE_FROM_NIGHT_LAYER\n"
       "#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n"},
      {{"render/glsl/fullscreen.vert", "render/passes/tone/glare_veil.frag"},
       {frame, block("ToneBlock", SKYIG_BINDING_TONE), output("outVeil", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_GLARE 2\n#define SKYIG_GLARE_CELL_PX 8.0\n"},
      // PhysicalSkyPass: inside the atmosphere, from space, and this frame's slices.
      // The warp-and-blend pass of a projector (WarpBlendPass): two outputs at once.
      {{"render/glsl/fullscreen.vert", "render/passes/projector/warp_blend.frag"},
       {optional(frame), block("ProjectorBlock", SKYIG_BINDING_PROJECTOR),
        sampler("channelDisplay", SKYIG_UNIT_CHANNEL_DISPLAY), sampler("channelHdr", SKYIG_UNIT_CHANNEL_HDR),
        sampler("warpMap", SKYIG_UNIT_PROJECTOR_WARP), sampler("alphaMap", SKYIG_UNIT_PROJECTOR_ALPHA),
        sampler("betaMap", SKYIG_UNIT_PROJECTOR_BETA), output("outDisplay", SKYIG_OUTPUT_PROJECTOR_DISPLAY),
        output("outLight", SKYIG_OUTPUT_PROJECTOR_LIGHT)}},
      // The composite into a host's framebuffer (ClientFrameRenderer).
      {{"render/client/client_frame.vert", "render/client/client_frame.frag"},
       {sampler("hostSource", SKYIG_UNIT_HOST_SOURCE), output("outColor", SKYIG_OUTPUT_COLOR)}},
      // Its variants (render/passes/sky/physical_sky.frag) and the frozen reference of the pass
      // (render/passes/sky/reference_sky_pass.h), through the same inputs: the transmittance is
      // read by the ground's reflection and the disc, the irradiance by the ground's, the
      // moon's slices by the moonlit variants.
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"}, physicalSky(true, true, false)},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"}, physicalSky(true, true, true), "#define SKYIG_MOONLIT\n"},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"}, physicalSky(false, false, false), "#define SKYIG_SKY\n"},
      {{"render/passes/sky/ground_cap.vert", "render/passes/sky/physical_sky.frag"},
       physicalSky(true, true, true),
       "#define SKYIG_MOONLIT\n#define SKYIG_GROUND\n"},
      {{"render/passes/sky/sun_disc.vert", "render/passes/sky/physical_sky.frag"},
       physicalSky(true, true, true),
       "#define SKYIG_MOONLIT\n#define SKYIG_SUN_DISC\n"},
      {{"render/passes/sky/sun_disc.vert", "render/passes/sky/physical_sky.frag"},
       physicalSky(true, false, false),
       "#define SKYIG_SKY\n#define SKYIG_SUN_DISC\n"},
      // The sky's variant that maps its own pixels to the display (SkyRenderer::drawChannel):
      // the tone block, the veil's grid, the display values beside the light.
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(false, false, false),
            {block("ToneBlock", SKYIG_BINDING_TONE), sampler("glareVeilGrid", SKYIG_UNIT_GLARE_VEIL),
             output("outDisplay", SKYIG_OUTPUT_FOLDED_DISPLAY)}),
       "#define SKYIG_SKY\n#define SKYIG_FOLD_TONE\n#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 2\n"
       "#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX 8.0\n"},
      // The same in a box of the exact veil, here the disc's (PhysicalSkyPass::draw, FoldedTone):
      // the veil per pixel, no grid.
      {{"render/passes/sky/sun_disc.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(true, false, false),
            {block("ToneBlock", SKYIG_BINDING_TONE), output("outDisplay", SKYIG_OUTPUT_FOLDED_DISPLAY)}),
       "#define SKYIG_SKY\n#define SKYIG_SUN_DISC\n#define SKYIG_FOLD_TONE\n#define SKYIG_TONE_CURVE\n"
       "#define SKYIG_GLARE 2\n"},
      // With the night's layer added (SkyRenderer::drawChannel at night): the ground's and the
      // band's near the horizon with the transmittance per pixel, the sky above reading the layer
      // already dimmed (no table); the sun's sky left out, the moon's in.
      {{"render/passes/sky/ground_cap.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(true, true, false),
            {sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
             sampler("nightExtinction", SKYIG_UNIT_NIGHT_LAYER_EXTINCTION)}),
       "#define SKYIG_GROUND\n#define SKYIG_NIGHT_LAYER\n#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n"},
      {{"render/passes/sky/ground_cap.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(false, false, true, false),
            {sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
             sampler("nightExtinction", SKYIG_UNIT_NIGHT_LAYER_EXTINCTION)}),
       "#define SKYIG_MOONLIT\n#define SKYIG_SKY\n#define SKYIG_HORIZON_BAND\n#define SKYIG_SUNLESS\n"
       "#define SKYIG_NIGHT_LAYER\n#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n"},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(false, false, true, false),
            {sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
             optional(sampler("nightExtinction", SKYIG_UNIT_NIGHT_LAYER_EXTINCTION))}),
       "#define SKYIG_MOONLIT\n#define SKYIG_SKY\n#define SKYIG_SUNLESS\n#define SKYIG_NIGHT_LAYER\n"
       "#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n#define SKYIG_NIGHT_LAYER_TRANSMITTED\n"},
      // The same mapping its pixels with the moon's glare veil read from the layer's alpha: the
      // tone block, no grid.
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(false, false, true, false),
            {sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
             optional(sampler("nightExtinction", SKYIG_UNIT_NIGHT_LAYER_EXTINCTION)),
             block("ToneBlock", SKYIG_BINDING_TONE), output("outDisplay", SKYIG_OUTPUT_FOLDED_DISPLAY)}),
       "#define SKYIG_MOONLIT\n#define SKYIG_SKY\n#define SKYIG_SUNLESS\n#define SKYIG_NIGHT_LAYER\n"
       "#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n#define SKYIG_NIGHT_LAYER_TRANSMITTED\n#define SKYIG_FOLD_TONE\n"
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n#define SKYIG_GLARE_FROM_NIGHT_LAYER\n"},
      // The pixels the horizon crosses, drawn last on the strip around it (PhysicalSkyPass::
      // drawHorizonEdge): the ground's and the sky's rays, the disc where the sun is on it; at
      // night with the layer (per-pixel transmittance) and the tone folded in.
      {{"render/passes/sky/horizon_strip.vert", "render/passes/sky/physical_sky.frag"},
       physicalSky(true, true, true),
       "#define SKYIG_MOONLIT\n#define SKYIG_HORIZON_EDGE\n#define SKYIG_SUN_DISC\n"},
      {{"render/passes/sky/horizon_strip.vert", "render/passes/sky/physical_sky.frag"},
       with(physicalSky(true, true, true, false),
            {sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
             sampler("nightExtinction", SKYIG_UNIT_NIGHT_LAYER_EXTINCTION),
             block("ToneBlock", SKYIG_BINDING_TONE), output("outDisplay", SKYIG_OUTPUT_FOLDED_DISPLAY)}),
       "#define SKYIG_MOONLIT\n#define SKYIG_HORIZON_EDGE\n#define SKYIG_SUNLESS\n#define SKYIG_NIGHT_LAYER\n"
       "#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n#define SKYIG_FOLD_TONE\n#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n"
       "#define SKYIG_GLARE_FROM_NIGHT_LAYER\n"},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky_reference.frag"}, physicalSky(true, true, true)},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky_space.frag"},
       {frame, band, sampler("transmittanceXyz", SKYIG_UNIT_TRANSMITTANCE), sampler("scatteringPacked", SKYIG_UNIT_SCATTERING),
        sampler("singleMieRG", SKYIG_UNIT_SINGLE_MIE), sampler("irradianceXyz", SKYIG_UNIT_IRRADIANCE), radiance}},
      {{"render/glsl/fullscreen.vert", "render/passes/sky/physical_sky_slice.frag"},
       {optional(frame), sampler("scatteringPacked", SKYIG_UNIT_SCATTERING),
        sampler("singleMieRG", SKYIG_UNIT_SINGLE_MIE), output("outScattering", SKYIG_OUTPUT_SLICE_SCATTERING),
        output("outSingleMie", SKYIG_OUTPUT_SLICE_SINGLE_MIE)}},
      // MoonPass, NightDiffusePass, StarPass.
      {{"render/passes/night/moon.vert", "render/passes/night/moon.frag"},
       {frame, band, sampler("moonAlbedo", SKYIG_UNIT_MOON_ALBEDO),
        sampler("extinctionTable", SKYIG_UNIT_MOON_EXTINCTION), radiance}},
      {{"render/glsl/fullscreen.vert", "render/passes/night/night_diffuse.frag"},
       {frame, band, sampler("milkyWayS10", SKYIG_UNIT_MILKY_WAY), sampler("zodiacalS10", SKYIG_UNIT_ZODIACAL),
        sampler("extinctionRec709", SKYIG_UNIT_NIGHT_EXTINCTION), radiance}},
      // Through a broken deck (a goggle's night pass): the sky pass's two weather tables.
      {{"render/glsl/fullscreen.vert", "render/passes/night/night_diffuse.frag"},
       {frame, band, sampler("milkyWayS10", SKYIG_UNIT_MILKY_WAY), sampler("zodiacalS10", SKYIG_UNIT_ZODIACAL),
        sampler("extinctionRec709", SKYIG_UNIT_NIGHT_EXTINCTION), sampler("fogTable", SKYIG_UNIT_FOG_TABLE),
        sampler("fogClearTable", SKYIG_UNIT_FOG_CLEAR_TABLE), radiance},
       "#define SKYIG_CLOUD_COVER 1\n"},
      // Its layer for the physical sky pass (NightDiffusePass::drawLayer): the light above the
      // atmosphere and, beside it, dimmed at the texel.
      {{"render/glsl/fullscreen.vert", "render/passes/night/night_diffuse.frag"},
       {frame, band, sampler("milkyWayS10", SKYIG_UNIT_MILKY_WAY), sampler("zodiacalS10", SKYIG_UNIT_ZODIACAL),
        sampler("extinctionRec709", SKYIG_UNIT_NIGHT_EXTINCTION), radiance,
        output("outTransmitted", SKYIG_OUTPUT_NIGHT_LAYER_TRANSMITTED)},
       "#define SKYIG_NIGHT_LAYER\n#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n"},
      // With the glare veil of the tone block's one source in its alpha.
      {{"render/glsl/fullscreen.vert", "render/passes/night/night_diffuse.frag"},
       {frame, band, block("ToneBlock", SKYIG_BINDING_TONE), sampler("milkyWayS10", SKYIG_UNIT_MILKY_WAY),
        sampler("zodiacalS10", SKYIG_UNIT_ZODIACAL), sampler("extinctionRec709", SKYIG_UNIT_NIGHT_EXTINCTION), radiance,
        output("outTransmitted", SKYIG_OUTPUT_NIGHT_LAYER_TRANSMITTED)},
       "#define SKYIG_NIGHT_LAYER\n#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n#define SKYIG_GLARE 1\n"},
      // GogglePass: the photocathode, its 8 x 8 means, the halo's two passes, the gain, the screen.
      {{"render/glsl/fullscreen.vert", "render/passes/goggle/goggle_input.frag"},
       {optional(frame), block("GoggleBlock", SKYIG_BINDING_GOGGLE), sampler("nvisImage", SKYIG_UNIT_GOGGLE_NVIS),
        output("outCathode", SKYIG_OUTPUT_COLOR)}},
      {{"render/glsl/fullscreen.vert", "render/passes/goggle/goggle_coarse.frag"},
       {optional(frame), block("GoggleBlock", SKYIG_BINDING_GOGGLE), sampler("cathodeImage", SKYIG_UNIT_GOGGLE_CATHODE),
        output("outMean", SKYIG_OUTPUT_COLOR)}},
      {{"render/glsl/fullscreen.vert", "render/passes/goggle/goggle_halo.frag"},
       {optional(frame), block("GoggleBlock", SKYIG_BINDING_GOGGLE), sampler("coarseImage", SKYIG_UNIT_GOGGLE_COARSE),
        output("outHalo", SKYIG_OUTPUT_COLOR)}},
      {{"render/glsl/fullscreen.vert", "render/passes/goggle/goggle_abc.frag"},
       {optional(frame), block("GoggleBlock", SKYIG_BINDING_GOGGLE), sampler("coarseImage", SKYIG_UNIT_GOGGLE_COARSE),
        output("outGain", SKYIG_OUTPUT_COLOR)}},
      {{"render/glsl/fullscreen.vert", "render/passes/goggle/goggle.frag"},
       {optional(frame), block("GoggleBlock", SKYIG_BINDING_GOGGLE), block("ToneBlock", SKYIG_BINDING_TONE),
        sampler("cathodeImage", SKYIG_UNIT_GOGGLE_CATHODE), sampler("haloLogImage", SKYIG_UNIT_GOGGLE_HALO),
        sampler("gainImage", SKYIG_UNIT_GOGGLE_GAIN), output("outDisplay", SKYIG_OUTPUT_COLOR)}},
      {{"render/passes/night/star.vert", "render/passes/night/star.frag"},
       {frame, input("aDirection", SKYIG_ATTRIB_STAR_DIRECTION), input("aRec709Lux", SKYIG_ATTRIB_STAR_REC709_LUX),
        radiance}},
      {{"render/passes/night/star_display.vert", "render/passes/night/star.frag"},
       {frame, block("ToneBlock", SKYIG_BINDING_TONE), input("aDirection", SKYIG_ATTRIB_STAR_DIRECTION),
        input("aRec709Lux", SKYIG_ATTRIB_STAR_REC709_LUX), sampler("hdrImage", SKYIG_UNIT_STAR_BACKGROUND), radiance}},
      // The tone pass over the displayed stars' quads after a sky pass that mapped its pixels
      // (TonePass::drawOver).
      {{"render/passes/night/star_display.vert", "render/passes/tone/tone.frag"},
       {frame, block("ToneBlock", SKYIG_BINDING_TONE), input("aDirection", SKYIG_ATTRIB_STAR_DIRECTION),
        input("aRec709Lux", SKYIG_ATTRIB_STAR_REC709_LUX), sampler("hdrImage", SKYIG_UNIT_STAR_BACKGROUND),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), sampler("glareVeilGrid", SKYIG_UNIT_GLARE_VEIL),
        output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX 8.0\n"},
      // The same on a night whose layer holds the veil.
      {{"render/passes/night/star_display.vert", "render/passes/tone/tone.frag"},
       {frame, block("ToneBlock", SKYIG_BINDING_TONE), input("aDirection", SKYIG_ATTRIB_STAR_DIRECTION),
        input("aRec709Lux", SKYIG_ATTRIB_STAR_REC709_LUX), sampler("hdrImage", SKYIG_UNIT_STAR_BACKGROUND),
        sampler("pointSourceImage", SKYIG_UNIT_POINT_SOURCES), sampler("nightLayer", SKYIG_UNIT_NIGHT_LAYER),
        output("outDisplay", SKYIG_OUTPUT_COLOR)},
       "#define SKYIG_TONE_CURVE\n#define SKYIG_GLARE 1\n#define SKYIG_GLARE_FROM_NIGHT_LAYER\n"
       "#define SKYIG_NIGHT_LAYER_CELL_PX 3.0\n"},
      // AtmosphereGpuPrecompute, in the order it runs them.
      {{"render/passes/precompute/precompute_transmittance.comp"}, {image("transmittance_out", SKYIG_IMAGE_TRANSMITTANCE)}},
      {{"render/passes/precompute/precompute_direct_irradiance.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        image("delta_irradiance_out", SKYIG_IMAGE_DELTA_IRRADIANCE), image("irradiance_out", SKYIG_IMAGE_IRRADIANCE)}},
      {{"render/passes/precompute/precompute_ray_transmittance.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        image("ray_transmittance_out", SKYIG_IMAGE_RAY_TRANSMITTANCE),
        image("ray_geometry_out", SKYIG_IMAGE_RAY_GEOMETRY)}},
      {{"render/passes/precompute/precompute_single_scattering.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        sampler("ray_transmittance", SKYIG_UNIT_RAY_TRANSMITTANCE), sampler("ray_geometry", SKYIG_UNIT_RAY_GEOMETRY),
        image("delta_rayleigh_out", SKYIG_IMAGE_DELTA_RAYLEIGH), image("delta_mie_out", SKYIG_IMAGE_DELTA_MIE),
        image("scattering_out", SKYIG_IMAGE_SCATTERING), image("single_mie_out", SKYIG_IMAGE_SINGLE_MIE)}},
      {{"render/passes/precompute/precompute_nu_slices.comp"},
       {sampler("single_rayleigh_texture", SKYIG_UNIT_DELTA_RAYLEIGH),
        sampler("single_mie_texture", SKYIG_UNIT_DELTA_MIE), sampler("multiple_texture", SKYIG_UNIT_DELTA_MULTIPLE),
        image("slices_a_out", SKYIG_IMAGE_NU_SLICES_A), image("slices_b_out", SKYIG_IMAGE_NU_SLICES_B)}},
      {{"render/passes/precompute/precompute_scattering_density_order2.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        sampler("ground_irradiance_texture", SKYIG_UNIT_GROUND_IRRADIANCE), sampler("slices_a", SKYIG_UNIT_NU_SLICES_A),
        sampler("slices_b", SKYIG_UNIT_NU_SLICES_B), image("density_out", SKYIG_IMAGE_DELTA_DENSITY)}},
      {{"render/passes/precompute/precompute_scattering_density.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        sampler("ground_irradiance_texture", SKYIG_UNIT_GROUND_IRRADIANCE), sampler("slices_a", SKYIG_UNIT_NU_SLICES_A),
        image("density_out", SKYIG_IMAGE_DELTA_DENSITY)}},
      {{"render/passes/precompute/precompute_indirect_irradiance.comp"},
       {sampler("single_rayleigh_texture", SKYIG_UNIT_DELTA_RAYLEIGH),
        sampler("single_mie_texture", SKYIG_UNIT_DELTA_MIE), sampler("multiple_texture", SKYIG_UNIT_DELTA_MULTIPLE),
        image("delta_irradiance_out", SKYIG_IMAGE_DELTA_IRRADIANCE),
        image("irradiance_accumulated", SKYIG_IMAGE_IRRADIANCE)}},
      {{"render/passes/precompute/precompute_multiple_scattering.comp"},
       {sampler("scattering_density_texture", SKYIG_UNIT_DELTA_DENSITY),
        sampler("ray_transmittance", SKYIG_UNIT_RAY_TRANSMITTANCE), sampler("ray_geometry", SKYIG_UNIT_RAY_GEOMETRY),
        image("delta_multiple_out", SKYIG_IMAGE_DELTA_MULTIPLE),
        image("scattering_accumulated", SKYIG_IMAGE_SCATTERING)}},
      // The panorama check of tests/physics/atmosphere/gpu_precompute_test.cpp.
      {{"render/passes/precompute/sky_view.comp"},
       {sampler("transmittance_texture", SKYIG_UNIT_TRANSMITTANCE),
        sampler("scattering_texture", SKYIG_UNIT_SCATTERING), sampler("single_mie_texture", SKYIG_UNIT_SINGLE_MIE),
        sampler("irradiance_texture", SKYIG_UNIT_IRRADIANCE), image("radiance_out", SKYIG_IMAGE_SKY_VIEW)}},
  };
  // A std140 block may stay active wherever render/glsl/uniforms.h declares it, read or not (Mesa
  // keeps them all): the blocks a program does not list above are optional in it.
  for (ProgramCase& c : cases) {
    if (c.files.size() == 1) continue;
    for (const Expect& b : {frame, block("AnalyticSkyBlock", SKYIG_BINDING_SKY), block("ToneBlock", SKYIG_BINDING_TONE),
                            block("ProjectorBlock", SKYIG_BINDING_PROJECTOR)}) {
      bool listed = false;
      for (const Expect& e : c.expect) listed = listed || (e.kind == b.kind && e.name == b.name);
      if (!listed) c.expect.push_back(optional(b));
    }
  }
  return cases;
}

bool isSampler(GLint type) {
  switch (type) {
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_ARRAY: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_CUBE_MAP_ARRAY:
    case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_2D_RECT:
    case GL_SAMPLER_BUFFER: case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_INT_SAMPLER_1D: case GL_INT_SAMPLER_2D: case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_1D: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_3D:
      return true;
    default:
      return false;
  }
}

bool isImage(GLint type) {
  switch (type) {
    case GL_IMAGE_1D: case GL_IMAGE_2D: case GL_IMAGE_3D: case GL_IMAGE_CUBE: case GL_IMAGE_2D_RECT:
    case GL_IMAGE_1D_ARRAY: case GL_IMAGE_2D_ARRAY: case GL_IMAGE_BUFFER:
    case GL_INT_IMAGE_2D: case GL_INT_IMAGE_3D: case GL_UNSIGNED_INT_IMAGE_2D: case GL_UNSIGNED_INT_IMAGE_3D:
      return true;
    default:
      return false;
  }
}

GLint property(GLuint program, GLenum interface, GLuint index, GLenum prop) {
  GLint value = -1;
  glGetProgramResourceiv(program, interface, index, 1, &prop, 1, nullptr, &value);
  return value;
}

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
  const GLint length = property(program, interface, index, GL_NAME_LENGTH);
  std::string name(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetProgramResourceName(program, interface, index, static_cast<GLsizei>(name.size()), nullptr, name.data());
  name.resize(std::strlen(name.c_str()));
  return name;
}

struct Resource {
  std::string kind, name;
  GLint value;
};

// What GL reports for every active resource that a binding or a location connects.
std::vector<Resource> activeBindings(GLuint program) {
  std::vector<Resource> out;
  auto each = [&](GLenum interface, auto&& f) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    for (GLuint i = 0; i < static_cast<GLuint>(count); ++i) f(i, resourceName(program, interface, i));
  };
  each(GL_UNIFORM, [&](GLuint i, const std::string& name) {
    const GLint type = property(program, GL_UNIFORM, i, GL_TYPE);
    if (!isSampler(type) && !isImage(type)) return;
    GLint unit = -1;
    glGetUniformiv(program, property(program, GL_UNIFORM, i, GL_LOCATION), &unit);
    out.push_back({isSampler(type) ? "sampler" : "image", name, unit});
  });
  each(GL_UNIFORM_BLOCK, [&](GLuint i, const std::string& name) {
    out.push_back({"uniform block", name, property(program, GL_UNIFORM_BLOCK, i, GL_BUFFER_BINDING)});
  });
  each(GL_SHADER_STORAGE_BLOCK, [&](GLuint i, const std::string& name) {
    out.push_back({"storage block", name, property(program, GL_SHADER_STORAGE_BLOCK, i, GL_BUFFER_BINDING)});
  });
  each(GL_PROGRAM_INPUT, [&](GLuint i, const std::string& name) {
    if (name.rfind("gl_", 0) == 0) return;  // built-ins have no location
    out.push_back({"input", name, property(program, GL_PROGRAM_INPUT, i, GL_LOCATION)});
  });
  each(GL_PROGRAM_OUTPUT, [&](GLuint i, const std::string& name) {
    if (name.rfind("gl_", 0) == 0) return;
    out.push_back({"output", name, property(program, GL_PROGRAM_OUTPUT, i, GL_LOCATION)});
  });
  return out;
}

GLuint link(const std::vector<std::string>& files, const std::string& defines) {
  if (files.size() == 1) return linkProgram({compileShaderStage(GL_COMPUTE_SHADER, files[0], defines)}, files[0]);
  return linkProgram({compileShaderStage(GL_VERTEX_SHADER, files[0], defines),
                      compileShaderStage(GL_FRAGMENT_SHADER, files[1], defines)},
                     files[0] + " + " + files[1]);
}

std::unique_ptr<GlContext> makeContext() {
  try {
    return createHeadlessContext();
  } catch (const GlContextError&) {
    return nullptr;
  }
}

bool isPassFile(std::string_view path) {
  for (std::string_view ext : {".vert", ".frag", ".comp"})
    if (path.size() > ext.size() && path.substr(path.size() - ext.size()) == ext) return true;
  return false;
}

}  // namespace

// Links every program of the renderer and the GPU precompute and compares what GL reports for
// each sampler, image, uniform/storage block, vertex input and fragment output with the
// render/glsl/bindings.h name that the C++ binds it by. A GLSL declaration with another
// number, or a new resource without a name, fails here.
TEST(Bindings, EveryPassUsesTheSharedUnits) {
  const auto gl = makeContext();
  if (!gl) GTEST_SKIP() << "no OpenGL 4.5 context through EGL";
  const std::vector<ProgramCase> cases = programs();

  // Every pass file of the embedded shaders is in a program above.
  for (const EmbeddedShader& s : embeddedShaders()) {
    if (!isPassFile(s.path)) continue;
    bool listed = false;
    for (const ProgramCase& c : cases)
      for (const std::string& f : c.files) listed = listed || f == s.path;
    EXPECT_TRUE(listed) << s.path << " is in no program of this test: add the program and its bindings";
  }

  for (const ProgramCase& c : cases) {
    std::string what = c.files[0];
    if (c.files.size() > 1) what += " + " + c.files[1];
    if (!c.defines.empty()) what += " with " + c.defines;
    SCOPED_TRACE(what);
    const GLuint program = link(c.files, c.defines);
    const std::vector<Resource> active = activeBindings(program);
    const bool compute = c.files.size() == 1;
    std::map<std::string, std::map<GLint, std::string>> taken;  // kind -> number -> name
    for (const Resource& r : active) {
      const Expect* e = nullptr;
      for (const Expect& x : c.expect)
        if (x.kind == r.kind && x.name == r.name) e = &x;
      if (!e) {
        ADD_FAILURE() << r.kind << " " << r.name << " (at " << r.value
                      << ") is not in this test: bind it by a render/glsl/bindings.h name and list it here";
        continue;
      }
      EXPECT_EQ(r.value, e->value) << r.kind << " " << r.name << ": the GLSL says " << r.value
                                   << ", render/glsl/bindings.h (what the C++ binds) " << e->value;
      // Two resources of one kind on one number would read the same texture or buffer.
      const auto [it, fresh] = taken[r.kind].emplace(r.value, r.name);
      EXPECT_TRUE(fresh) << r.kind << "s " << it->second << " and " << r.name << " share " << r.value;
      // The precompute unbinds units and images up to these counts.
      if (compute && r.kind == "sampler") {
        EXPECT_LT(r.value, SKYIG_PRECOMPUTE_UNIT_COUNT) << r.name;
      }
      if (compute && r.kind == "image") {
        EXPECT_LT(r.value, SKYIG_PRECOMPUTE_IMAGE_COUNT) << r.name;
      }
    }
    for (const Expect& e : c.expect) {
      if (e.mayBeInactive) continue;
      bool found = false;
      for (const Resource& r : active) found = found || (r.kind == e.kind && r.name == e.name);
      EXPECT_TRUE(found) << e.kind << " " << e.name << " is not active in the linked program";
    }
    glDeleteProgram(program);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The GLSL side, as text: no embedded shader file (passes, physics, shared headers) gives a
// binding or a location as a bare number.
TEST(Bindings, NoShaderSourceHasABareBindingNumber) {
  const std::regex bare(R"(\b(binding|location)\s*=\s*[0-9])");
  int files = 0;
  for (const EmbeddedShader& s : embeddedShaders()) {
    ++files;
    std::istringstream in{std::string(s.source)};
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      EXPECT_FALSE(std::regex_search(line, bare))
          << s.path << ":" << n << ": a bare number; name it in render/glsl/bindings.h\n  " << line;
  }
  EXPECT_GT(files, 20);
}

// The C++ side, as text: no source of the renderer binds a texture unit, image unit, uniform
// buffer or vertex attribute by a bare number, nor keeps its own constant for one.
TEST(Bindings, NoRendererSourceBindsByNumber) {
  const std::filesystem::path root = std::filesystem::path(SKYIG_SOURCE_DIR) / "render";
  ASSERT_TRUE(std::filesystem::is_directory(root)) << root;
  const std::regex bare(
      R"((glBindTextureUnit|glBindImageTexture|\bimage|\bbind|UniformBuffer\s*\w*|Block_)\(\s*[0-9])"
      R"(|glBindBufferBase\([^,]*,\s*[0-9])"
      R"(|VertexArrayAttrib\w*\([^,]*,\s*[0-9])"
      R"(|\bk\w*(Unit|Binding|Location)\s*=\s*[0-9])");  // a local constant instead of the shared name
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".h") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      EXPECT_FALSE(std::regex_search(line, bare))
          << entry.path().string() << ":" << n << ": a bare number; use its render/glsl/bindings.h name\n  "
          << line;
  }
  EXPECT_GT(files, 10);
}
