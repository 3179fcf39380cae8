#pragma once
// The receiver thread of a CIGI node: datagrams in, decoded, applied to the host state and
// published whole (latest wins). Malformed input is counted and logged at a limited rate;
// the last good state is kept.
#include "services/host_snapshot.h"
#include "services/latest.h"
#include "services/node_stats.h"
#include "services/udp_socket.h"

#include <atomic>
#include <mutex>
#include <optional>

namespace skyig::services {

class CigiReceiver {
 public:
  CigiReceiver(UdpSocket& socket, NodeStats& stats, Latest<HostSnapshot>& out);
  // Runs until stop is set (checks it at least every 50 ms).
  void run(const std::atomic<bool>& stop);
  // Handles one datagram (the loop's body; public for tests and benchmarks).
  void handle(std::span<const std::uint8_t> datagram, const sockaddr_in& from, Clock::time_point arrival);
  std::optional<sockaddr_in> lastSender() const;

 private:
  UdpSocket& socket_;
  NodeStats& stats_;
  Latest<HostSnapshot>& out_;
  CigiStateTracker tracker_;
  OwnshipPredictor predictor_;
  protocol::cigi::DecodedMessage decoded_;
  mutable std::mutex senderMutex_;
  std::optional<sockaddr_in> lastSender_;
  Clock::time_point lastWarning_{};
  std::uint64_t suppressedWarnings_ = 0;
};

}  // namespace skyig::services
