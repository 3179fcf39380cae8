#include "render/passes/tone/tone_pass.h"

#include "render/glsl/bindings.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace skyig::render {

GlareGrid glareGrid(const glm::dmat3& ndcToWorld, int width, int height, const std::vector<glm::dvec3>& sources,
                    int cellPx) {
  GlareGrid g;
  g.cellPx = std::max(cellPx, 1);
  g.columns = (width + g.cellPx - 1) / g.cellPx;
  g.rows = (height + g.cellPx - 1) / g.cellPx;
  const int vx = g.columns + 1, vy = g.rows + 1;
  // The grid's vertex (i, j) as render/glsl/pixel_grid.glsl places it, unnormalised: the view through
  // the pixel corner (i, j) x cellPx is corner + i stepX + j stepY, on the image plane.
  const glm::dvec3 corner = ndcToWorld * glm::dvec3(-1.0, -1.0, 1.0);
  const glm::dvec3 stepX = ndcToWorld * glm::dvec3(2.0 * g.cellPx / std::max(width, 1), 0.0, 0.0);
  const glm::dvec3 stepY = ndcToWorld * glm::dvec3(0.0, 2.0 * g.cellPx / std::max(height, 1), 0.0);
  // The widest cell edge: a segment of length L on a plane at distance f from the eye subtends at
  // most 2 atan(L / 2f), the angle of the segment centred on the plane's point nearest the eye
  // (so this bounds every edge, and equals the widest where that point is in view).
  const double f = std::abs(glm::dot(glm::normalize(glm::cross(stepX, stepY)), corner));
  g.cellAngleRad = 2.0 * std::atan(std::max(glm::length(stepX), glm::length(stepY)) / (2.0 * f));
  const double cosNear = std::cos(std::min(kGlareExactCells * g.cellAngleRad, 3.14159265358979));
  for (std::size_t s = 0; s < std::min<std::size_t>(sources.size(), 2); ++s) {
    const glm::dvec3 source = glm::normalize(sources[s]);
    int x0 = g.columns, x1 = 0, y0 = g.rows, y1 = 0;
    // A vertex d is near where d . s > cosNear |d|: along a row, d . s and |d|^2 are a line and a
    // parabola in i, so the test takes a few products, no square root (but past 90 degrees).
    const double b = glm::dot(stepX, source), c = glm::dot(stepX, stepX);
    for (int j = 0; j < vy; ++j) {
      const glm::dvec3 rowStart = corner + static_cast<double>(j) * stepY;
      const double a = glm::dot(rowStart, source), a2 = glm::dot(rowStart, rowStart), b2 = 2.0 * glm::dot(rowStart, stepX);
      for (int i = 0; i < vx; ++i) {
        const double x = i, ds = a + x * b, d2 = a2 + x * (b2 + x * c);
        const bool near = cosNear > 0.0 ? ds > 0.0 && ds * ds > cosNear * cosNear * d2 : ds > cosNear * std::sqrt(d2);
        if (!near) continue;
        // The cells that share this vertex.
        x0 = std::min(x0, i - 1);
        x1 = std::max(x1, i + 1);
        y0 = std::min(y0, j - 1);
        y1 = std::max(y1, j + 1);
      }
    }
    if (x1 > x0 && y1 > y0)
      g.nearBoxes[s] = glm::ivec4(std::max(x0, 0), std::min(x1, g.columns), std::max(y0, 0), std::min(y1, g.rows));
  }
  return g;
}

TonePass::TonePass() { glCreateVertexArrays(1, &emptyVao_); }

TonePass::~TonePass() { glDeleteVertexArrays(1, &emptyVao_); }

std::string TonePass::defines(Veil veil) const {
  std::string d = variant_.tumblinRushmeier ? "#define SKYIG_TONE_TUMBLIN_RUSHMEIER\n" : "#define SKYIG_TONE_CURVE\n";
  if (veil != Veil::kNone) d += "#define SKYIG_GLARE " + std::to_string(sources_) + "\n";
  if (veil == Veil::kGrid)
    d += "#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX " + std::to_string(kGlareCellPx) + ".0\n";
  if (veil == Veil::kNightLayer) d += "#define SKYIG_GLARE_FROM_NIGHT_LAYER\n";
  if (variant_.photopic) d += "#define SKYIG_PHOTOPIC\n";
  return d;
}

const GlProgram& TonePass::program(Veil veil, bool starQuads) {
  // The tone pass reads the night's layer with the cell the sky pass's own define gives it.
  const std::string d = defines(veil) + (veil == Veil::kNightLayer ? nightLayerCellDefine(night_) : std::string());
  std::unique_ptr<GlProgram>& p = programs_[{d, starQuads}];
  // Over the stars' quads: their vertex stage exactly as the displayed-star pass compiled it (no
  // defines), so the quads fall where it drew; the fragment is this frame's variant.
  if (!p)
    p = starQuads ? std::make_unique<GlProgram>("render/passes/night/star_display.vert", "", "render/passes/tone/tone.frag", d)
                  : std::make_unique<GlProgram>("render/glsl/fullscreen.vert", "render/passes/tone/tone.frag", d);
  return *p;
}

