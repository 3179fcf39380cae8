# The fuzz targets, one per decoder; each is <name>.cpp in this folder.
set(SKYIG_FUZZ_TARGETS fuzz_cigi_decoder fuzz_canaerospace fuzz_pcap_reader fuzz_candump_reader)
