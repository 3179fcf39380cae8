#pragma once
// The CANaerospace message (CANaerospace interface specification V1.7, Stock Flight Systems,
// section 3): the CAN identifier is the message (parameter) id; the payload is a 4-byte
// header - node id, data type, service code, message code - and 0..4 data bytes, all
// big-endian. DLC = 4 + the size of the data type.
#include <array>
#include <cstdint>
#include <string>

#include "protocol/canaerospace/can_frame.h"

namespace skyig::protocol::canaerospace {

// Data type codes (spec section 3.2 table).
enum class DataType : std::uint8_t {
  noData = 0, error = 1, floatType = 2, longType = 3, ulongType = 4, blong = 5,
  shortType = 6, ushortType = 7, bshort = 8, charType = 9, uchar = 10, bchar = 11,
  short2 = 12, ushort2 = 13, bshort2 = 14, char4 = 15, uchar4 = 16, bchar4 = 17,
  char2 = 18, uchar2 = 19, bchar2 = 20, memid = 21, chksum = 22, achar = 23, achar2 = 24,
  achar4 = 25, char3 = 26, uchar3 = 27, bchar3 = 28, achar3 = 29,
  doubleH = 30,  // most significant 32 bits of an IEEE-754 double
  doubleL = 31,  // least significant 32 bits
};

// Data bytes of a type: 0..4, or -1 for reserved (32..99) and user-defined (100..255) codes.
int dataSize(std::uint8_t dataType);
const char* dataTypeName(std::uint8_t dataType);

struct Message {
  std::uint32_t id = 0;          // CAN identifier (11 bit, or 29 bit for redundancy channels)
  std::uint8_t nodeId = 0;
  std::uint8_t dataType = 0;     // a DataType code; raw so user-defined codes survive
  std::uint8_t serviceCode = 0;
  std::uint8_t messageCode = 0;  // incremented per message of an id, wraps 255 -> 0
  std::uint8_t dataLength = 0;   // 0..4
  std::array<std::uint8_t, 4> data{};
  bool operator==(const Message&) const = default;

  std::uint32_t u32() const;     // data[0..3] big-endian
  float asFloat() const;         // FLOAT
  std::int32_t asLong() const;   // LONG
};

// Identifier ranges (spec section 3.1).
enum class IdRange : std::uint8_t {
  emergencyEvent, nodeServiceHigh, userDefinedHigh, normalOperation, userDefinedLow, debugService,
  nodeServiceLow, outside,
};
IdRange idRange(std::uint32_t id);

enum class FrameError : std::uint8_t {
  none = 0,
  remoteFrame,   // RTR frames carry no CANaerospace message
  errorFrame,    // a CAN error frame
  tooShort,      // DLC < 4: no room for the header
  tooLong,       // DLC > 8
  sizeMismatch,  // DLC differs from 4 + the data type's size
};
inline constexpr std::size_t kFrameErrorCount = 6;
const char* toString(FrameError e);

// Reads a CANaerospace message out of a frame; FrameError::none on success.
FrameError parseFrame(const CanFrame& frame, Message& out);

// Builds the frame of a message: 29-bit identifier when the id does not fit in 11 bits.
CanFrame toFrame(const Message& m);

// Helpers to build messages of the types skyig uses.
Message makeFloat(std::uint32_t id, std::uint8_t nodeId, float value, std::uint8_t messageCode,
                  std::uint8_t serviceCode = 0);
Message makeLong(std::uint32_t id, std::uint8_t nodeId, std::int32_t value, std::uint8_t messageCode);
// A double as DOUBLEH then DOUBLEL, message codes `messageCode` and `messageCode + 1`.
std::array<Message, 2> makeDoublePair(std::uint32_t id, std::uint8_t nodeId, double value,
                                      std::uint8_t messageCode);
Message makeChar4(std::uint32_t id, std::uint8_t nodeId, std::array<std::uint8_t, 4> bytes,
                  std::uint8_t messageCode);

}  // namespace skyig::protocol::canaerospace
