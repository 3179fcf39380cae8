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

// Something that keeps every datagram as it arrived (serve --record); record() returns false
// once it can no longer write, and is not called again.
class DatagramRecorder {
 public:
  virtual ~DatagramRecorder() = default;
  virtual bool record(std::span<const std::uint8_t> datagram, const sockaddr_in& from, std::int64_t unixTimeNs) = 0;
  virtual std::string error() const = 0;
};

class CigiReceiver {
 public:
  CigiReceiver(NodeStats& stats, Latest<HostSnapshot>& out);
  // Receives from `socket` until stop is set (checks it at least every 50 ms).
  void run(UdpSocket& socket, const std::atomic<bool>& stop);
  // Handles one datagram: the loop's body, and what replay feeds with recorded datagrams
  // and recorded arrival times.
  void handle(std::span<const std::uint8_t> datagram, const sockaddr_in& from, Clock::time_point arrival);
  void setRecorder(DatagramRecorder* recorder) { recorder_ = recorder; }
  // host.max_views: View Controls for higher ids are counted (NodeStats::droppedViews).
  void setMaxViews(std::size_t n) { tracker_.setMaxViews(n); }

 private:
  DatagramRecorder* recorder_ = nullptr;
  NodeStats& stats_;
  Latest<HostSnapshot>& out_;
  CigiStateTracker tracker_;
  OwnshipPredictor predictor_;
  protocol::cigi::DecodedMessage decoded_;
  Clock::time_point lastWarning_{};
  std::uint64_t suppressedWarnings_ = 0;
};

}  // namespace skyig::services
