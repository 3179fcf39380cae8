#pragma once
// A classic CAN 2.0 frame laid out like Linux's `struct can_frame` (linux/can.h): a 32-bit
// identifier carrying the EFF/RTR/ERR flags in its top bits, the payload length, and 8 data
// bytes at offset 8. node/transport can copy between the two with a static_assert on the size;
// protocol/ needs no Linux header.
#include <array>
#include <cstdint>

namespace skyig::protocol::canaerospace {

inline constexpr std::uint32_t kCanEffFlag = 0x80000000u;  // 29-bit (extended) identifier
inline constexpr std::uint32_t kCanRtrFlag = 0x40000000u;  // remote transmission request
inline constexpr std::uint32_t kCanErrFlag = 0x20000000u;  // error frame
inline constexpr std::uint32_t kCanSffMask = 0x000007FFu;
inline constexpr std::uint32_t kCanEffMask = 0x1FFFFFFFu;

struct CanFrame {
  std::uint32_t canId = 0;  // identifier | flags
  std::uint8_t len = 0;     // payload length 0..8 (the DLC)
  std::uint8_t pad = 0;
  std::uint8_t res0 = 0;
  std::uint8_t len8Dlc = 0;
  alignas(8) std::array<std::uint8_t, 8> data{};

  bool extended() const { return (canId & kCanEffFlag) != 0; }
  bool remote() const { return (canId & kCanRtrFlag) != 0; }
  bool error() const { return (canId & kCanErrFlag) != 0; }
  std::uint32_t identifier() const { return canId & (extended() ? kCanEffMask : kCanSffMask); }
  bool operator==(const CanFrame&) const = default;
};
static_assert(sizeof(CanFrame) == 16, "CanFrame must match struct can_frame");

}  // namespace skyig::protocol::canaerospace
