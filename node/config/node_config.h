#pragma once
// A node's configuration (TOML, see config/*.toml): the sky, the default observer for
// `skyig render`, and the display channels. Every value has a default, so an empty file (or
// none) is a valid configuration.
#include "protocol/canaerospace/identifiers.h"
#include "node/host/host_session.h"
#include "node/host/host_state.h"
#include "sky/channel.h"
#include "physics/common/sky_conditions.h"
#include "physics/weather/precipitation.h"
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/medium.h"
#include "node/common/config_error.h"
#include "node/config/degradation_settings.h"
#include "tables/settings.h"
#include "sky/sky_state.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::services {

// How this node hears the host and answers it (`skyig serve`).
struct HostLink {
  std::string listen = "0.0.0.0:8004";  // CIGI host -> IG
  std::string multicastGroup;           // empty: unicast
  std::string multicastInterface;       // the interface's IPv4 address the group is joined on; "": listen's address
  int replyPort = 8005;                 // Start of Frame goes back to the host's address on this port
  std::string replyTo;                  // "ADDR:PORT": Start of Frame goes there instead; "" = the host's address
  // Who may drive the node, how a restart and reordering are told apart (node/host/host_session.h).
  HostSessionSettings session;
  bool synchronous = false;             // render frame N after the host's frame N
  double syncTimeoutS = 0.1;
  double frameRateHz = 60.0;            // headless pacing
  std::string canInterface;             // SocketCAN interface for a CANaerospace host; empty: none
  int maxViews = static_cast<int>(kDefaultMaxViews);  // view ids 0..maxViews-1 kept (CIGI View Control)
};

// The default sky: the physical atmosphere (Bruneton & Neyret 2008, docs/atmosphere.md).
inline sky::SkyConditions physicalSky() {
  sky::SkyConditions c;
  c.model = sky::SkyModel::Physical;
  return c;
}

// [channel.projector]: the projector a channel is drawn for, warped and blended
// (render/passes/projector/warp_blend_pass.h). Its calibration is read when the channel is first needed
// (node/config/projector_channel.h), before anything renders; the region's camera, where the file
// gives one, then replaces the channel's yaw/pitch/roll and frustum, and its resolution is the
// channel's render size unless the channel gives width and height.
struct ProjectorSettings {
  std::string mpcdi;          // a VESA MPCDI file (.mpcdi, or its mpcdi.xml); relative to the configuration's folder
  std::string region;         // the region of it that this channel's projector shows
  bool warpOffsets = false;   // warp_values = "offset": the PFM holds offsets from its grid, not coordinates
  std::string bourkeMesh;     // or Paul Bourke's warp mesh; its camera is the channel's own offset and frustum
  bool sizeGiven = false;     // the channel gives width and height
  bool enabled() const { return !mpcdi.empty() || !bourkeMesh.empty(); }
};

struct NodeConfig {
  std::string nodeName = "ig";
  sky::SkyConditions sky = physicalSky();
  sky::ObserverState observer;
  std::vector<sky::ChannelConfig> channels{sky::ChannelConfig{}};
  std::vector<std::string> channelNodes{""};  // per channel: the node that renders it ("" any)
  std::vector<ProjectorSettings> channelProjectors{ProjectorSettings{}};  // per channel: its projector, if any
  HostLink host;
  AtmosphereSettings atmosphere;
  // [weather] precipitation_*: the layer in sky.precipitation until the host sends its own.
  weather::PrecipitationSettings precipitation;
  // The star catalogue (BSC5 CSV) that sky.starCatalogue is loaded from (node/config/sky_data.h):
  // "" = the bundled one, "none" = planets only.
  std::string starCataloguePath;
  protocol::canaerospace::IdentifierMap canIdentifiers;
  // [eye] adaptation = "temporal": the pilot's eye adapts in time on the host's clock
  // (physics/eye/adaptation.h); "instant": adapted at once to every scene (single-frame renders).
  bool temporalAdaptation = true;
  // [degrade]: a lower internal resolution while the node cannot hold its frame rate
  // (node/frame/degradation.h); `skyig serve` only.
  DegradationSettings degrade;

  // The channels node `name` renders: those assigned to it, and those assigned to none.
  std::vector<sky::ChannelConfig> channelsOf(const std::string& name) const;
  // The projector of the channel named `channel` (not enabled() for a plain channel or none).
  ProjectorSettings projectorOf(const std::string& channel) const;
};

// The largest configuration file read (whatever the file: a FIFO or /dev/zero included).
inline constexpr std::size_t kMaxConfigBytes = 1u << 20;

// Throws ConfigError for a file that cannot be read, is larger than kMaxConfigBytes or is bad.
NodeConfig loadNodeConfig(const std::string& path);
NodeConfig parseNodeConfig(const std::string& text, const std::string& sourceName);

}  // namespace skyig::services
