# The protocol library's sources, relative to protocol/. Shared by protocol/CMakeLists.txt
# and the fuzzing build (tests/fuzz), which compiles them again with sanitizers.
set(SKYIG_PROTOCOL_SOURCES
  cigi/packets.cpp
  cigi/date.cpp
  cigi/encoder.cpp
  cigi/decoder.cpp
  canaerospace/message.cpp
  canaerospace/state_decoder.cpp
  canaerospace/state_encoder.cpp
  io/byte_source.cpp
  io/byte_sink.cpp
  pcap/udp_frame.cpp
  pcap/pcap_writer.cpp
  pcap/pcap_reader.cpp
  pcap/pcapng_reader.cpp
  candump/candump.cpp
  recording_format.cpp
)
