#pragma once
// Where skyig reads its data files at run time (bsc5.csv, moon.png, milkyway.png): one rule for
// every library and command, with no path of the source or build tree compiled in.
//   1. $SKYIG_DATA_DIR, when it is set and not empty;
//   2. else, in a host that links libskyig.so (api/), the share/skyig beside the library:
//      <prefix>/<libdir>/libskyig.so reads <prefix>/share/skyig (the relative path is fixed
//      when the library is configured, SKYIG_LIBRARY_TO_DATA), whatever the host's executable;
//   3. else <directory of the running executable>/../share/skyig: /usr/bin/skyig reads
//      /usr/share/skyig, and the build tree's build/bin/skyig reads build/share/skyig, where
//      CMake stages the files (cmake/DataFiles.cmake). Tests set SKYIG_DATA_DIR.
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
// unset), `library` the path of libskyig.so when this code runs inside it (else empty),
// `executable` the running program's path. An empty result: none is known.
std::filesystem::path dataDirectory(const char* environment, const std::filesystem::path& executable,
                                    const std::filesystem::path& library = {});

// The rule above for this process (dladdr for the library, /proc/self/exe). Throws DataFileError when SKYIG_DATA_DIR is
// unset and the executable's path cannot be read.
std::filesystem::path dataDirectory();

// dataDirectory() / name, whether or not the file is there.
std::string dataFilePath(const std::string& name);

// dataFilePath(name) when that is a file; else throws DataFileError naming the path tried and
// how the directory was chosen.
std::string requireDataFile(const std::string& name);

}  // namespace skyig::ephemeris
