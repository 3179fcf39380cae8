#pragma once
// The GPU side of the physical atmosphere: a model's tables folded into linear Rec.709 at half
// float (physics/atmosphere/precompute/rec709_tables.h; 12.9 MB at the default size) and the sky pass that
// renders from them (render/passes/sky/physical_sky.frag). A new model is uploaded a few
// scattering slices per frame into a second texture set while the current one is drawn, then
// swapped in: a frame never waits for a whole table set.
#include "physics/atmosphere/model.h"
#include "physics/atmosphere/precompute/rec709_tables.h"
#include "render/passes/common/atmosphere_uniforms.h"
#include "render/gl/gl_program.h"
#include "render/passes/tone/folded_tone.h"
#include "render/passes/common/night_layer.h"
#include "physics/weather/cloud_deck.h"
#include "render/passes/common/cloud_field.h"
#include "render/passes/sky/fog_table_texture.h"
#include "render/passes/sky/sky_variant.h"
#include "physics/atmosphere/physical_camera.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <string>

namespace skyig::render {

// A 2D table of the atmosphere as an RGBA32F texture (linear filtering, clamped to its edges).
GLuint uploadTable2D(const shader::cpu_texture::sampler2D& table);

class PhysicalSkyPass {
 public:
  // Scattering slices (radii) a frame packs and uploads while a new model is pending: 2 of the
  // default tables (256 x 128 texels each) cost a few ms of CPU (docs/atmosphere.md).
  static constexpr int kDefaultSlicesPerFrame = 2;
  // insideFragment: the fragment shader drawn with the camera inside the atmosphere; another
  // one with the same inputs only for the frozen reference (render/passes/sky/reference_sky_pass.h).
  // The live pass compiles kInsideFragment in its variants.
  static constexpr const char* kInsideFragment = "render/passes/sky/physical_sky.frag";
  explicit PhysicalSkyPass(int slicesPerFrame = kDefaultSlicesPerFrame, const char* insideFragment = kInsideFragment);
  ~PhysicalSkyPass();
  PhysicalSkyPass(const PhysicalSkyPass&) = delete;
  PhysicalSkyPass& operator=(const PhysicalSkyPass&) = delete;

  // Makes `model` the one to draw. The first model is uploaded at once; a later one becomes
  // pending and is uploaded by the next draws (a newer one replaces a pending one).
  void use(std::shared_ptr<const atmosphere::AtmosphereModel> model);
  // Uploads the pending model's next slices (swapping it in once complete), then draws into
  // the bound target: camera in metres from the planet's centre, the sun's and the moon's
  // directions (airless), all in the local east-north-up frame; a zero moonlightScale skips the
  // moon. sunRefraction is the refraction about the sun's apparent centre (SkyState::
  // sunRefraction; zero: none) the disc is drawn through. The frame block must be bound.
  // tone.defines, when not empty, are the tone pass's variant (TonePass::folded): the pass then
  // also maps each pixel to the display and writes it at SKYIG_OUTPUT_FOLDED_DISPLAY
  // (render/passes/sky/physical_sky.frag, SKYIG_FOLD_TONE), with tone.exactDefines in tone.exactBoxes; the
  // tone block must be bound, and the veil's grid at its unit if the defines read it (or the
  // night's layer, which then holds the veil). `night`, when it has a texture, adds the night's
  // own light (SKYIG_NIGHT_LAYER). `sunlit` false leaves out the sun's sky, ground and disc
  // (SKYIG_SUNLESS), when its twilight changes no display code (sky/shown_layers.h); inside the
  // atmosphere only. Returns whether it drew what was asked (never from space, whose program has
  // neither, nor for a reference pass): if not, only the sky was drawn, the sun's light in it.
  bool draw(const glm::dvec3& camera, const glm::dvec3& sunDirection,
            const glm::dvec3& moonDirection = glm::dvec3(0.0, 0.0, 1.0),
            const glm::dvec3& moonlightScale = glm::dvec3(0.0),
            const glm::dvec4& sunRefraction = glm::dvec4(0.0), const FoldedTone& tone = {},
            const NightLayer& night = {}, bool sunlit = true);

  // The fog layers the next draw() composes over the sky (sky/fog_state.h, drawnFogLayers); none
  // (extinction 0) until set. `table`: their table for an eye tableHeightM above the ground,
  // made with the state (sky/fog_state.h, FogTables), used when the draw's eye is at that
  // height; else (null, another height) the pass makes it.
  void setFog(const weather::FogLayers& layers, std::shared_ptr<const std::vector<glm::vec4>> table = nullptr,
              double tableHeightM = -1.0) {
    fog_ = layers;
    fogPrecomputed_ = std::move(table);
    fogPrecomputedHeightM_ = tableHeightM;
  }

