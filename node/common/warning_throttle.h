#pragma once
// A warning that may repeat every frame or every datagram (a host state the sky cannot use):
// the first is logged at once, later ones at most once per interval with how many were held
// back since, so a bad host cannot fill the log (it used to write 10-78 lines a second).
#include <chrono>
#include <cstdint>

namespace skyig::services {

class WarningThrottle {
 public:
  using Clock = std::chrono::steady_clock;
  explicit WarningThrottle(Clock::duration interval = std::chrono::seconds(5)) : interval_(interval) {}

  // True when this occurrence should be logged; then *heldBack is how many were not logged
  // since the last one that was. `now`: the caller's clock (a replay passes recording time).
  bool allow(Clock::time_point now, std::uint64_t* heldBack) {
    if (logged_ && now - last_ < interval_) {
      ++heldBack_;
      return false;
    }
    *heldBack = heldBack_;
    heldBack_ = 0;
    last_ = now;
    logged_ = true;
    return true;
  }

 private:
  Clock::duration interval_;
  Clock::time_point last_{};
  bool logged_ = false;
  std::uint64_t heldBack_ = 0;
};

}  // namespace skyig::services
