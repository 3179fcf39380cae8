#include "services/frame_files.h"

#include <cstdio>
#include <filesystem>

namespace skyig::services {

std::string frameStem(const std::string& dir, std::uint64_t frame, const ephemeris::UtcTime& t,
                      const std::string& channel) {
  std::string time = ephemeris::formatIso8601Utc(t);
  for (char& c : time)
    if (c == ':') c = '-';
  char number[24];
  std::snprintf(number, sizeof number, "%06llu", static_cast<unsigned long long>(frame));
  return (std::filesystem::path(dir) / ("frame_" + std::string(number) + "_" + time + (channel.empty() ? "" : "_" + channel)))
      .string();
}

int writeFrameFiles(const render::SkyRenderer& renderer, const std::string& stem, const sky::ChannelConfig& channel,
                    bool exr, bool png, const render::ImageAttributes& attributes) {
  int written = 0;
  if (exr) {
    render::writeExr(stem + ".exr", renderer.readHdr(), attributes);
    ++written;
  }
  if (png) {
    render::writePng(stem + ".png", renderer.readDisplay(), channel.display.gamma);
    ++written;
  }
  return written;
}

}  // namespace skyig::services
