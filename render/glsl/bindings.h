#ifndef SKYIG_COMMON_BINDINGS_H
#define SKYIG_COMMON_BINDINGS_H
// Every number that C++ and GLSL must agree on to connect a resource to a shader: uniform-block
// binding points, texture units, image units, vertex-attribute and fragment-output locations.
// Plain #defines of integer literals, which both preprocessors read the same way: the shaders
// write `layout(binding = SKYIG_UNIT_MOON_ALBEDO)`, the passes `glBindTextureUnit(
// SKYIG_UNIT_MOON_ALBEDO, ...)`, and neither side holds a bare number.
// tests/render/bindings_test.cpp (ctest Bindings.*) links every program and checks what GL
// reports for each sampler, image, block, input and output against these names, and that no
// shader or pass source binds by a bare number.

// Uniform blocks (layouts in render/glsl/uniforms.h). SkyRenderer binds them once per channel and
// every pass reads them from there, so each block has its own binding point.
#define SKYIG_BINDING_FRAME 0  // FrameBlock: view rays and viewport
#define SKYIG_BINDING_SKY 1    // AnalyticSkyBlock
#define SKYIG_BINDING_TONE 2   // ToneBlock
#define SKYIG_BINDING_PROJECTOR 3  // ProjectorBlock: the warp-and-blend pass
#define SKYIG_BINDING_BAND 4       // BandBlock: the eye's band or a goggle's (render/glsl/band.glsl)
#define SKYIG_BINDING_GOGGLE 5     // GoggleBlock: a goggle channel's intensifier

// Texture units. Every pass binds its textures right before it draws, so units may repeat
// between passes; within a program they must differ.

// The physical sky (passes/physical_sky*.frag, PhysicalSkyPass) and render/passes/precompute/sky_view.comp:
// the four tables in the order of Bruneton's rendering functions. The slice program
// (physical_sky_slice.frag) reads the 3D tables at the same units as the sky programs, so
// PhysicalSkyPass::draw binds them once for both; this frame's 2D slices come after.
#define SKYIG_UNIT_TRANSMITTANCE 0
#define SKYIG_UNIT_SCATTERING 1
#define SKYIG_UNIT_SINGLE_MIE 2
#define SKYIG_UNIT_IRRADIANCE 3
#define SKYIG_UNIT_SUN_SLICE_SCATTERING 4
#define SKYIG_UNIT_SUN_SLICE_SINGLE_MIE 5
#define SKYIG_UNIT_MOON_SLICE_SCATTERING 6
#define SKYIG_UNIT_MOON_SLICE_SINGLE_MIE 7

// The GPU precompute (atmosphere/precompute_*.comp, AtmosphereGpuPrecompute): one unit per
// table for all seven programs, so each scattering order binds every table once and the passes
// run back to back; a table is unbound only while a pass rewrites it as an image. The
// transmittance is read at SKYIG_UNIT_TRANSMITTANCE, as by the sky.
#define SKYIG_UNIT_DELTA_RAYLEIGH 1    // single Rayleigh (order 1)
#define SKYIG_UNIT_DELTA_MIE 2         // single Mie (order 1)
#define SKYIG_UNIT_DELTA_MULTIPLE 3    // multiple scattering of the last order
#define SKYIG_UNIT_DELTA_IRRADIANCE 4  // ground irradiance of the last order
#define SKYIG_UNIT_DELTA_DENSITY 5     // scattering density
#define SKYIG_UNIT_NU_SLICES_A 6       // precompute_nu_slices.comp's two outputs
#define SKYIG_UNIT_NU_SLICES_B 7
#define SKYIG_UNIT_RAY_TRANSMITTANCE 8  // precompute_ray_transmittance.comp's two outputs
#define SKYIG_UNIT_RAY_GEOMETRY 9
#define SKYIG_UNIT_GROUND_IRRADIANCE 10  // the delta irradiance's ground row, a 1D texture
#define SKYIG_PRECOMPUTE_UNIT_COUNT 11  // units 0 to 10, unbound before and after

// The diffuse night sky (render/passes/night/night_diffuse.frag, NightDiffusePass).
#define SKYIG_UNIT_MILKY_WAY 0
#define SKYIG_UNIT_ZODIACAL 1
#define SKYIG_UNIT_NIGHT_EXTINCTION 2  // ExtinctionTexture
// The night's light at a few pixels a texel (NightDiffusePass::drawLayer), read by the physical
// sky pass beside its own 0 to 7 and the tone's glare veil.
#define SKYIG_UNIT_NIGHT_LAYER 9
#define SKYIG_UNIT_NIGHT_LAYER_EXTINCTION 10  // the same ExtinctionTexture as the night pass's
// The weather's layers along this frame's views (render/passes/sky/fog_table_texture.h), read by
// the physical sky pass when a layer is on (SKYIG_FOG).
#define SKYIG_UNIT_FOG_TABLE 11
// The same without the broken cloud decks, mixed with it by their field (SKYIG_CLOUD_COVER).
#define SKYIG_UNIT_FOG_CLEAR_TABLE 12
// The decks' light tables (SKYIG_CLOUD_LIGHT, PhysicalSkyPass): the sun's light at each deck's
// face by its local elevation, the air's transmittance from the eye to the face by the view's.
#define SKYIG_UNIT_CLOUD_LIGHT_TABLE 13

