#pragma once
// Where skyig reads its data files at run time (bsc5.csv, moon.png, milkyway.png): one rule for
// every library and command, with no path of the source or build tree compiled in.
//   1. $SKYIG_DATA_DIR, when it is set and not empty;
//   2. else <directory of the running executable>/../share/skyig: /usr/bin/skyig reads
//      /usr/share/skyig, and the build tree's build/bin/skyig reads build/share/skyig, where
//      CMake stages the files (services/CMakeLists.txt). Tests set SKYIG_DATA_DIR.
// It lives in ephemeris/, the lowest library that reads one of the files (the catalogue).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace skyig::ephemeris {

// A data file is missing or the data directory cannot be found; what() names the path tried and
// SKYIG_DATA_DIR. The CLI exits with 2 (a setup error, like a bad configuration).
class DataFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The rule above with its inputs given: `environment` is SKYIG_DATA_DIR's value (null when
// unset), `executable` the running program's path. An empty result: neither is known.
std::filesystem::path dataDirectory(const char* environment, const std::filesystem::path& executable);

// The rule above for this process (/proc/self/exe). Throws DataFileError when SKYIG_DATA_DIR is
// unset and the executable's path cannot be read.
std::filesystem::path dataDirectory();

// dataDirectory() / name, whether or not the file is there.
std::string dataFilePath(const std::string& name);

// dataFilePath(name) when that is a file; else throws DataFileError naming the path tried and
// how the directory was chosen.
std::string requireDataFile(const std::string& name);

}  // namespace skyig::ephemeris
