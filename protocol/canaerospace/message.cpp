#include "protocol/canaerospace/message.h"

#include <bit>

#include "protocol/byte_order.h"

namespace skyig::protocol::canaerospace {

namespace {

struct TypeInfo {
  const char* name;
  int size;
};

// Spec V1.7 section 3.2: codes 0..31 and their data sizes.
constexpr TypeInfo kTypes[32] = {
    {"NODATA", 0}, {"ERROR", 4},  {"FLOAT", 4},  {"LONG", 4},    {"ULONG", 4},   {"BLONG", 4},
    {"SHORT", 2},  {"USHORT", 2}, {"BSHORT", 2}, {"CHAR", 1},    {"UCHAR", 1},   {"BCHAR", 1},
    {"SHORT2", 4}, {"USHORT2", 4}, {"BSHORT2", 4}, {"CHAR4", 4}, {"UCHAR4", 4}, {"BCHAR4", 4},
    {"CHAR2", 2},  {"UCHAR2", 2}, {"BCHAR2", 2}, {"MEMID", 4},   {"CHKSUM", 4},  {"ACHAR", 1},
    {"ACHAR2", 2}, {"ACHAR4", 4}, {"CHAR3", 3},  {"UCHAR3", 3},  {"BCHAR3", 3},  {"ACHAR3", 3},
    {"DOUBLEH", 4}, {"DOUBLEL", 4},
};

Message makeRaw(std::uint32_t id, std::uint8_t nodeId, DataType type, std::uint32_t bits, std::uint8_t code,
                std::uint8_t service) {
  Message m;
  m.id = id;
  m.nodeId = nodeId;
  m.dataType = static_cast<std::uint8_t>(type);
  m.serviceCode = service;
  m.messageCode = code;
  m.dataLength = 4;
  storeU32(m.data.data(), bits, ByteOrder::big);
  return m;
}

}  // namespace

int dataSize(std::uint8_t dataType) { return dataType < 32 ? kTypes[dataType].size : -1; }

const char* dataTypeName(std::uint8_t dataType) {
  if (dataType < 32) return kTypes[dataType].name;
  return dataType < 100 ? "reserved" : "user-defined";
}

std::uint32_t Message::u32() const { return loadU32(data.data(), ByteOrder::big); }
float Message::asFloat() const { return std::bit_cast<float>(u32()); }
std::int32_t Message::asLong() const { return std::bit_cast<std::int32_t>(u32()); }

IdRange idRange(std::uint32_t id) {
  if (id <= 127) return IdRange::emergencyEvent;
  if (id <= 199) return IdRange::nodeServiceHigh;
  if (id <= 299) return IdRange::userDefinedHigh;
  if (id <= 1799) return IdRange::normalOperation;
  if (id <= 1899) return IdRange::userDefinedLow;
  if (id <= 1999) return IdRange::debugService;
  if (id <= 2031) return IdRange::nodeServiceLow;
  return IdRange::outside;
}

const char* toString(FrameError e) {
  switch (e) {
    case FrameError::none: return "no error";
    case FrameError::remoteFrame: return "remote (RTR) frame";
    case FrameError::errorFrame: return "CAN error frame";
    case FrameError::tooShort: return "DLC below 4: no CANaerospace header";
    case FrameError::tooLong: return "DLC above 8";
    case FrameError::sizeMismatch: return "DLC does not match the data type";
  }
  return "unknown error";
}

FrameError parseFrame(const CanFrame& frame, Message& out) {
  if (frame.error()) return FrameError::errorFrame;
  if (frame.remote()) return FrameError::remoteFrame;
  if (frame.len > 8) return FrameError::tooLong;
  if (frame.len < 4) return FrameError::tooShort;
  const int size = dataSize(frame.data[1]);
  // Reserved and user-defined types have no size in the spec: accept what the DLC says.
  if (size >= 0 && frame.len != 4 + size) return FrameError::sizeMismatch;
  out.id = frame.identifier();
  out.nodeId = frame.data[0];
  out.dataType = frame.data[1];
  out.serviceCode = frame.data[2];
  out.messageCode = frame.data[3];
  out.dataLength = static_cast<std::uint8_t>(frame.len - 4);
  out.data = {};
  for (std::size_t i = 0; i < out.dataLength; ++i) out.data[i] = frame.data[4 + i];
  return FrameError::none;
}

CanFrame toFrame(const Message& m) {
  CanFrame f;
  f.canId = m.id > kCanSffMask ? ((m.id & kCanEffMask) | kCanEffFlag) : m.id;
  const std::uint8_t n = m.dataLength > 4 ? 4 : m.dataLength;
  f.len = static_cast<std::uint8_t>(4 + n);
  f.data[0] = m.nodeId;
  f.data[1] = m.dataType;
  f.data[2] = m.serviceCode;
  f.data[3] = m.messageCode;
  for (std::size_t i = 0; i < n; ++i) f.data[4 + i] = m.data[i];
  return f;
}

Message makeFloat(std::uint32_t id, std::uint8_t nodeId, float value, std::uint8_t messageCode, std::uint8_t serviceCode) {
  return makeRaw(id, nodeId, DataType::floatType, std::bit_cast<std::uint32_t>(value), messageCode, serviceCode);
}

Message makeLong(std::uint32_t id, std::uint8_t nodeId, std::int32_t value, std::uint8_t messageCode) {
  return makeRaw(id, nodeId, DataType::longType, std::bit_cast<std::uint32_t>(value), messageCode, 0);
}

std::array<Message, 2> makeDoublePair(std::uint32_t id, std::uint8_t nodeId, double value, std::uint8_t messageCode) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  return {makeRaw(id, nodeId, DataType::doubleH, static_cast<std::uint32_t>(bits >> 32), messageCode, 0),
          makeRaw(id, nodeId, DataType::doubleL, static_cast<std::uint32_t>(bits & 0xFFFFFFFFu),
                  static_cast<std::uint8_t>(messageCode + 1), 0)};
}

Message makeChar4(std::uint32_t id, std::uint8_t nodeId, std::array<std::uint8_t, 4> bytes, std::uint8_t messageCode) {
  Message m;
  m.id = id;
  m.nodeId = nodeId;
  m.dataType = static_cast<std::uint8_t>(DataType::char4);
  m.messageCode = messageCode;
  m.dataLength = 4;
  m.data = bytes;
  return m;
}

}  // namespace skyig::protocol::canaerospace