  // The cloud decks' fields (sky/fog_state.h, FogState::cover): where one is broken, setFog's
  // layers have its gaps filled, `clear` (and its table for tableHeightM, when made with the
  // state) is the same without it, and the next draw() mixes the two per pixel by the field
  // (SKYIG_CLOUD_COVER). None broken (the default): setFog's layers alone.
  // The layers' transmittance along the sun's apparent direction, what its disc is dimmed by
  // under them (sky/fog_state.h, fogTransmittanceToSpaceAlong); 1 until set.
  void setSunThroughFog(double transmittance) { sunThroughFog_ = transmittance; }
  // The largest angle (rad) one pixel of the channel drawn next spans: the horizon's edge is drawn
  // on a strip this wide (and a half) either side of it (sky/camera.h, largestPixelAngleRad).
  void setPixelAngle(double radians) { pixelAngleRad_ = radians; }

  void setCloudCover(const std::array<weather::CloudCover, sky::kCloudLayers>& cover, const weather::FogLayers& clear,
                     std::shared_ptr<const std::vector<glm::vec4>> clearTable = nullptr) {
    cover_ = cover;
    fogClear_ = clear;
    fogClearPrecomputed_ = std::move(clearTable);
  }

  // The broken decks the last draw() inside the atmosphere mixed by their fields, with its
  // weather tables (none broken: CloudFieldView::broken() is 0).
  const CloudFieldView& cloudField() const { return cloudField_; }

  // What a draw() does to the pass's own state, without drawing: the pending model's next
  // slices uploaded (swapped in once complete). A replay that skips the frames it does not
  // write calls it for them, so its written frames show the tables a frame-by-frame run would.
  void stepUpload();

  const atmosphere::AtmosphereModel* current() const { return current_.model.get(); }
  const atmosphere::AtmosphereModel* pending() const { return pending_ ? pending_->set.model.get() : nullptr; }
  // How many draw() calls from now the pending model is first drawn (0: none pending).
  int framesUntilSwap() const;
  // What the last draw() spent on the pending model: bytes sent and wall seconds (packing the
  // slices on the CPU and the GL calls, not waiting for the GPU).
  std::size_t lastUploadBytes() const { return lastUploadBytes_; }
  double lastUploadSeconds() const { return lastUploadSeconds_; }
  // GPU memory of one table set (the current one).
  std::size_t tableBytes() const { return current_.bytes; }

  // The tables draw() reads now (names 0 and no model before the first use()), for shaders
  // other than the pass's own: a host's aerial perspective (render/client/client_aerial_perspective.h).
  struct Tables {
    std::shared_ptr<const atmosphere::AtmosphereModel> model;
    GLuint scattering = 0, singleMieRg = 0;  // the packed Rec.709 pair
  };
  Tables tables() const { return {current_.model, current_.scattering, current_.singleMie}; }

 private:
  struct TableSet {
    std::shared_ptr<const atmosphere::AtmosphereModel> model;
    GLuint transmittance = 0, irradiance = 0, scattering = 0, singleMie = 0;
    atmosphere::PackedRec709Tables small;  // the 2D tables and the sun (no scattering texels)
    std::size_t bytes = 0;
  };
  struct Pending {
    TableSet set;
    atmosphere::Rec709Packer packer;
    int nextSlice = 0;
  };
  static TableSet createSet(std::shared_ptr<const atmosphere::AtmosphereModel> model,
                            const atmosphere::Rec709Packer& packer);
  static void releaseSet(TableSet& set);
  static std::size_t uploadSlices(const TableSet& set, const atmosphere::Rec709Packer& packer, int first, int count);
  void makeCurrent(TableSet set);

  // One of the programs (a variant of the sky inside the atmosphere, the sun disc's quad, the
  // camera in space) and its per-frame uniforms, looked up once: draw() runs every frame.
  struct Program {
    Program(const char* vertex, const char* fragment, const std::string& defines = "");
    GlProgram program;
    GLint camera, sun, sunRefraction, moonOn, moonDirection, moonScale, radii, angles, groundCap, horizonStrip, nightGround;
    CloudFieldLocations cloudField;                     // SKYIG_CLOUD_COVER's
    GLint lit, litSide, litEye;                          // SKYIG_CLOUD_LIGHT's
    GLint sunThrough;                                                // SKYIG_FOG's
  };
  int brokenDecks() const;  // the broken decks among setFog's layers
  // The decks the eye is outside of, for SKYIG_CLOUD_LIGHT (render/passes/sky/physical_sky.frag's
  // cloudLit and cloudLitSide): the face each shows, its optical depth, asymmetry and index among
  // the broken decks; which face, its reflectance, the weather layers' depth between it and the eye.
  struct LitDecks {
    int count = 0;
    std::array<glm::vec4, sky::kCloudLayers> lit{}, side{};
  };
  LitDecks litDecks(double heightM) const;
  // The table SKYIG_CLOUD_LIGHT reads for the decks of `lit` seen from heightM, bound to its unit;
  // remade when a face's height or the eye's changes.
  void updateCloudLightTable(const LitDecks& lit, double heightM);
  void setCloudUniforms(const Program& program, double heightM) const;
  // The program of a variant, compiled the first time a frame needs it (a node uses a few of the
  // many); the HDR variants without the night layer or the tone are compiled with the pass.
  const Program& program(const SkyVariant& v);
  void setModelUniforms(const Program& program) const;

