#pragma once
// Where the night sky's images are read at run time: $SKYIG_DATA_DIR if set (an installed node),
// else the source tree's sky/data (SKYIG_SKY_DATA_DIR, sky/CMakeLists.txt).
#include <cstdlib>
#include <string>

#ifndef SKYIG_SKY_DATA_DIR
#error "SKYIG_SKY_DATA_DIR must name sky/data (sky/CMakeLists.txt)"
#endif

namespace skyig::sky::night {

inline std::string skyDataPath(const std::string& file) {
  const char* dir = std::getenv("SKYIG_DATA_DIR");
  return std::string(dir && *dir ? dir : SKYIG_SKY_DATA_DIR) + "/" + file;
}

}  // namespace skyig::sky::night
