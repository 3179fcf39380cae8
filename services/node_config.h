#pragma once
// A node's configuration (TOML, see config/*.toml): the sky, the default observer for
// `skyig render`, and the display channels. Every value has a default, so an empty file (or
// none) is a valid configuration.
#include "protocol/canaerospace/identifiers.h"
#include "services/host_session.h"
#include "services/host_state.h"
#include "sky/channel.h"
#include "sky/common/sky_conditions.h"
#include "sky/atmosphere/conditions.h"
#include "sky/atmosphere/medium.h"
#include "sky/atmosphere/visibility_blend.h"
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
  // Who may drive the node, how a restart and reordering are told apart (services/host_session.h).
  HostSessionSettings session;
  bool synchronous = false;             // render frame N after the host's frame N
  double syncTimeoutS = 0.1;
  double frameRateHz = 60.0;            // headless pacing
  std::string canInterface;             // SocketCAN interface for a CANaerospace host; empty: none
  int maxViews = static_cast<int>(kDefaultMaxViews);  // view ids 0..maxViews-1 kept (CIGI View Control)
};

// Tables of the physical sky (sky.model = "physical"): their size and cache ([sky]) and the
// medium they are computed for ([atmosphere]; Bruneton's 2017 Earth by default).
struct AtmosphereSettings {
  // "medium" (the default: within 3% of Bruneton's tables up to 5 km, ~28 s once on llvmpipe),
  // "small" (2 s; for tests, coarse at sunset) or "default" (Bruneton's sizes, for a GPU).
  std::string tables = "medium";
  atmosphere::Medium medium;  // the ground albedo comes from sky.ground_albedo
  int scatteringOrders = 4;
  // The visibility (km, Koschmieder) the tables are computed for until the host says otherwise
  // ([atmosphere] visibility_km, `render --visibility`); unset: the medium's own aerosols.
  std::optional<double> visibilityKm;
  std::string cacheDir;          // "" = $CACHE_DIRECTORY (systemd), else $XDG_CACHE_HOME/skyig or ~/.cache/skyig
  // The cache's size bound (least recently used tables evicted; 0: none) and at most one
  // precompute for the host's conditions per buildIntervalS (0: no limit). A distinct
  // visibility must also be held for the debounce time (services/host_atmosphere.h).
  std::uint64_t cacheMaxBytes = 512ull << 20;
  double buildIntervalS = 60.0;
  // Visibilities (km) whose tables `serve` keeps besides the configuration's own ([sky]
  // atmosphere_visibility_steps; built in the background on a first start, or by `skyig
  // precompute`): a host's visibility between two is shown at once as their blend while its
  // exact tables are built (sky/atmosphere/visibility_blend.h). Empty: no blending.
  std::vector<double> visibilityStepsKm = atmosphere::defaultVisibilityStepsKm();
};

// The default sky: the physical atmosphere (Bruneton & Neyret 2008, docs/atmosphere.md).
inline sky::SkyConditions physicalSky() {
  sky::SkyConditions c;
  c.model = sky::SkyModel::Physical;
  return c;
}

// [channel.projector]: the projector a channel is drawn for, warped and blended
// (render/passes/warp_blend_pass.h). Its calibration is read when the channel is first needed
// (services/projector_channel.h), before anything renders; the region's camera, where the file
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
  // The star catalogue (BSC5 CSV) that sky.starCatalogue is loaded from (services/sky_data.h):
  // "" = the bundled one, "none" = planets only.
  std::string starCataloguePath;
  protocol::canaerospace::IdentifierMap canIdentifiers;
  // [eye] adaptation = "temporal": the pilot's eye adapts in time on the host's clock
  // (sky/eye/adaptation.h); "instant": adapted at once to every scene (single-frame renders).
  bool temporalAdaptation = true;

  // The channels node `name` renders: those assigned to it, and those assigned to none.
  std::vector<sky::ChannelConfig> channelsOf(const std::string& name) const;
  // The projector of the channel named `channel` (not enabled() for a plain channel or none).
  ProjectorSettings projectorOf(const std::string& channel) const;
};

// A bad file: what() reads "FILE:LINE: KEY: expected ..., got ..." (the CLI exits with 2).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest configuration file read (whatever the file: a FIFO or /dev/zero included).
inline constexpr std::size_t kMaxConfigBytes = 1u << 20;

// Throws ConfigError for a file that cannot be read, is larger than kMaxConfigBytes or is bad.
NodeConfig loadNodeConfig(const std::string& path);
NodeConfig parseNodeConfig(const std::string& text, const std::string& sourceName);

}  // namespace skyig::services
