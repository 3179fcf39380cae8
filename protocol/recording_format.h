#pragma once
// Which kind of recording a file is, from its first bytes, so `skyig replay FILE` can pick
// the reader: classic pcap (either byte order, micro or nano), pcapng, or a can-utils
// candump log (text whose first non-blank character is '(').
#include <cstdint>
#include <string>

#include "protocol/io/byte_source.h"

namespace skyig::protocol {

enum class RecordingFormat : std::uint8_t { pcap, pcapng, candump, unknown };

const char* toString(RecordingFormat f);

// Looks at the first bytes only; `description` (optional) says what was seen when the
// format is unknown, e.g. "empty file" or "first bytes 7F 45 4C 46".
RecordingFormat detectRecordingFormat(io::ByteSource& source, std::string* description = nullptr);

}  // namespace skyig::protocol
