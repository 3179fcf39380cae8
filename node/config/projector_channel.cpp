#include "node/config/projector_channel.h"

#include "calibration/load.h"
#include "render/sky_renderer.h"

#include <spdlog/spdlog.h>

#include <string>

namespace skyig::services {

ProjectorChannel loadProjectorChannel(const sky::ChannelConfig& channel, const ProjectorSettings& settings) {
  ProjectorChannel out{channel, nullptr};
  if (!settings.enabled()) return out;
  // A Bourke mesh names no resolution: it is shown on a projector of the channel's size.
  const calibration::ProjectorSource source =
      settings.mpcdi.empty()
          ? calibration::bourkeSource(settings.bourkeMesh, channel.width, channel.height)
          : calibration::mpcdiSource(settings.mpcdi, settings.region,
                                     settings.warpOffsets ? calibration::WarpValues::Offset
                                                          : calibration::WarpValues::Absolute);
  std::shared_ptr<const calibration::ProjectorCalibration> projector;
  try {
    projector = std::make_shared<const calibration::ProjectorCalibration>(calibration::loadProjector(source));
  } catch (const calibration::CalibrationError& e) {
    throw ConfigError(std::string(e.what()) + " (channel " + channel.name + "'s projector)");
  }
  for (const std::string& w : projector->warnings) spdlog::warn("{} (channel {}'s projector)", w, channel.name);
  out.channel = render::SkyRenderer::projectorChannel(channel, *projector);  // the camera the renderer draws
  if (!settings.sizeGiven) {
    if (projector->width < sky::kMinChannelSide || projector->width > sky::kMaxChannelSide ||
        projector->height < sky::kMinChannelSide || projector->height > sky::kMaxChannelSide)
      throw ConfigError(projector->source + ": a projector of " + std::to_string(projector->width) + "x" +
                        std::to_string(projector->height) + " pixels: give channel " + channel.name +
                        " a width and height in " + std::to_string(sky::kMinChannelSide) + ".." +
                        std::to_string(sky::kMaxChannelSide));
    out.channel.width = projector->width;
    out.channel.height = projector->height;
  }
  out.projector = projector;
  return out;
}

}  // namespace skyig::services
