#!/usr/bin/env bash
# Weather every second for a minute (docs/performance.md, "Weather every second"): one headless
# node, driven by `skyig host` for two minutes on loopback: a steady minute (20 km, no fog, no
# precipitation), then config/showers.csv (the visibility across the tables' 10 km floor both
# ways, the ground fog and rain, snow and dust changing every second). From the node's
# --dump-state (each frame's own time) and --stats-json: the frame-time p50, p99 and largest
# frame of each minute, the time from a host datagram's arrival to the end of the first frame
# that shows it, the tables built meanwhile, and the node's memory and table cache.
#
# Usage: deploy/weather-minute.sh [--skyig PATH] [--out DIR] [--size WxH] [--rate HZ] [--minute S]
#                                 [--weather CSV] [--build-interval S]
#   --skyig PATH   default build/bin/skyig
#   --out DIR      results, logs and the table cache (default weather-minute-out/)
#   --size WxH     the channel (default 640x400); --rate the node's and host's rate (default 30)
#   --minute S     the length of each half (default 60; the showers are cut or held to it)
#   --weather CSV  the second half's weather instead of config/showers.csv (the host's --weather
#                  columns, its times from 0), e.g. one visibility the cache lacks: a table build
#   --build-interval S  the node's atmosphere_build_interval (default the configuration's, 60 s)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
skyig="$here/build/bin/skyig"
out="$here/weather-minute-out"
size="640x400"
rate=30
minute=60
weather="$here/config/showers.csv"
build_interval=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --skyig) skyig="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --rate) rate="$2"; shift 2 ;;
    --minute) minute="$2"; shift 2 ;;
    --weather) weather="$2"; shift 2 ;;
    --build-interval) build_interval="atmosphere_build_interval = $2"; shift 2 ;;
    *) echo "weather-minute.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[[ -x "$skyig" ]] || { echo "weather-minute.sh: no skyig at $skyig (build first, or --skyig)" >&2; exit 2; }
mkdir -p "$out"
width="${size%x*}"; height="${size#*x}"
port=$(( 20000 + RANDOM % 20000 ))

# The node: the shipped configuration's sky and tables, one channel of the asked size.
cat > "$out/node.toml" <<TOML
[sky]
model = "physical"
atmosphere_tables = "medium"
$build_interval
[host]
listen = "127.0.0.1:$port"
[[channel]]
name = "front"
width = $width
height = $height
TOML
# The host's weather: steady, then the showers shifted by a minute.
{
  echo "time_s, visibility_m, humidity_pct, fog_visibility_m, fog_top_m, precipitation, severity, precipitation_visibility_m, precipitation_top_m"
  echo "0, 20000, 50, 0, 0, none, 0, 0, 1500"
  grep -v '^#' "$weather" | tail -n +2 | awk -F, -v m="$minute" '$1 + 0 < m { $1 = $1 + m; print }' OFS=,
} > "$out/weather.csv"

export XDG_CACHE_HOME="$out/cache"
rm -f "$out/dump.jsonl" "$out/stats.json"
"$skyig" serve --config "$out/node.toml" --headless --frame-rate "$rate" --dump-state "$out/dump.jsonl" \
  --stats-json "$out/stats.json" --log-interval 10 > "$out/node.log" 2>&1 &
node=$!
trap 'kill $node 2>/dev/null || true' EXIT
# Serving once its programs are compiled, just before its first frame: its tables are built or
# loaded by then (a fresh cache builds them first; the channel is announced before that).
for _ in $(seq 1 600); do grep -q "compiled in" "$out/node.log" && break; sleep 1; done
grep -q "compiled in" "$out/node.log" || { echo "weather-minute.sh: the node did not start serving; $out/node.log:" >&2; tail "$out/node.log" >&2; exit 1; }
"$skyig" host --path "$here/config/circuit.csv" --loop --rate "$rate" --duration $(( 2 * minute )) \
  --start-utc 2026-06-21T09:00:00Z --weather "$out/weather.csv" --to "127.0.0.1:$port" > "$out/host.log" 2>&1
rss_kb=$(awk '/VmRSS/ { print $2 }' "/proc/$node/status")
kill -INT $node; wait $node || true
trap - EXIT
cache_mb=$(du -sm "$out/cache" | cut -f1)

python3 - "$out" "$rate" "$minute" "$rss_kb" "$cache_mb" <<'PY'
import json, sys
out, rate, minute, rss_kb, cache_mb = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
lines = [json.loads(l) for l in open(f"{out}/dump.jsonl")]
def pct(v, p): v = sorted(v); return v[min(len(v) - 1, int(p * len(v)))] if v else 0.0
halves = {"steady": [], "changing": []}
for l in lines:
    if l.get("host_frame") is None or "timing" not in l: continue
    t = l["host_frame"] / rate
    halves["steady" if t < minute else "changing"].append(l["timing"]["frame_ms"])
stats = json.load(open(f"{out}/stats.json"))
age = stats["latency"]["arrival_to_frame_end"]
log = open(f"{out}/node.log").read()
result = {
    "frames": {k: {"count": len(v), "p50_ms": pct(v, 0.5), "p99_ms": pct(v, 0.99), "max_ms": max(v, default=0.0)}
               for k, v in halves.items()},
    "arrival_to_frame_end_ms": {k: age.get(k + "_us", 0.0) / 1000.0 for k in ("p50", "p99", "max")},
    "new_tables_requested": log.count("new tables requested"),
    "blended_until_built": log.count("blending the"),
    "own_tables_shown": log.count("its own tables are shown"),
    "node_rss_mb": rss_kb / 1024.0,
    "table_cache_mb": cache_mb,
}
json.dump(result, open(f"{out}/weather-minute.json", "w"), indent=2)
print("| minute | frames | p50 ms | p99 ms | largest ms |\n| --- | --- | --- | --- | --- |")
for k, f in result["frames"].items():
    print(f"| {k} | {f['count']} | {f['p50_ms']:.1f} | {f['p99_ms']:.1f} | {f['max_ms']:.1f} |")
a = result["arrival_to_frame_end_ms"]
print(f"\nhost datagram to the end of the frame showing it: p50 {a['p50']:.0f} ms, p99 {a['p99']:.0f} ms, max {a['max']:.0f} ms")
print(f"tables: {result['new_tables_requested']} requested, {result['blended_until_built']} blended until built, "
      f"{result['own_tables_shown']} shown built")
print(f"node memory {result['node_rss_mb']:.0f} MB, table cache {cache_mb} MB; results in {out}/weather-minute.json")
PY
