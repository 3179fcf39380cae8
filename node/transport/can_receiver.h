#pragma once
// The receiver thread of a CANaerospace host: CAN frames from a raw SocketCAN socket (or any
// stream of struct can_frame records, such as a socketpair in the tests) into the host state.
#include "protocol/canaerospace/state_decoder.h"
#include "node/host/host_snapshot.h"
#include "node/common/latest.h"
#include "node/host/node_stats.h"

#include <atomic>
#include <string>

namespace skyig::services {

// Opens a raw CAN socket bound to `interface` (e.g. "can0"). Throws NetworkError with a
// clear message where the kernel has no CAN support (EAFNOSUPPORT) or the interface is unknown.
int openSocketCan(const std::string& interface);

class CanReceiver {
 public:
  CanReceiver(int fd, const protocol::canaerospace::IdentifierMap& map, NodeStats& stats, Latest<HostSnapshot>& out);
  void run(const std::atomic<bool>& stop);
  void handle(const protocol::canaerospace::CanFrame& frame, Clock::time_point arrival);

 private:
  int fd_;
  NodeStats& stats_;
  HostPublisher out_;
  protocol::canaerospace::StateDecoder decoder_;
  HostState state_;
  OwnshipPredictor predictor_;
  double lastStatedSeconds_ = -1.0;
};

}  // namespace skyig::services
