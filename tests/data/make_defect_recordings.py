#!/usr/bin/env python3
"""Writes the defective recordings of tests/data (README.md) from circuit_timelapse.pcap.

Each file holds one defect that `skyig record` or a disk once produced, kept small:
  large_datagram.pcap       a 65,496-byte CIGI datagram (IG Control + 2,046 View Controls)
                            between ordinary ones: above the old 65,535-byte snap length
  time_gap.pcap             20 records, a jump of 1,000,000 s, 20 more (a corrupt clock)
  corrupt_first_record.pcap 40 records, the first one's captured length 0x7FFFFFFF
  unknown_link_type.pcap    5 records under link type 147 (USER0), which skyig cannot parse

Run from the repository root: python3 tests/data/make_defect_recordings.py
The output is deterministic (byte-identical on every run).
"""
import pathlib
import struct

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE / "circuit_timelapse.pcap"


def read_pcap(path):
    data = path.read_bytes()
    header, records, offset = data[:24], [], 24
    while offset < len(data):
        sec, usec, incl, orig = struct.unpack_from("<IIII", data, offset)
        records.append([sec, usec, data[offset + 16:offset + 16 + incl], orig])
        offset += 16 + incl
    return header, records


def record_bytes(sec, usec, frame, orig=None):
    return struct.pack("<IIII", sec, usec, len(frame), len(frame) if orig is None else orig) + frame


def ip_checksum(header):
    total = sum(struct.unpack("!10H", header))
    while total > 0xFFFF:
        total = (total & 0xFFFF) + (total >> 16)
    return (~total) & 0xFFFF


def with_payload(frame, payload):
    """The Ethernet/IPv4/UDP frame `frame` carrying `payload` instead (lengths, checksum)."""
    eth, ip, udp = bytearray(frame[:14]), bytearray(frame[14:34]), bytearray(frame[34:42])
    struct.pack_into("!H", ip, 2, 20 + 8 + len(payload))
    struct.pack_into("!H", ip, 10, 0)
    struct.pack_into("!H", ip, 10, ip_checksum(bytes(ip)))
    struct.pack_into("!H", udp, 4, 8 + len(payload))
    struct.pack_into("!H", udp, 6, 0)  # no UDP checksum (allowed over IPv4, RFC 768)
    return bytes(eth + ip + udp) + payload


def view_control(view_id, yaw_deg):
    """CIGI 3.3 View Control (opcode 16, 32 bytes, big-endian), yaw enabled."""
    p = bytearray(32)
    p[0], p[1] = 16, 32
    struct.pack_into("!H", p, 2, view_id)
    p[5] = 1 << 5  # yaw enable
    struct.pack_into("!f", p, 28, yaw_deg)
    return bytes(p)


def main():
    header, records = read_pcap(SOURCE)

    def write(name, chunks, file_header=header):
        (HERE / name).write_bytes(file_header + b"".join(chunks))

    # large_datagram.pcap: the libpcap default snap length, as skyig now writes.
    big_header = header[:16] + struct.pack("<I", 262144) + header[20:]
    chunks = []
    for i, (sec, usec, frame, _) in enumerate(records[:10]):
        chunks.append(record_bytes(sec, usec, frame))
        if i == 4:
            payload = frame[42:42 + 24] + b"".join(view_control(v, float(v % 360)) for v in range(2046))
            chunks.append(record_bytes(sec, usec + 1000, with_payload(frame, payload)))
    write("large_datagram.pcap", chunks, big_header)

    chunks = []
    for i, (sec, usec, frame, _) in enumerate(records[:40]):
        chunks.append(record_bytes(sec + (1000000 if i >= 20 else 0), usec, frame))
    write("time_gap.pcap", chunks)

    chunks = [record_bytes(sec, usec, frame) for sec, usec, frame, _ in records[:40]]
    first = bytearray(chunks[0])
    struct.pack_into("<I", first, 8, 0x7FFFFFFF)
    chunks[0] = bytes(first)
    write("corrupt_first_record.pcap", chunks)

    user0 = header[:20] + struct.pack("<I", 147)
    write("unknown_link_type.pcap", [record_bytes(sec, usec, frame) for sec, usec, frame, _ in records[:5]], user0)


if __name__ == "__main__":
    main()
