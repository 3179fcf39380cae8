#pragma once
// A test suite whose tests share one headless GL context and one SkyRenderer, made once for the
// suite: the renderer compiles its programs in seconds on llvmpipe.
#include "render/gl/gl_context.h"
#include "render/sky_renderer.h"

#include <gtest/gtest.h>

namespace skyig::render::testing {

class SharedRendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = createHeadlessContext().release();
    renderer_ = new SkyRenderer();
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete context_;
    renderer_ = nullptr;
    context_ = nullptr;
  }
  static inline GlContext* context_ = nullptr;
  static inline SkyRenderer* renderer_ = nullptr;
};

}  // namespace skyig::render::testing
