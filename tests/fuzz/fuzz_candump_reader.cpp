// libFuzzer target: any bytes as a candump log, read with skip-bad. Every record that
// parses must format back to a line that parses to the same frame.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "protocol/candump/candump.h"

using namespace skyig::protocol;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  io::MemorySource src(std::span(data, size));
  candump::Reader reader(src, true);
  candump::Record rec;
  while (reader.next(rec) == candump::Reader::Status::record) {
    std::string line = candump::formatLine(rec.timestampUs, rec.interface, rec.frame);
    line.pop_back();
    std::string why;
    const auto back = candump::parseLine(line, &why);
    if (!back || !(back->frame == rec.frame) || back->timestampUs != rec.timestampUs) std::abort();
  }
  return 0;
}