// The moon (render/passes/night/moon.frag, MoonPass). Kept apart from the sky pass's 0 to 7 as they always
// were; nothing needs it (see above), and any GL 4.5 driver has far more units than 22.
#define SKYIG_UNIT_MOON_ALBEDO 20
#define SKYIG_UNIT_MOON_EXTINCTION 21  // ExtinctionTexture

// Tone reproduction (render/passes/tone/tone.frag, TonePass): the HDR target, the displayed stars and
// planets to add (display cd/m^2), and the glare veil at the vertices of the pass's grid; the
// veil's unit clear of the sky pass's 0 to 7, since the sky pass reads it too when it maps its
// own pixels (render/passes/tone/tone_display.glsl).
#define SKYIG_UNIT_HDR_IMAGE 0
#define SKYIG_UNIT_POINT_SOURCES 1
#define SKYIG_UNIT_GLARE_VEIL 8

// The warp-and-blend pass (render/passes/projector/warp_blend.frag, WarpBlendPass): the channel's undithered
// display values and its HDR image, read through the warp; the projector's maps.
#define SKYIG_UNIT_CHANNEL_DISPLAY 0
#define SKYIG_UNIT_CHANNEL_HDR 1
#define SKYIG_UNIT_PROJECTOR_WARP 2
#define SKYIG_UNIT_PROJECTOR_ALPHA 3
#define SKYIG_UNIT_PROJECTOR_BETA 4

// The host-frame composite (render/client/client_frame.frag, ClientFrameRenderer): the channel's display
// frame or its HDR image, copied into the host's framebuffer where its depth is at the far plane.
#define SKYIG_UNIT_HOST_SOURCE 0

// The goggle (passes/goggle*.frag, GogglePass): the channel's NVIS radiance (the HDR target),
// the photocathode's illuminance, its means over 8 x 8 pixels (and their mip chain), the halo
// at that resolution, and the gain.
#define SKYIG_UNIT_GOGGLE_NVIS 0
#define SKYIG_UNIT_GOGGLE_CATHODE 1
#define SKYIG_UNIT_GOGGLE_COARSE 2
#define SKYIG_UNIT_GOGGLE_HALO 3
#define SKYIG_UNIT_GOGGLE_GAIN 4  // the automatic brightness control's gain, 1 x 1

// The displayed-star pass (render/passes/night/star_display.vert, StarPass::drawDisplayed): the HDR target
// without stars, read per star for the sky it sits on.
#define SKYIG_UNIT_STAR_BACKGROUND 0

// Image units of the GPU precompute (atmosphere/*.comp): each program numbers what it writes
// from 0 (at most four tables), and a table written by two programs keeps one unit in both
// (irradiance: direct and indirect irradiance; scattering: single and multiple scattering).
#define SKYIG_IMAGE_TRANSMITTANCE 0
#define SKYIG_IMAGE_DELTA_IRRADIANCE 0
#define SKYIG_IMAGE_IRRADIANCE 1
#define SKYIG_IMAGE_DELTA_RAYLEIGH 0
#define SKYIG_IMAGE_DELTA_MIE 1
#define SKYIG_IMAGE_SCATTERING 2
#define SKYIG_IMAGE_SINGLE_MIE 3
#define SKYIG_IMAGE_NU_SLICES_A 0
#define SKYIG_IMAGE_NU_SLICES_B 1
#define SKYIG_IMAGE_DELTA_DENSITY 0
#define SKYIG_IMAGE_DELTA_MULTIPLE 0
#define SKYIG_IMAGE_RAY_TRANSMITTANCE 0
#define SKYIG_IMAGE_RAY_GEOMETRY 1
#define SKYIG_IMAGE_SKY_VIEW 0  // render/passes/precompute/sky_view.comp's panorama
#define SKYIG_PRECOMPUTE_IMAGE_COUNT 4  // image units 0 to 3, unbound after

// Vertex attributes of the star pass (render/passes/night/star.vert, StarPass): the two vec3 of a source,
// in the order one instance stores them in the interleaved buffer.
#define SKYIG_ATTRIB_STAR_DIRECTION 0
#define SKYIG_ATTRIB_STAR_REC709_LUX 1

// Fragment outputs. A pass with one output writes draw buffer 0: colour attachment 0 of its
// RenderTarget. The slice program writes the two colour attachments of PhysicalSkyPass's
// slice framebuffer.
#define SKYIG_OUTPUT_COLOR 0
#define SKYIG_OUTPUT_SLICE_SCATTERING 0
#define SKYIG_OUTPUT_SLICE_SINGLE_MIE 1
// The physical sky pass mapping its own pixels (SKYIG_FOLD_TONE) writes the display values
// beside the light, into SkyRenderer's framebuffer of both targets.
#define SKYIG_OUTPUT_FOLDED_DISPLAY 1
// The night's layer (NightDiffusePass::drawLayer) writes the light above the atmosphere and,
// beside it, the same dimmed by the transmittance to space at each texel.
#define SKYIG_OUTPUT_NIGHT_LAYER_TRANSMITTED 1
// The warp-and-blend pass writes both of WarpBlendPass's targets at once: the 8-bit image sent
// to the projector and the light it contributes (cd/m^2).
#define SKYIG_OUTPUT_PROJECTOR_DISPLAY 0
#define SKYIG_OUTPUT_PROJECTOR_LIGHT 1

#endif
