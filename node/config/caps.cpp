#include "node/config/caps.h"

#include "ephemeris/data_files.h"
#include "render/gl/gl_context.h"
#include "render/gl/swap_group.h"
#include "node/common/version.h"

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace skyig::services {

namespace {

// Whether the kernel offers a socket family (AF_CAN is missing on kernels without CAN).
std::string socketFamilySupport(int family, int type, int protocol) {
  const int fd = ::socket(family, type, protocol);
  if (fd < 0) return std::string("unavailable (") + std::strerror(errno) + ")";
  ::close(fd);
  return "available";
}

// The data directory this process reads (ephemeris/data_files.h) and how it was chosen, so an
// installed node shows it reads its own prefix's share/skyig.
std::string dataDirectorySupport() {
  try {
    const std::filesystem::path dir = ephemeris::dataDirectory();
    const char* environment = std::getenv("SKYIG_DATA_DIR");
    const bool complete = std::filesystem::is_regular_file(dir / "bsc5.csv");
    return dir.string() + (environment && *environment ? " (SKYIG_DATA_DIR)" : " (beside the executable)") +
           (complete ? "" : ", bsc5.csv missing");
  } catch (const ephemeris::DataFileError& e) {
    return std::string("unknown: ") + e.what();
  }
}

// GLX_NV_swap_group: frame-lock hardware the windows join when the driver offers it.
std::string swapBarrierSupport() {
  const render::SwapGroupSupport s = render::querySwapGroupSupport();
  if (!s.available) return "unavailable: " + s.reason + "; nodes keep in step by synchronous CIGI";
  return "GLX_NV_swap_group available (" + std::to_string(s.maxGroups) + " group(s), " +
         std::to_string(s.maxBarriers) + " barrier(s)): windows use group 1, barrier 1";
}

}  // namespace

std::string versionText() {
  std::ostringstream out;
  out << "skyig " << kVersion << " (" << SKYIG_BUILD_TYPE << ", " << SKYIG_COMPILER << ")";
  return out.str();
}

std::string capsText() {
  std::ostringstream out;
  try {
    const auto context = render::createHeadlessContext();
    const render::GlInfo& i = context->info();
    out << "GL renderer:   " << i.renderer << " (" << i.vendor << ")\n"
        << "GL version:    " << i.version << ", GLSL " << i.glslVersion << ", via " << i.platform << "\n"
        << "GL limits:     max texture " << i.maxTextureSize << ", max 3D texture " << i.max3dTextureSize << "\n"
        << "GPU timing:    " << (i.softwareRenderer ? "software renderer: wall clock after glFinish" : "GL timer queries")
        << "\n";
  } catch (const std::exception& e) {
    out << "GL:            unavailable headless: " << e.what() << "\n";
  }
  out << "UDP sockets:   " << socketFamilySupport(AF_INET, SOCK_DGRAM, 0) << "\n"
      << "Swap barrier:  " << swapBarrierSupport() << "\n"
      << "SocketCAN:     " << socketFamilySupport(29 /* PF_CAN */, SOCK_RAW, 1 /* CAN_RAW */) << "\n"
      << "Data files:    " << dataDirectorySupport() << "\n";
  return out.str();
}

}  // namespace skyig::services
