#include "protocol/candump/candump.h"

#include <array>
#include <cstdio>

namespace skyig::protocol::candump {

using canaerospace::kCanEffFlag;
using canaerospace::kCanEffMask;
using canaerospace::kCanErrFlag;
using canaerospace::kCanRtrFlag;
using canaerospace::kCanSffMask;

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool isSpace(char c) { return c == ' ' || c == '\t'; }

std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 60;
  std::string q = "\"";
  for (char c : s.substr(0, kMax)) q += (c >= 32 && c < 127) ? c : '?';
  if (s.size() > kMax) q += "...";
  return q + "\"";
}

}  // namespace

std::optional<Record> parseLine(std::string_view line, std::string* why) {
  auto bad = [&](std::string msg) -> std::optional<Record> {
    if (why != nullptr) *why = std::move(msg);
    return std::nullopt;
  };
  while (!line.empty() && (line.back() == '\r' || isSpace(line.back()))) line.remove_suffix(1);
  std::size_t i = 0;
  if (line.empty() || line[0] != '(') return bad("expected '(' and a timestamp at column 1");
  ++i;
  std::int64_t seconds = 0;
  std::size_t digits = 0;
  for (; i < line.size() && line[i] >= '0' && line[i] <= '9'; ++i, ++digits) {
    if (digits >= 12) return bad("timestamp seconds too long at column " + std::to_string(i + 1));
    seconds = seconds * 10 + (line[i] - '0');
  }
  if (digits == 0 || i >= line.size() || line[i] != '.') return bad("bad timestamp: expected (SECONDS.MICROSECONDS)");
  ++i;
  std::int64_t micros = 0;
  std::size_t fracDigits = 0;
  for (; i < line.size() && line[i] >= '0' && line[i] <= '9'; ++i, ++fracDigits) {
    if (fracDigits >= 9) return bad("timestamp fraction too long at column " + std::to_string(i + 1));
    micros = micros * 10 + (line[i] - '0');
  }
  if (fracDigits == 0 || i >= line.size() || line[i] != ')')
    return bad("bad timestamp: expected (SECONDS.MICROSECONDS)");
  for (std::size_t k = fracDigits; k < 6; ++k) micros *= 10;  // "(1.5)" is 1.500000 s
  for (std::size_t k = 6; k < fracDigits; ++k) micros /= 10;  // nanosecond logs
  ++i;
  if (i >= line.size() || !isSpace(line[i])) return bad("expected a space after the timestamp");
  while (i < line.size() && isSpace(line[i])) ++i;
  const std::size_t ifStart = i;
  while (i < line.size() && !isSpace(line[i])) ++i;
  if (i == ifStart || i >= line.size()) return bad("expected an interface name and a frame after the timestamp");
  Record r;
  r.timestampUs = seconds * 1000000 + micros;
  r.interface = std::string(line.substr(ifStart, i - ifStart));
  while (i < line.size() && isSpace(line[i])) ++i;
  const std::size_t frameStart = i;
  std::size_t frameEnd = i;
  while (frameEnd < line.size() && !isSpace(line[frameEnd])) ++frameEnd;
  // Anything after the frame (candump -x writes direction flags) is ignored, as canplayer does.
  const std::string_view f = line.substr(frameStart, frameEnd - frameStart);
  const std::size_t hash = f.find('#');
  if (hash == std::string_view::npos) return bad("frame " + quoted(f) + " has no '#'");
  if (hash != 3 && hash != 8)
    return bad("identifier " + quoted(f.substr(0, hash)) + " must have 3 (11-bit) or 8 (29-bit) hex digits");
  std::uint32_t id = 0;
  for (std::size_t k = 0; k < hash; ++k) {
    const int v = hexValue(f[k]);
    if (v < 0) return bad("identifier " + quoted(f.substr(0, hash)) + " is not hexadecimal");
    id = (id << 4) | static_cast<std::uint32_t>(v);
  }
  CanFrame& cf = r.frame;
  if (hash == 3) {
    if (id > kCanSffMask) return bad("11-bit identifier " + quoted(f.substr(0, 3)) + " exceeds 7FF");
    cf.canId = id;
  } else {
    if ((id & ~(kCanEffMask | kCanErrFlag)) != 0)
      return bad("29-bit identifier " + quoted(f.substr(0, 8)) + " has reserved flag bits set");
    cf.canId = (id & kCanErrFlag) != 0 ? id : (id | kCanEffFlag);  // as can-utils parse_canframe
  }
  std::size_t k = hash + 1;
  if (k < f.size() && f[k] == '#') return bad("CAN FD frame (##) not supported: " + quoted(f));
  if (k < f.size() && (f[k] == 'R' || f[k] == 'r')) {
    cf.canId |= kCanRtrFlag;
    ++k;
    if (k < f.size()) {
      const int len = hexValue(f[k]);
      if (len < 0 || len > 8 || k + 1 != f.size()) return bad("remote frame " + quoted(f) + ": bad length");
      cf.len = static_cast<std::uint8_t>(len);
    }
    return r;
  }
  std::size_t n = 0;
  while (k < f.size()) {
    if (f[k] == '.') {
      ++k;
      continue;
    }
    if (k + 1 >= f.size()) return bad("data " + quoted(f.substr(hash + 1)) + " has an odd number of hex digits");
    const int hi = hexValue(f[k]);
    const int lo = hexValue(f[k + 1]);
    if (hi < 0 || lo < 0) return bad("data " + quoted(f.substr(hash + 1)) + " is not hexadecimal");
    if (n == 8) return bad("data " + quoted(f.substr(hash + 1)) + " longer than 8 bytes");
    cf.data[n++] = static_cast<std::uint8_t>(hi << 4 | lo);
    k += 2;
  }
  cf.len = static_cast<std::uint8_t>(n);
  return r;
}

