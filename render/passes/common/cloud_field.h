#pragma once
// The broken decks' fields as render/passes/common/cloud_field.glsl reads them: one upload for
// every program that evaluates a field (the physical sky pass, the night's diffuse light), so
// each sees the same cloud and the same gaps.
#include "physics/weather/cloud_deck.h"
#include "physics/weather/fog_layer.h"
#include "physics/common/cloud_layer.h"

#include <glad/gl.h>

#include <array>

namespace skyig::render {

using CloudCovers = std::array<weather::CloudCover, sky::kCloudLayers>;

// The broken decks among `layers` (a deck whose field is broken and whose layer has
// extinction): the n of a program's SKYIG_CLOUD_COVER.
int brokenDeckCount(const CloudCovers& cover, const weather::FogLayers& layers);

// A program's cloud-field uniforms, looked up once (-1 in a program without the field).
struct CloudFieldLocations {
  explicit CloudFieldLocations(GLuint program);
  bool present() const { return shape >= 0; }
  GLint shape, place, along, eye;
};

// The broken decks' fields for an eye heightM above a ground of radius bottomRadiusM, into
// `program` (nothing where it has no field).
void setCloudField(GLuint program, const CloudFieldLocations& at, const CloudCovers& cover,
                   const weather::FogLayers& layers, double heightM, double bottomRadiusM);

// The broken decks one sky pass drew, for a pass over it that looks through them (the night's
// light in a goggle): their fields, the layers, the eye, and the sky pass's weather tables of
// the same frame with the decks' gaps filled and without the decks (1D textures).
struct CloudFieldView {
  CloudCovers cover{};
  weather::FogLayers layers{};
  double heightM = 0.0, bottomRadiusM = 0.0;
  GLuint cloudedTable = 0, clearTable = 0;
  int broken() const { return cloudedTable != 0 && clearTable != 0 ? brokenDeckCount(cover, layers) : 0; }
};

}  // namespace skyig::render
