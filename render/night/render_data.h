#pragma once
// Where the night sky's images are read at run time: $SKYIG_DATA_DIR if set (an installed node),
// else the source tree's render/data (SKYIG_RENDER_DATA_DIR, render/CMakeLists.txt).
#include <cstdlib>
#include <string>

#ifndef SKYIG_RENDER_DATA_DIR
#error "SKYIG_RENDER_DATA_DIR must name render/data (render/CMakeLists.txt)"
#endif

namespace skyig::render::night {

inline std::string renderDataPath(const std::string& file) {
  const char* dir = std::getenv("SKYIG_DATA_DIR");
  return std::string(dir && *dir ? dir : SKYIG_RENDER_DATA_DIR) + "/" + file;
}

}  // namespace skyig::render::night
