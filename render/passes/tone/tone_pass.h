#pragma once
// The tone pass (render/passes/tone/tone.frag): the HDR image and the displayed point sources in,
// display values out, compiled in variants so that no pixel pays for what the state does not
// show: the display's operator, photopic only, and the eye's glare veil of the sources that give
// light. The veil (CIE 146:2002, physics/eye/glare.glsl) is smooth away from its source, so it is
// evaluated at the vertices of a grid of cells a few pixels wide and read bilinearly
// (render/glsl/pixel_grid.glsl), and per pixel only in a box of cells around each source,
// where it is steep: out to kGlareExactCells cells' angle from the source. The grid is a small
// target of its own (kGlareCellPx-pixel cells, render/passes/tone/glare_veil.frag) or, on a night with one
// glare source, the night's layer, whose alpha holds it (render/passes/common/night_layer.h): the sky
// pass reads that layer at every pixel anyway. Beyond the boxes, interpolating its 1/theta^2
// term over a cell of angle a errs by at most about 1.5 (a / theta)^2 of the veil (its Hessian
// is 6 b / theta^4), under 0.6%, whatever the cell; measured, the display codes differ from the
// per-pixel veil's by at most 1 (docs/performance.md).
// The same mapping runs in the physical sky pass (folded), the boxes' too; the pass then maps
// again only where later passes drew (drawOver).
#include "render/gl/gl_program.h"
#include "render/passes/tone/folded_tone.h"
#include "render/passes/common/night_layer.h"
#include "render/gl/render_target.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace skyig::render {

inline constexpr int kGlareCellPx = 8;
inline constexpr double kGlareExactCells = 18.0;

// The grid of a channel, columns x rows cells of cellPx pixels from the bottom-left corner (the
// last ones may reach past the viewport; its vertices are those of render/glsl/pixel_grid.glsl), and
// the boxes of cells (x0, x1, y0, y1: [x0, x1) x [y0, y1)) around the sources where the veil is
// evaluated per pixel: every cell with a corner within kGlareExactCells cells' angle of a source
// (the angle of the widest cell edge of the grid), so every pixel outside the boxes is at least
// kGlareExactCells - 1 cells' angle from each source. An empty box has x0 = x1.
struct GlareGrid {
  int cellPx = kGlareCellPx;
  int columns = 0, rows = 0;
  std::array<glm::ivec4, 2> nearBoxes{};
  double cellAngleRad = 0.0;
};
GlareGrid glareGrid(const glm::dmat3& ndcToWorld, int width, int height, const std::vector<glm::dvec3>& sources,
                    int cellPx = kGlareCellPx);

class TonePass {
 public:
  struct Variant {
    bool tumblinRushmeier = false;  // else the scene's histogram curve
    bool photopic = false;          // no part of the view dim enough for rod vision
  };
  TonePass();
  ~TonePass();
  TonePass(const TonePass&) = delete;
  TonePass& operator=(const TonePass&) = delete;

  // A frame's tone starts here: its variant, and the veil's grid of a width x height channel for
  // `glareSources`, the directions of the tone block's glare sources that give light (at most 2,
  // in its order; none: no veil): the night's layer where it holds the veil (night.veil, one
  // source), else the grid's own target, drawn here. The frame and tone blocks must be bound.
  // Then either draw(), or the folded sky pass and drawOver().
  void prepare(const Variant& variant, const glm::dmat3& ndcToWorld, int width, int height,
               const std::vector<glm::dvec3>& glareSources, const NightLayer& night = {});
  // Every pixel of `target`, from the HDR image and the point sources at their units.
  void draw(const RenderTarget& target);
  // What the physical sky pass needs to map its pixels as draw() would (PhysicalSkyPass::draw's
  // `tone`): the defines, and those of the veil per pixel with the boxes where they apply; the
  // veil's grid, or the night's layer that holds it, is bound at its unit by prepare().
  FoldedTone folded() const;
  // After a folded sky pass: `target` again only where later passes drew. The rectangles (x, y,
  // width, height in pixels; the moon's quad), the quads `drawQuads` draws with the program it
  // is given (the displayed stars': StarPass::drawFootprints, with the program of
  // render/passes/night/star_display.vert and the tone fragment), each with the veil from the grid, then
  // again with the veil per pixel where they fall in the boxes of the exact veil.
  void drawOver(const RenderTarget& target, std::span<const glm::ivec4> rectangles,
                const std::function<void(const GlProgram&)>& drawQuads);

 private:
  // Where a program reads the veil.
  enum class Veil { kNone, kPerPixel, kGrid, kNightLayer };
  // The defines of the tone's mapping with the frame's variant and the veil from `veil` (for the
  // sky pass, which reads the night's layer with its own define).
  std::string defines(Veil veil) const;
  // The tone pass's fragment over the whole channel (render/glsl/fullscreen.vert), or over the
  // displayed stars' quads exactly as the displayed-star pass placed them (render/passes/night/star_display.vert).
  const GlProgram& program(Veil veil, bool starQuads);
  // The boxes of the exact veil in pixels (x, y, width, height) within the channel; empty ones left out.
  std::vector<glm::ivec4> nearBoxPixels() const;
  void drawNearBoxes();  // into the bound target
  void bindVeil() const;
  std::map<std::pair<std::string, bool>, std::unique_ptr<GlProgram>> programs_;
  std::array<std::unique_ptr<GlProgram>, 2> veilPrograms_;  // render/passes/tone/glare_veil.frag, 1 or 2 sources
  std::unique_ptr<RenderTarget> veilGrid_;                  // the veil at the grid's vertices
  GLuint emptyVao_ = 0;
  // The frame's, from prepare().
  Variant variant_;
  int sources_ = 0;
  Veil veil_ = Veil::kNone;  // away from the boxes
  NightLayer night_;         // where the veil comes from it
  int width_ = 0, height_ = 0;
  GlareGrid grid_;
};

}  // namespace skyig::render
