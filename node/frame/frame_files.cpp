#include "node/frame/frame_files.h"

#include "node/frame/frame_metadata.h"

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

int writeFrameImages(const render::SkyRenderer& renderer, const std::string& exrPath, const std::string& pngPath,
                     const sky::ChannelConfig& channel, const render::ImageAttributes& attributes,
                     const calibration::ProjectorCalibration* projector) {
  int written = 0;
  if (!exrPath.empty()) {
    render::ImageAttributes all = attributes;
    if (projector) addProjectorAttributes(all, *projector);
    render::writeExr(exrPath, projector ? renderer.readProjectorHdr() : renderer.readHdr(), all);
    ++written;
  }
  if (!pngPath.empty()) {
    render::writePng(pngPath, projector ? renderer.readProjectorDisplay() : renderer.readDisplay(), channel.display.gamma);
    ++written;
  }
  return written;
}

int writeFrameFiles(const render::SkyRenderer& renderer, const std::string& stem, const sky::ChannelConfig& channel,
                    bool exr, bool png, const render::ImageAttributes& attributes,
                    const calibration::ProjectorCalibration* projector) {
  return writeFrameImages(renderer, exr ? stem + ".exr" : "", png ? stem + ".png" : "", channel, attributes, projector);
}

}  // namespace skyig::services
