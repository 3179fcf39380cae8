# Every dependency is a Debian 12 package (deploy/setup.sh installs them); the CMake names
# below are the config files and Find modules those packages install.
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(OpenEXR 3 REQUIRED)
find_package(PNG REQUIRED)
find_package(Threads REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(tomlplusplus 3 REQUIRED)

# GeographicLib: Debian ships only a Find module, off the default path, and no target.
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)
if(NOT TARGET GeographicLib::GeographicLib)
  add_library(GeographicLib::GeographicLib INTERFACE IMPORTED)
  target_link_libraries(GeographicLib::GeographicLib INTERFACE ${GeographicLib_LIBRARIES})
  target_include_directories(GeographicLib::GeographicLib SYSTEM INTERFACE ${GeographicLib_INCLUDE_DIRS})
endif()

if(SKYIG_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(SKYIG_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
