#pragma once
// The set-up the night's whole-renderer GL tests share: one headless context (llvmpipe where
// there is no GPU), one renderer and the small physical-sky tables from the test cache, made once
// for a suite and kept for its tests.
#include "tables/table_cache.h"
#include "render/gl/gl_context.h"
#include "render/sky_renderer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

namespace skyig::night_testing {

class NightGlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = render::createHeadlessContext().release();
    renderer_ = new render::SkyRenderer();
    atmosphere::ModelConfig config;
    config.sizes = atmosphere::TableSizes::small();
    model_ = new std::shared_ptr<const atmosphere::AtmosphereModel>(std::make_shared<const atmosphere::AtmosphereModel>(
        atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache")));
  }
  static void TearDownTestSuite() {
    delete renderer_;
    delete model_;
    delete context_;
    renderer_ = nullptr;
    model_ = nullptr;
    context_ = nullptr;
  }

  static inline render::GlContext* context_ = nullptr;
  static inline render::SkyRenderer* renderer_ = nullptr;
  static inline std::shared_ptr<const atmosphere::AtmosphereModel>* model_ = nullptr;
};

}  // namespace skyig::night_testing