std::string formatLine(std::int64_t timestampUs, std::string_view interface, const CanFrame& frame) {
  char buf[160];
  const long long sec = timestampUs / 1000000;
  const long long usec = timestampUs % 1000000;
  int n = std::snprintf(buf, sizeof buf, "(%010lld.%06lld) ", sec, usec);
  std::string s(buf, static_cast<std::size_t>(n));
  s += interface;
  s += ' ';
  if ((frame.canId & kCanErrFlag) != 0)
    n = std::snprintf(buf, sizeof buf, "%08X#", static_cast<unsigned>(frame.canId & (kCanEffMask | kCanErrFlag)));
  else if ((frame.canId & kCanEffFlag) != 0)
    n = std::snprintf(buf, sizeof buf, "%08X#", static_cast<unsigned>(frame.canId & kCanEffMask));
  else
    n = std::snprintf(buf, sizeof buf, "%03X#", static_cast<unsigned>(frame.canId & kCanSffMask));
  s.append(buf, static_cast<std::size_t>(n));
  static const char* kHex = "0123456789ABCDEF";
  if ((frame.canId & kCanRtrFlag) != 0) {
    s += 'R';
    if (frame.len > 0 && frame.len <= 8) s += kHex[frame.len];
  } else {
    for (std::size_t i = 0; i < frame.len && i < 8; ++i) {
      s += kHex[frame.data[i] >> 4];
      s += kHex[frame.data[i] & 15];
    }
  }
  s += '\n';
  return s;
}

bool Reader::readLine(std::string& line, std::uint64_t& lineOffset) {
  line.clear();
  lineOffset = offset_;
  constexpr std::size_t kChunk = 64 * 1024;
  constexpr std::size_t kMaxLine = 4096;  // longer is not a candump line; keeps memory bounded
  bool any = false;
  while (true) {
    if (chunkPos_ >= chunk_.size()) {
      chunk_.resize(kChunk);
      chunkOffset_ = offset_;
      const std::size_t n = source_.readAt(offset_, chunk_);
      chunk_.resize(n);
      chunkPos_ = 0;
      if (n == 0) return any;
    }
    const std::uint8_t c = chunk_[chunkPos_++];
    ++offset_;
    any = true;
    if (c == '\n') return true;
    if (line.size() < kMaxLine) line += static_cast<char>(c);
  }
}

Reader::Status Reader::next(Record& out) {
  std::string line;
  std::uint64_t lineOffset = 0;
  while (readLine(line, lineOffset)) {
    ++line_;
    std::string_view v = line;
    while (!v.empty() && (v.back() == '\r' || isSpace(v.back()))) v.remove_suffix(1);
    if (v.empty()) continue;
    std::string why;
    std::optional<Record> r = parseLine(v, &why);
    if (r) {
      out = std::move(*r);
      out.line = line_;
      out.offset = lineOffset;
      return Status::record;
    }
    LineError e{line_, lineOffset,
                "candump log line " + std::to_string(line_) + " at byte " + std::to_string(lineOffset) + ": " + why +
                    " in " + quoted(v)};
    if (!skipBad_) {
      error_ = std::move(e);
      offset_ = source_.size();
      chunk_.clear();
      chunkPos_ = 0;
      return Status::error;
    }
    ++skipped_;
    if (skippedErrors_.size() < 1000) skippedErrors_.push_back(std::move(e));
  }
  if (!source_.error().empty()) {
    error_ = LineError{line_, offset_, source_.error()};
    return Status::error;
  }
  return Status::end;
}

bool Writer::write(std::int64_t timestampUs, std::string_view interface, const CanFrame& frame) {
  if (!error_.empty()) return false;
  if (timestampUs < 0) {
    error_ = "candump writer: negative timestamp " + std::to_string(timestampUs) + " us";
    return false;
  }
  if (interface.empty() || interface.find_first_of(" \t\n#()") != std::string_view::npos) {
    error_ = "candump writer: bad interface name " + quoted(interface);
    return false;
  }
  const std::string s = formatLine(timestampUs, interface, frame);
  if (!sink_.write({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()})) {
    error_ = "candump writer: line " + std::to_string(records_ + 1) + ": " + sink_.error();
    return false;
  }
  ++records_;
  if (syncEvery_ != 0 && records_ % syncEvery_ == 0 && !sink_.sync()) {
    error_ = "candump writer: sync after line " + std::to_string(records_) + ": " + sink_.error();
    return false;
  }
  return true;
}

}  // namespace skyig::protocol::candump
