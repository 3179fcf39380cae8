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

const GlProgram& TonePass::program(const Variant& variant, int glareSources, bool fromGrid) {
  std::unique_ptr<GlProgram>& p = programs_[static_cast<std::size_t>(
      (variant.tumblinRushmeier ? 12 : 0) + (fromGrid ? 6 : 0) + 2 * glareSources + (variant.photopic ? 1 : 0))];
  if (!p) {
    std::string defines = variant.tumblinRushmeier ? "#define SKYIG_TONE_TUMBLIN_RUSHMEIER\n" : "#define SKYIG_TONE_CURVE\n";
    if (glareSources > 0) defines += "#define SKYIG_GLARE " + std::to_string(glareSources) + "\n";
    if (fromGrid) defines += "#define SKYIG_GLARE_FROM_GRID\n#define SKYIG_GLARE_CELL_PX " + std::to_string(kGlareCellPx) + ".0\n";
    if (variant.photopic) defines += "#define SKYIG_PHOTOPIC\n";
    p = std::make_unique<GlProgram>("passes/fullscreen.vert", "passes/tone.frag", defines);
  }
  return *p;
}

void TonePass::draw(const Variant& variant, const glm::dmat3& ndcToWorld, const RenderTarget& target,
                    const std::vector<glm::dvec3>& glareSources) {
  glBindVertexArray(emptyVao_);
  const int n = static_cast<int>(std::min<std::size_t>(glareSources.size(), 2));
  const int width = target.width(), height = target.height();
  if (n == 0) {
    target.bindForDrawing();
    program(variant, n, false).use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  const GlareGrid g = glareGrid(ndcToWorld, width, height, glareSources);
  // The veil at the grid's vertices.
  if (!veil_ || veil_->width() != g.columns + 1 || veil_->height() != g.rows + 1) {
    veil_ = std::make_unique<RenderTarget>(g.columns + 1, g.rows + 1, GL_RGBA32F);
    glTextureParameteri(veil_->texture(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(veil_->texture(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(veil_->texture(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(veil_->texture(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  std::unique_ptr<GlProgram>& veil = veilPrograms_[static_cast<std::size_t>(n - 1)];
  if (!veil)
    veil = std::make_unique<GlProgram>("passes/fullscreen.vert", "passes/glare_veil.frag",
                                       "#define SKYIG_GLARE " + std::to_string(n) + "\n#define SKYIG_GLARE_CELL_PX " +
                                           std::to_string(kGlareCellPx) + ".0\n");
  veil_->bindForDrawing();
  veil->use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Every pixel with the veil read from the grid, then those near a source again with the veil
  // per pixel (overlapping boxes draw the same values twice).
  target.bindForDrawing();
  glBindTextureUnit(SKYIG_UNIT_GLARE_VEIL, veil_->texture());
  program(variant, n, true).use();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  program(variant, n, false).use();
  glEnable(GL_SCISSOR_TEST);
  for (const glm::ivec4& b : g.nearBoxes) {
    if (b.x >= b.y || b.z >= b.w) continue;
    const int x0 = b.x * kGlareCellPx, y0 = b.z * kGlareCellPx;
    glScissor(x0, y0, std::min(b.y * kGlareCellPx, width) - x0, std::min(b.w * kGlareCellPx, height) - y0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace skyig::render
