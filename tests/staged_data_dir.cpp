// Linked into every test program and benchmark (tests/CMakeLists.txt): they live beside their
// sources in the build tree, not in build/bin, so skyig's executable-relative data directory
// (ephemeris/data_files.h) would miss the files cmake/DataFiles.cmake stages. Unless the caller
// chose another, SKYIG_DATA_DIR names the staged copy, for ctest and direct runs alike.
#include <cstdlib>

namespace {

[[maybe_unused]] const bool kDataDirSet = ::setenv("SKYIG_DATA_DIR", SKYIG_STAGED_DATA_DIR, /*overwrite=*/0) == 0;

}  // namespace