  // This frame's 2D slice of the scattering tables for one light (physical_sky_slice.frag).
  struct Slice {
    GLuint scattering = 0, singleMie = 0, framebuffer = 0;
  };
  static void setFrameUniforms(const Program& program, const glm::dvec3& camera, const glm::dvec3& sunDirection,
                               const glm::dvec4& sunRefraction, const glm::vec4& radii, const glm::vec3& angles);
  void ensureSlices();
  void releaseSlices();
  void drawSlice(const Slice& slice, double uMuS, double uR);

  // What every pixel of one frame inside the atmosphere shares, computed once in double.
  struct Frame {
    glm::dvec3 camera, sunDirection, moonDirection, moonlightScale;
    glm::dvec4 sunRefraction;
    glm::vec4 radii;   // r, rho, H and the sun's u_r
    glm::vec3 angles;  // the sun's and the moon's u_mu_s, the cosine of the disc's cone
    glm::dvec4 sunUvwz, moonUvwz;  // each light's scattering coordinates at the camera
    bool moon = false, sunlit = true;
    const NightLayer* night = nullptr;
    double horizon = 0.0;  // the horizon's elevation (rad)
  };
  Frame frameInside(const glm::dvec3& camera, const glm::dvec3& sunDirection, const glm::dvec3& moonDirection,
                    const glm::dvec3& moonlightScale, const glm::dvec4& sunRefraction, const NightLayer& night,
                    bool sunlit) const;
  void bindTables(const NightLayer& night) const;
  void drawFromSpace(const glm::dvec3& camera, const glm::dvec3& sunDirection, const glm::dvec3& moonDirection,
                     const glm::dvec3& moonlightScale, const glm::dvec4& sunRefraction);
  // This frame's slices of the tables at r for each light, into small targets; the caller's
  // target and viewport come back after. Returns the caller's target.
  GLint drawSlices(const Frame& f);
  void prepare(const Program& program, const Frame& f) const;
  void drawDisc(const Frame& f, const SkyVariant& base);
  // Into a target without depth: both parts at once, then the disc.
  void drawWithoutDepth(const Frame& f, const SkyVariant& base);
  // Into a target with depth: the ground, the band near the horizon, the sky, the disc, the
  // horizon's edge.
  void drawParts(const Frame& f, const SkyVariant& base);
  // The pixels the horizon crosses, over what the parts drew there (the caller's depth test off,
  // no depth written).
  void drawHorizonEdge(const Frame& f, const SkyVariant& base);

  int slicesPerFrame_;
  // Inside the atmosphere, by variant (program()).
  std::map<SkyVariant, std::unique_ptr<Program>> programs_;
  std::unique_ptr<Program> reference_;  // another inside fragment, drawn alone (the reference)
  Program space_;
  GlProgram sliceProgram_;
  GLint sliceCoordsLocation_ = -1;
  Slice sunSlice_, moonSlice_;
  int sliceWidth_ = 0, sliceHeight_ = 0;
  TableSet current_;
  std::unique_ptr<Pending> pending_;
  std::size_t lastUploadBytes_ = 0;
  weather::FogLayers fog_{};
  std::shared_ptr<const std::vector<glm::vec4>> fogPrecomputed_;
  double fogPrecomputedHeightM_ = -1.0;
  std::unique_ptr<FogTableTexture> fogTable_ = std::make_unique<FogTableTexture>();
  std::array<weather::CloudCover, sky::kCloudLayers> cover_{};
  weather::FogLayers fogClear_{};
  std::shared_ptr<const std::vector<glm::vec4>> fogClearPrecomputed_;
  std::unique_ptr<FogTableTexture> fogClearTable_ = std::make_unique<FogTableTexture>();
  double cloudLightLowestZ_ = 1.0;
  double pixelAngleRad_ = 1e-3;
  double sunThroughFog_ = 1.0;  // this frame's lowest light drawn, the sine of its elevation
  GLuint cloudLightTable_ = 0;  // kCloudLightTableSize x 6, RGBA32F, made at first use
  std::array<double, sky::kCloudLayers + 2> cloudLightKey_{};  // faces, eye, model of what it holds
  double lastUploadSeconds_ = 0.0;
  CloudFieldView cloudField_;
};

}  // namespace skyig::render
