#pragma once
// A channel and the projector it is drawn for ([channel.projector], node/config/node_config.h):
// its calibration read once, before anything renders, and the channel as the renderer draws it
// for the projector (SkyRenderer::drawProjector).
#include "calibration/projector.h"
#include "node/config/node_config.h"
#include "sky/channel.h"

#include <memory>

namespace skyig::services {

struct ProjectorChannel {
  // As drawn: for a projector, the region's offset and frustum where the calibration gives a
  // camera, and the projector's resolution unless the configuration gave the channel a size.
  sky::ChannelConfig channel;
  std::shared_ptr<const calibration::ProjectorCalibration> projector;  // null: a plain channel
};

// The channel with its projector read from `settings` (a plain channel when it names none).
// Throws ConfigError with the calibration's message (the file and the element) when the file
// cannot be read or is bad: the CLI exits 2 before anything renders.
ProjectorChannel loadProjectorChannel(const sky::ChannelConfig& channel, const ProjectorSettings& settings);

}  // namespace skyig::services
