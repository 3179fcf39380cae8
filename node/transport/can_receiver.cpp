#include "node/transport/can_receiver.h"

#include "node/transport/udp_socket.h"

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace skyig::services {

namespace can = protocol::canaerospace;
static_assert(sizeof(can::CanFrame) == sizeof(struct can_frame), "protocol CanFrame mirrors struct can_frame");

int openSocketCan(const std::string& interface) {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    if (errno == EAFNOSUPPORT)
      throw NetworkError("SocketCAN is not available: this kernel has no CAN support (AF_CAN: " +
                         std::string(std::strerror(errno)) + "); load the can and can_raw modules, or use CIGI over UDP");
    throw NetworkError("socket(PF_CAN, SOCK_RAW, CAN_RAW): " + std::string(std::strerror(errno)));
  }
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, interface.c_str(), IFNAMSIZ - 1);
  if (::ioctl(fd, SIOCGIFINDEX, &ifr) < 0) {
    ::close(fd);
    throw NetworkError("CAN interface \"" + interface + "\": " + std::strerror(errno));
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0) {
    ::close(fd);
    throw NetworkError("bind CAN interface \"" + interface + "\": " + std::strerror(errno));
  }
  return fd;
}

CanReceiver::CanReceiver(int fd, const can::IdentifierMap& map, NodeStats& stats, Latest<HostSnapshot>& out)
    : fd_(fd), stats_(stats), out_(out, /*history=*/0), decoder_(map) {}

void CanReceiver::run(const std::atomic<bool>& stop) {
  while (!stop.load(std::memory_order_relaxed)) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    can::CanFrame frame;
    const ssize_t n = ::read(fd_, &frame, sizeof frame);
    if (n == 0) return;  // the stream ended (a closed socketpair)
    if (n != static_cast<ssize_t>(sizeof frame)) {
      stats_.canStatus[static_cast<std::size_t>(can::FeedStatus::malformedFrame)].fetch_add(1);
      continue;
    }
    handle(frame, Clock::now());
  }
}

void CanReceiver::handle(const can::CanFrame& frame, Clock::time_point arrival) {
  stats_.canFrames.fetch_add(1, std::memory_order_relaxed);
  const can::FeedResult r = decoder_.feed(frame);
  stats_.canStatus[static_cast<std::size_t>(r.status)].fetch_add(1, std::memory_order_relaxed);
  if (r.status != can::FeedStatus::applied) return;
  const can::CanAerospaceState& c = decoder_.state();
  if (c.has(can::kLatitude | can::kLongitude | can::kAltitude | can::kHeading | can::kPitch | can::kRoll)) {
    const sky::Ownship o{c.latitudeDeg, c.longitudeDeg, c.altitudeM, {c.headingDeg, c.pitchDeg, c.rollDeg}};
    // Each parameter comes in its own frame, so consecutive states differ in one field only
    // and their difference is no velocity: the view holds the latest state (CANaerospace
    // hosts send attitude at the IG's rate or faster).
    state_.ownship = o;
    state_.ownshipValid = true;
    state_.ownshipTime = arrival;
    predictor_ = OwnshipPredictor{};
    predictor_.addSample(o, arrival, {});
  }
  if (c.has(can::kUtcTime | can::kDate)) {
    // Whole seconds: the clock is re-anchored when the stated second changes (it has just
    // begun), and runs on the local clock in between.
    const ephemeris::UtcTime stated{c.year, c.month, c.day, c.hour * 3600.0 + c.minute * 60.0 + c.second};
    if (!state_.timeValid || stated.secondsOfDay != lastStatedSeconds_ || stated.day != state_.utc.day) {
      state_.timeValid = true;
      state_.utc = stated;
      state_.utcTime = arrival;
      lastStatedSeconds_ = stated.secondsOfDay;
    }
  }
  ++state_.updates;
  state_.received = arrival;
  out_.publish(HostSnapshot{state_, predictor_, std::nullopt, std::nullopt, Clock::now(), {}});
  stats_.arrivalToVisible.add(std::chrono::duration<double, std::micro>(Clock::now() - arrival).count());
}

}  // namespace skyig::services
