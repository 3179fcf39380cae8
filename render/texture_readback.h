#pragma once
// A texture's pixels read back to the CPU as images, top row first (GL's rows start at the
// bottom): the renderer's targets and the projector's.
#include "render/image.h"

#include <glad/gl.h>

namespace skyig::render {

HdrImage readFloatTexture(GLuint texture, int width, int height);    // RGBA float
DisplayImage readDisplayTexture(GLuint texture, int width, int height);  // RGBA 8-bit

}  // namespace skyig::render
