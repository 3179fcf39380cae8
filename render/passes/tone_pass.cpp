#include "render/passes/tone_pass.h"

#include "shaders/common/bindings.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace skyig::render {

GlareGrid glareGrid(const glm::dmat3& ndcToWorld, int width, int height, const std::vector<glm::dvec3>& sources) {
  GlareGrid g;
  g.columns = (width + kGlareCellPx - 1) / kGlareCellPx;
  g.rows = (height + kGlareCellPx - 1) / kGlareCellPx;
  const int vx = g.columns + 1, vy = g.rows + 1;
  // The grid's vertices as unit view directions, as passes/glare_veil.frag places them.
  std::vector<glm::dvec3> v(static_cast<std::size_t>(vx) * vy);
  for (int j = 0; j < vy; ++j)
    for (int i = 0; i < vx; ++i) {
      const double px = i * kGlareCellPx, py = j * kGlareCellPx;
      v[static_cast<std::size_t>(j) * vx + i] =
          glm::normalize(ndcToWorld * glm::dvec3(2.0 * px / width - 1.0, 2.0 * py / height - 1.0, 1.0));
    }
  // The widest cell edge's angle.
  double minCos = 1.0;
  for (int j = 0; j < vy; ++j)
    for (int i = 0; i < vx; ++i) {
      const glm::dvec3& a = v[static_cast<std::size_t>(j) * vx + i];
      if (i + 1 < vx) minCos = std::min(minCos, glm::dot(a, v[static_cast<std::size_t>(j) * vx + i + 1]));
      if (j + 1 < vy) minCos = std::min(minCos, glm::dot(a, v[static_cast<std::size_t>(j + 1) * vx + i]));
    }
  g.cellAngleRad = std::acos(std::clamp(minCos, -1.0, 1.0));
  const double cosNear = std::cos(std::min(kGlareExactCells * g.cellAngleRad, 3.14159265358979));
  for (std::size_t s = 0; s < std::min<std::size_t>(sources.size(), 2); ++s) {
    int x0 = g.columns, x1 = 0, y0 = g.rows, y1 = 0;
    for (int j = 0; j < vy; ++j)
      for (int i = 0; i < vx; ++i)
        if (glm::dot(v[static_cast<std::size_t>(j) * vx + i], sources[s]) > cosNear) {
          // The cells that share this vertex.
          x0 = std::min(x0, i - 1);
          x1 = std::max(x1, i + 1);
          y0 = std::min(y0, j - 1);
          y1 = std::max(y1, j + 1);
        }
    if (x1 > x0 && y1 > y0)
      g.nearBoxes[s] = glm::ivec4(std::max(x0, 0), std::min(x1, g.columns), std::max(y0, 0), std::min(y1, g.rows));
  }
  return g;
}

TonePass::TonePass() { glCreateVertexArrays(1, &emptyVao_); }

TonePass::~TonePass() { glDeleteVertexArrays(1, &emptyVao_); }

std::string TonePass::defines(const Variant& variant, int glareSources, bool fromGrid) {
  std::string d = variant.tumblinRushmeier ? "#define SKYIG_TONE_TUMBLIN_RUSHMEIER\n" : "#define SKYIG_TONE_CURVE\n";
  if (glareSources > 0) d += "#define SKYIG_GLARE " + std::to_string(glareSources) + "\n";
  if (fromGrid) d += "#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX " + std::to_string(kGlareCellPx) + ".0\n";
  if (variant.photopic) d += "#define SKYIG_PHOTOPIC\n";
  return d;
}

const GlProgram& TonePass::program(const Variant& variant, int glareSources, bool fromGrid) {
  std::unique_ptr<GlProgram>& p = programs_[static_cast<std::size_t>(
      (variant.tumblinRushmeier ? 12 : 0) + (fromGrid ? 6 : 0) + 2 * glareSources + (variant.photopic ? 1 : 0))];
  if (!p) p = std::make_unique<GlProgram>("passes/fullscreen.vert", "passes/tone.frag", defines(variant, glareSources, fromGrid));
  return *p;
}

