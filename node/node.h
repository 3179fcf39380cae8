#pragma once
// The IG node (`skyig serve`): receiver thread -> HostSnapshot -> worker thread (ephemeris,
// sky conditions, adaptation) -> SkyState -> render loop on the calling thread, every channel
// of this node per frame, then Start of Frame to the host (docs/design.md).
#include "node/config/node_config.h"
#include "node/host/node_stats.h"
#include "node/transport/udp_socket.h"

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

namespace skyig::services {

struct NodeOptions {
  NodeConfig config;
  Endpoint listen{"0.0.0.0", 8004};                 // host -> IG
  std::optional<std::string> multicastGroup;
  std::optional<std::string> multicastInterface;    // where the group is joined; default: listen's address
  std::optional<Endpoint> replyTo;                  // Start of Frame; default: the followed host's address
  std::uint16_t replyPort = 8005;                   //   ... on this port
  bool headless = true;
  std::uint64_t frames = 0;                         // stop after this many (0: until signalled)
  double frameRateHz = 60.0;                        // headless pacing (windows follow vsync)
  bool synchronous = false;                         // render frame N after the host's frame N
  double syncTimeoutS = 0.1;
  std::string dumpStatePath;                        // JSON lines, one per frame
  std::string statsPath;                            // JSON, every statsIntervalS and on exit
  std::string recordPath;                           // pcap of every datagram received
  std::string saveFramesDir;                        // every saveEvery-th frame of each channel, EXR + PNG
  std::uint64_t saveEvery = 30;
  double statsIntervalS = 2.0;
  double logIntervalS = 5.0;                        // the frame-timing info line (0: only at exit)
  std::optional<std::string> canInterface;          // SocketCAN interface (CANaerospace host)
  int canFd = -1;                                   // an already open CAN frame stream (tests)
};

// Runs until `stop` is set or options.frames frames were rendered; returns the exit code.
int runNode(const NodeOptions& options, NodeStats& stats, const std::atomic<bool>& stop);

}  // namespace skyig::services