void TonePass::prepare(const Variant& variant, const glm::dmat3& ndcToWorld, int width, int height,
                       const std::vector<glm::dvec3>& glareSources, const NightLayer& night) {
  variant_ = variant;
  sources_ = static_cast<int>(std::min<std::size_t>(glareSources.size(), 2));
  width_ = width;
  height_ = height;
  grid_ = GlareGrid{};
  night_ = NightLayer{};
  veil_ = Veil::kNone;
  if (sources_ == 0) return;
  if (sources_ == 1 && night.texture != 0 && night.veil) {
    veil_ = Veil::kNightLayer;
    night_ = night;
    grid_ = glareGrid(ndcToWorld, width, height, glareSources, night.cellPx);
    bindVeil();
    return;
  }
  veil_ = Veil::kGrid;
  grid_ = glareGrid(ndcToWorld, width, height, glareSources);
  if (!veilGrid_ || veilGrid_->width() != grid_.columns + 1 || veilGrid_->height() != grid_.rows + 1) {
    veilGrid_ = std::make_unique<RenderTarget>(grid_.columns + 1, grid_.rows + 1, GL_RGBA32F);
    veilGrid_->readBilinear();
  }
  std::unique_ptr<GlProgram>& veil = veilPrograms_[static_cast<std::size_t>(sources_ - 1)];
  if (!veil)
    veil = std::make_unique<GlProgram>("render/glsl/fullscreen.vert", "render/passes/tone/glare_veil.frag",
                                       "#define SKYIG_GLARE " + std::to_string(sources_) + "\n#define SKYIG_GLARE_CELL_PX " +
                                           std::to_string(kGlareCellPx) + ".0\n");
  glBindVertexArray(emptyVao_);
  veilGrid_->bindForDrawing();
  veil->use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  bindVeil();
}

void TonePass::bindVeil() const {
  if (veil_ == Veil::kGrid) glBindTextureUnit(SKYIG_UNIT_GLARE_VEIL, veilGrid_->texture());
  // Either of the layer's two targets: both hold the veil in alpha.
  if (veil_ == Veil::kNightLayer) glBindTextureUnit(SKYIG_UNIT_NIGHT_LAYER, night_.texture);
}

void TonePass::draw(const RenderTarget& target) {
  glBindVertexArray(emptyVao_);
  target.bindForDrawing();
  bindVeil();
  // Every pixel with the veil read from the grid, then those near a source again with the veil
  // per pixel.
  program(veil_, false).use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  drawNearBoxes();
}

FoldedTone TonePass::folded() const {
  FoldedTone f{defines(veil_), {}, {}};
  if (sources_ > 0) {
    f.exactDefines = defines(Veil::kPerPixel);
    f.exactBoxes = nearBoxPixels();
  }
  return f;
}

void TonePass::drawOver(const RenderTarget& target, std::span<const glm::ivec4> rectangles,
                        const std::function<void(const GlProgram&)>& drawQuads) {
  glBindVertexArray(emptyVao_);
  target.bindForDrawing();
  bindVeil();
  program(veil_, false).use();
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& r : rectangles) {
    if (r.z <= 0 || r.w <= 0) continue;
    glScissor(r.x, r.y, r.z, r.w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
  drawQuads(program(veil_, true));
  if (sources_ == 0) return;
  // The sky pass mapped the boxes with the veil per pixel (folded()): what was drawn over them
  // is mapped so again, each pixel's last value the one draw() would give it.
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& box : nearBoxPixels()) {
    glBindVertexArray(emptyVao_);
    program(Veil::kPerPixel, false).use();
    for (const glm::ivec4& r : rectangles) {
      const glm::ivec2 lo = glm::max(glm::ivec2(r.x, r.y), glm::ivec2(box.x, box.y));
      const glm::ivec2 hi = glm::min(glm::ivec2(r.x + r.z, r.y + r.w), glm::ivec2(box.x + box.z, box.y + box.w));
      if (r.z <= 0 || r.w <= 0 || hi.x <= lo.x || hi.y <= lo.y) continue;
      glScissor(lo.x, lo.y, hi.x - lo.x, hi.y - lo.y);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glScissor(box.x, box.y, box.z, box.w);
    drawQuads(program(Veil::kPerPixel, true));
  }
  glDisable(GL_SCISSOR_TEST);
}

std::vector<glm::ivec4> TonePass::nearBoxPixels() const {
  std::vector<glm::ivec4> boxes;
  if (sources_ == 0) return boxes;
  for (const glm::ivec4& b : grid_.nearBoxes) {
    if (b.x >= b.y || b.z >= b.w) continue;
    const int x0 = b.x * grid_.cellPx, y0 = b.z * grid_.cellPx;
    boxes.emplace_back(x0, y0, std::min(b.y * grid_.cellPx, width_) - x0, std::min(b.w * grid_.cellPx, height_) - y0);
  }
  return boxes;
}

void TonePass::drawNearBoxes() {
  if (sources_ == 0) return;
  program(Veil::kPerPixel, false).use();
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& b : nearBoxPixels()) {
    glScissor(b.x, b.y, b.z, b.w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace skyig::render