void TonePass::prepare(const Variant& variant, const glm::dmat3& ndcToWorld, int width, int height,
                       const std::vector<glm::dvec3>& glareSources) {
  variant_ = variant;
  sources_ = static_cast<int>(std::min<std::size_t>(glareSources.size(), 2));
  width_ = width;
  height_ = height;
  grid_ = GlareGrid{};
  if (sources_ == 0) return;
  grid_ = glareGrid(ndcToWorld, width, height, glareSources);
  if (!veil_ || veil_->width() != grid_.columns + 1 || veil_->height() != grid_.rows + 1) {
    veil_ = std::make_unique<RenderTarget>(grid_.columns + 1, grid_.rows + 1, GL_RGBA32F);
    veil_->readBilinear();
  }
  std::unique_ptr<GlProgram>& veil = veilPrograms_[static_cast<std::size_t>(sources_ - 1)];
  if (!veil)
    veil = std::make_unique<GlProgram>("passes/fullscreen.vert", "passes/glare_veil.frag",
                                       "#define SKYIG_GLARE " + std::to_string(sources_) + "\n#define SKYIG_GLARE_CELL_PX " +
                                           std::to_string(kGlareCellPx) + ".0\n");
  glBindVertexArray(emptyVao_);
  veil_->bindForDrawing();
  veil->use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(SKYIG_UNIT_GLARE_VEIL, veil_->texture());
}

void TonePass::draw(const RenderTarget& target) {
  glBindVertexArray(emptyVao_);
  target.bindForDrawing();
  // Every pixel with the veil read from the grid, then those near a source again with the veil
  // per pixel.
  program(variant_, sources_, sources_ > 0).use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  drawNearBoxes();
}

FoldedTone TonePass::folded() const {
  FoldedTone f{defines(variant_, sources_, sources_ > 0), {}, {}};
  if (sources_ > 0) {
    f.exactDefines = defines(variant_, sources_, false);
    f.exactBoxes = nearBoxPixels();
  }
  return f;
}

const GlProgram& TonePass::starQuadProgram(bool fromGrid) {
  std::unique_ptr<GlProgram>& quads = starQuadPrograms_[static_cast<std::size_t>(
      (variant_.tumblinRushmeier ? 12 : 0) + (fromGrid ? 6 : 0) + 2 * sources_ + (variant_.photopic ? 1 : 0))];
  // The stars' vertex stage exactly as the displayed-star pass compiled it (no defines), so the
  // quads fall where it drew; the fragment is this frame's variant.
  if (!quads)
    quads = std::make_unique<GlProgram>("passes/star_display.vert", "", "passes/tone.frag",
                                        defines(variant_, sources_, fromGrid));
  return *quads;
}

void TonePass::drawOver(const RenderTarget& target, std::span<const glm::ivec4> rectangles,
                        const std::function<void(const GlProgram&)>& drawQuads) {
  glBindVertexArray(emptyVao_);
  target.bindForDrawing();
  program(variant_, sources_, sources_ > 0).use();
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& r : rectangles) {
    if (r.z <= 0 || r.w <= 0) continue;
    glScissor(r.x, r.y, r.z, r.w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
  drawQuads(starQuadProgram(sources_ > 0));
  if (sources_ == 0) return;
  // The sky pass mapped the boxes with the veil per pixel (folded()): what was drawn over them
  // is mapped so again, each pixel's last value the one draw() would give it.
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& box : nearBoxPixels()) {
    glBindVertexArray(emptyVao_);
    program(variant_, sources_, false).use();
    for (const glm::ivec4& r : rectangles) {
      const glm::ivec2 lo = glm::max(glm::ivec2(r.x, r.y), glm::ivec2(box.x, box.y));
      const glm::ivec2 hi = glm::min(glm::ivec2(r.x + r.z, r.y + r.w), glm::ivec2(box.x + box.z, box.y + box.w));
      if (r.z <= 0 || r.w <= 0 || hi.x <= lo.x || hi.y <= lo.y) continue;
      glScissor(lo.x, lo.y, hi.x - lo.x, hi.y - lo.y);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glScissor(box.x, box.y, box.z, box.w);
    drawQuads(starQuadProgram(false));
  }
  glDisable(GL_SCISSOR_TEST);
}

std::vector<glm::ivec4> TonePass::nearBoxPixels() const {
  std::vector<glm::ivec4> boxes;
  if (sources_ == 0) return boxes;
  for (const glm::ivec4& b : grid_.nearBoxes) {
    if (b.x >= b.y || b.z >= b.w) continue;
    const int x0 = b.x * kGlareCellPx, y0 = b.z * kGlareCellPx;
    boxes.emplace_back(x0, y0, std::min(b.y * kGlareCellPx, width_) - x0, std::min(b.w * kGlareCellPx, height_) - y0);
  }
  return boxes;
}

void TonePass::drawNearBoxes() {
  if (sources_ == 0) return;
  program(variant_, sources_, false).use();
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& b : nearBoxPixels()) {
    glScissor(b.x, b.y, b.z, b.w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace skyig::render
