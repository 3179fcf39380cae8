#!/usr/bin/env bash
# One command for the GPU check (docs/performance.md, "GPU check"): on a machine with an NVIDIA
# GPU (OpenGL through the vendor's EGL library, headless), within a time budget,
#   - skyig --version --caps (the GL renderer must be NVIDIA's, not llvmpipe);
#   - GL timer-query times at 1920x1200 (skyig bench): the sky pass, the day frame, the moonlit
#     and the moonless night frames, a class A goggle (moonlit night), a 1920x1200 projector's
#     warp-and-blend;
#   - the five-channel dome frame of config/dome5.toml (its 1600x1200 and 1024x1024 channels
#     timed by skyig bench, summed as the node draws them: 3 + 2);
#   - skyig precompute of the medium (the node's default) and the default tables, fresh;
#   - the golden scenes (tests/data/golden, llvmpipe's images) rendered on the GPU and compared
#     with the tolerances of tests/node/golden_look_test.cpp;
#   - atmosphere_gpu_tests (the GPU precompute against the CPU reference);
# and writes gpu-check.json and gpu-check.md into the out directory, printing the table.
# Without an NVIDIA GPU it says so, runs the same steps at a small size on llvmpipe (the
# plumbing check that keeps this script working; a ctest test runs it) and exits 0 when the
# plumbing works.
#
# Usage: deploy/gpu-check.sh [--bundle DIR] [--skyig PATH] [--out DIR] [--budget-s N] [--no-gpu]
#   --bundle DIR   a bundle made by deploy/gpu-bundle.sh (its lib/ on skyig's LD_LIBRARY_PATH)
#   --skyig PATH   this skyig (its build tree's test programs when it lies in one)
#                  default: the bundle's, else build/bin/skyig, else .gpu-bundle's, else a build
#   --out DIR      results, logs and caches (default gpu-check-out/ in the repository); nothing
#                  is written elsewhere
#   --budget-s N   the whole run's time (default 480); each step's timeout fits what is left
#   --no-gpu       the plumbing check on llvmpipe even where there is a GPU
# Exit status: 0 when every step ran and, on a GPU, the renderer is NVIDIA's, the golden images
#   match and the GPU tests pass; 1 when a step failed (or, on a GPU, a golden image differs or a
#   GPU test failed); 2 when there is an NVIDIA GPU but GL is not on it.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
bundle="" skyig="" out="$repo/gpu-check-out" budget=480 force_no_gpu=0

log() { printf '[gpu-check] %s\n' "$*"; }
die() { printf '[gpu-check] error: %s\n' "$*" >&2; exit 1; }
usage() { sed -n '/^# Usage:/,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }

while (( $# > 0 )); do
  case "$1" in
    --bundle) bundle=${2:?--bundle needs a directory}; shift 2 ;;
    --skyig) skyig=${2:?--skyig needs a path}; shift 2 ;;
    --out) out=${2:?--out needs a directory}; shift 2 ;;
    --budget-s) budget=${2:?--budget-s needs seconds}; shift 2 ;;
    --no-gpu) force_no_gpu=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument: $1" ;;
  esac
done
if ! [[ "$budget" =~ ^[0-9]+$ ]] || (( budget < 30 )); then die "--budget-s: expected whole seconds, at least 30"; fi
command -v python3 >/dev/null || die "python3 is needed (the report, the golden comparison)"
command -v timeout >/dev/null || die "timeout (coreutils) is needed"

started=$SECONDS
deadline=$(( started + budget ))
# The out directory is ours: new, empty or an earlier run's (it removes folders of its own there).
if [[ -e "$out" && ! -f "$out/meta.tsv" && -n "$(ls -A "$out" 2>/dev/null || echo x)" ]]; then
  die "--out $out is not empty and not an earlier gpu-check's out directory: not writing there"
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
for d in logs cache tmp helper; do mkdir -p "$out/$d"; done
: > "$out/steps.tsv"
: > "$out/meta.tsv"
meta() { printf '%s\t%s\n' "$1" "${2//$'\t'/ }" >> "$out/meta.tsv"; }

# ---- which skyig, which test programs, which libraries -----------------------------------
golden_dir="$repo/tests/data/golden"
scenes_source="$repo/tests/node/golden_look_test.cpp"
dome_config="$repo/config/dome5.toml"
gpu_tests="" compiled_build_dir="" data_dir=""
lib_path=""
if [[ -z "$bundle" && -z "$skyig" && ! -x "$repo/build/bin/skyig" && -x "$repo/.gpu-bundle/bin/skyig" ]]; then
  bundle="$repo/.gpu-bundle"
fi
if [[ -n "$bundle" ]]; then
  bundle=$(cd "$bundle" && pwd) || die "--bundle: no such directory"
  [[ -x "$bundle/bin/skyig" ]] || die "$bundle/bin/skyig is missing: make the bundle with deploy/gpu-bundle.sh"
  skyig=${skyig:-"$bundle/bin/skyig"}
  lib_path="$bundle/lib"
  data_dir="$bundle/share/skyig"
  [[ -x "$bundle/tests/atmosphere_gpu_tests" ]] && gpu_tests="$bundle/tests/atmosphere_gpu_tests"
  compiled_build_dir=$(sed -n 's/^build_dir=//p' "$bundle/manifest.txt" 2>/dev/null || true)
  [[ -f "$bundle/golden/look.toml" ]] && golden_dir="$bundle/golden"
  [[ -f "$bundle/golden/golden_look_test.cpp" ]] && scenes_source="$bundle/golden/golden_look_test.cpp"
  [[ -f "$bundle/config/dome5.toml" ]] && dome_config="$bundle/config/dome5.toml"
  meta bundle "$bundle"
  meta bundle_commit "$(sed -n 's/^commit=//p' "$bundle/manifest.txt" 2>/dev/null || true)"
fi
if [[ -z "$skyig" ]]; then
  if [[ ! -x "$repo/build/bin/skyig" ]]; then
    [[ -f /etc/debian_version ]] || die "no skyig: make a bundle on the Debian build machine (deploy/gpu-bundle.sh) and pass --bundle"
    log "step: build (deploy/build.sh; the Debian packages come from deploy/setup.sh)"
    "$repo/deploy/build.sh" > "$out/logs/build.log" 2>&1 || die "the build failed: $out/logs/build.log"
  fi
  skyig="$repo/build/bin/skyig"
fi
[[ -x "$skyig" ]] || die "$skyig is not an executable"
skyig=$(cd "$(dirname "$skyig")" && pwd)/$(basename "$skyig")
if [[ -z "$bundle" ]]; then
  # A build tree's skyig: its test programs beside it (build/bin/skyig -> build/tests/...).
  tree=$(dirname "$(dirname "$skyig")")
  if [[ -f "$tree/CMakeCache.txt" ]]; then
    [[ -x "$tree/tests/physics/atmosphere/atmosphere_gpu_tests" ]] && gpu_tests="$tree/tests/physics/atmosphere/atmosphere_gpu_tests"
    compiled_build_dir=$(sed -n 's/^skyig_BINARY_DIR:STATIC=//p' "$tree/CMakeCache.txt")
    data_dir="$tree/share/skyig"
  fi
fi
meta skyig "$skyig"

# The bundle's libraries for skyig and the test program only (not for python3 or the system's
# tools): skyig runs through a wrapper that sets them.
libs="${lib_path}${lib_path:+${LD_LIBRARY_PATH:+:}}${LD_LIBRARY_PATH:-}"
if [[ -n "$bundle" ]] && LD_LIBRARY_PATH="$libs" ldd "$skyig" 2>/dev/null | grep -E '^\s*lib(EGL|GLX|GLdispatch|OpenGL)\.so[^ ]* => not found' >/dev/null; then
  log "this machine has no glvnd dispatch libraries: using the bundle's lib-glvnd/"
  libs="$libs:$bundle/lib-glvnd"
  meta glvnd "the bundle's lib-glvnd (none on this machine)"
fi
if missing=$(LD_LIBRARY_PATH="$libs" ldd "$skyig" 2>/dev/null | grep 'not found'); then
  die "$skyig: libraries not found: $(echo "$missing" | awk '{print $1}' | tr '\n' ' ')"
fi
skyig_exe=$skyig
skyig="$out/helper/skyig"
printf '#!/usr/bin/env bash\n# deploy/gpu-check.sh: %s with its libraries\nLD_LIBRARY_PATH=%q exec %q "$@"\n' \
  "$skyig_exe" "$libs" "$skyig_exe" > "$skyig"
chmod +x "$skyig"

# Every cache in the out directory: skyig's tables ($XDG_CACHE_HOME/skyig; $CACHE_DIRECTORY
# would come first), Mesa's and NVIDIA's shader caches; temporary files too.
unset CACHE_DIRECTORY
export XDG_CACHE_HOME="$out/cache"
export __GL_SHADER_DISK_CACHE_PATH="$out/cache/nvidia"
export TMPDIR="$out/tmp"
export SKYIG_ATMOSPHERE_PRECOMPUTE=gpu   # the GPU path or an error, never minutes on the CPU
[[ -n "$data_dir" && -d "$data_dir" ]] && export SKYIG_DATA_DIR="$data_dir"

# ---- the GPU ------------------------------------------------------------------------------
gpu=0
if (( force_no_gpu == 0 )) && command -v nvidia-smi >/dev/null && nvidia-smi -L > "$out/logs/nvidia-smi.txt" 2>&1; then
  gpu=1
  meta card "$(nvidia-smi --query-gpu=name --format=csv,noheader 2>/dev/null | head -n 1)"
  meta driver "$(nvidia-smi --query-gpu=driver_version --format=csv,noheader 2>/dev/null | head -n 1)"
  vendor_json=""
  for f in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json \
           /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    [[ -f "$f" ]] && { vendor_json=$f; break; }
  done
  if [[ -z "$vendor_json" ]] && ldconfig -p 2>/dev/null | grep 'libEGL_nvidia\.so\.0' >/dev/null; then
    # The driver's EGL library is there without its glvnd vendor file: one of our own.
    mkdir -p "$out/egl_vendor.d"
    printf '{\n  "file_format_version": "1.0.0",\n  "ICD": { "library_path": "libEGL_nvidia.so.0" }\n}\n' \
      > "$out/egl_vendor.d/10_nvidia.json"
    vendor_json="$out/egl_vendor.d/10_nvidia.json"
  fi
  if [[ -n "$vendor_json" ]]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor_json"
    meta egl_vendor "$vendor_json"
  else
    meta egl_vendor "none found (glvnd's default search)"
  fi
  log "NVIDIA GPU: $(head -n 1 "$out/logs/nvidia-smi.txt")"
  log "EGL vendor file: ${vendor_json:-none found, glvnd searches its default folders}"
else
  if (( force_no_gpu )); then log "--no-gpu: checking the plumbing on llvmpipe"
  else log "no NVIDIA GPU: checking the plumbing on llvmpipe"; fi
  # llvmpipe even where another vendor's EGL would be picked.
  [[ -f /usr/share/glvnd/egl_vendor.d/50_mesa.json ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/glvnd/egl_vendor.d/50_mesa.json
fi
meta mode "$( ((gpu)) && echo gpu || echo plumbing)"

# Sizes, frames and tables: the real ones on a GPU, small ones for the plumbing.
if (( gpu )); then
  width=1920 height=1200 frames=200 projector=1920x1200 tables=medium
  dome_a=1600x1200 dome_b=1024x1024
  precompute_tables=(medium default)
  golden_only=""
  gpu_tests_filter="*"
  t_caps=30 t_precompute=150 t_bench=90 t_golden=150 t_gpu_tests=300
else
  width=320 height=200 frames=3 projector=320x200 tables=small
  dome_a=160x120 dome_b=100x100
  precompute_tables=(small)
  golden_only="noon,full_moon_rising,goggle_moonless_winter_night"
  gpu_tests_filter="AtmosphereGpu.BadOptionsAreRejectedWithTheirName"
  t_caps=20 t_precompute=60 t_bench=40 t_golden=60 t_gpu_tests=40
fi
meta size "${width}x${height}"
meta frames "$frames"
meta projector "$projector"
meta tables "$tables"
meta budget_s "$budget"

# ---- steps --------------------------------------------------------------------------------
# step NAME NOMINAL_TIMEOUT_S CMD...: runs CMD with its stdout and stderr in logs/NAME.out and
# .err under a timeout that keeps the run within the budget (10 s kept for the report), and
# records its exit status and seconds in steps.tsv; a failure is recorded, not fatal.
abort_reason=""
record() { printf '%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "${4//$'\t'/ }" >> "$out/steps.tsv"; }
step() {
  local name=$1 nominal=$2
  shift 2
  local left=$(( deadline - SECONDS - 10 ))
  if [[ -n "$abort_reason" ]]; then record "$name" skipped 0 "$abort_reason"; log "step: $name skipped ($abort_reason)"; return 0; fi
  if (( left < 5 )); then record "$name" skipped 0 "out of budget"; log "step: $name skipped (out of budget)"; return 0; fi
  local limit=$(( nominal < left ? nominal : left ))
  log "step: $name (timeout ${limit} s)"
  local t0 t1 rc=0
  t0=$(date +%s.%N)
  timeout -k 5 "$limit" "$@" > "$out/logs/$name.out" 2> "$out/logs/$name.err" || rc=$?
  t1=$(date +%s.%N)
  local secs
  secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
  record "$name" "$rc" "$secs" ""
  if (( rc == 0 )); then log "  done in ${secs} s"
  elif (( rc == 124 || rc == 137 )); then log "  TIMED OUT after ${secs} s (logs/$name.err)"
  else log "  exit status $rc after ${secs} s: $(tail -n 2 "$out/logs/$name.err" | tr '\n' ' ' | cut -c1-200)"; fi
  return 0
}

# The sky configurations: a table size and no visibility steps (precompute builds only these
# tables; bench reads the same ones from the cache).
for t in small medium default; do
  printf '[sky]\natmosphere_tables = "%s"\natmosphere_visibility_steps = []\n' "$t" > "$out/sky-$t.toml"
done
if (( gpu )); then
  dome_toml="$dome_config"
else
  awk '/^[[:space:]]*atmosphere_tables[[:space:]]*=/ { next }
       { print }
       /^\[sky\][[:space:]]*$/ { print "atmosphere_tables = \"small\""; done = 1 }
       END { if (!done) print "[sky]\natmosphere_tables = \"small\"" }' "$dome_config" > "$out/dome5-small.toml"
  dome_toml="$out/dome5-small.toml"
fi

step caps "$t_caps" "$skyig" --version --caps
renderer=$(sed -n 's/^GL renderer:[[:space:]]*//p' "$out/logs/caps.out" | head -n 1)
if (( gpu )); then
  if [[ "$renderer" != *NVIDIA* && "$renderer" != *nvidia* ]]; then
    log "****************************************************************************"
    log "ERROR: an NVIDIA GPU is here but GL is not on it: the renderer is '${renderer:-none}'"
    log "  EGL vendor file: ${__EGL_VENDOR_LIBRARY_FILENAMES:-none set}"
    log "  libEGL_nvidia in ldconfig: $(ldconfig -p 2>/dev/null | grep -c 'libEGL_nvidia') entries"
    log "  skyig's GL libraries: $(LD_LIBRARY_PATH="$libs" ldd "$skyig_exe" | grep -E 'lib(EGL|GLX|GLdispatch)' | awk '{print $1 "=" $3}' | tr '\n' ' ')"
    log "  (the container may lack the driver's graphics libraries: NVIDIA_DRIVER_CAPABILITIES=graphics)"
    log "****************************************************************************"
    abort_reason="the GL renderer is not NVIDIA's"
    meta renderer_error "GL renderer '${renderer:-none}' is not NVIDIA's"
  fi
fi

# Precompute, fresh (its own empty cache), then its tables moved into the shared cache.
for t in "${precompute_tables[@]}"; do
  rm -rf "${out:?}/precompute-$t"
  step "precompute_$t" "$t_precompute" "$skyig" --log-level info precompute --config "$out/sky-$t.toml" --cache "$out/precompute-$t"
  mkdir -p "$out/cache/skyig"
  find "$out/precompute-$t" -maxdepth 1 -name '*.skyatm' -exec mv -f {} "$out/cache/skyig/" \; 2>/dev/null || true
  rm -rf "${out:?}/precompute-$t"
done

bench=("$skyig" bench --config "$out/sky-$tables.toml" --width "$width" --height "$height" --frames "$frames"
       --projector-size "$projector" --json)
step bench_day "$t_bench" "${bench[@]}" --utc 2026-06-21T11:00:00Z --yaw 180
step bench_moonlit_night "$t_bench" "${bench[@]}" --utc 2026-12-25T17:40:00Z --yaw 60 --pitch 2
step bench_moonless_night "$t_bench" "${bench[@]}" --utc 2026-12-09T22:00:00Z --yaw 180 --pitch 30
# The day frame at 30 m inside a 200 m ground fog of 400 m visibility (physics/weather): the fog
# layer's cost over the sky pass.
step bench_fog "$t_bench" "${bench[@]}" --utc 2026-06-21T11:00:00Z --yaw 180 --alt 30 --fog-visibility 0.4 --fog-top 200
for size in "$dome_a" "$dome_b"; do
  step "bench_dome5_$size" "$t_bench" "$skyig" bench --config "$dome_toml" --width "${size%x*}" --height "${size#*x}" \
    --frames "$frames" --projector-size "$projector" --json --utc 2026-06-21T11:00:00Z
done
meta dome_sizes "$dome_a,$dome_b"

# The helper: the golden comparison, the relocation of the test program's cache, the report.
helper="$out/helper/gpu_check.py"
cat > "$helper" <<'PY'
"""deploy/gpu-check.sh's helper: golden | relocate | report (written by the script each run)."""
import json, os, re, shlex, struct, subprocess, sys, time, zlib


def read_png(path):
    """8-bit, non-interlaced PNG -> (width, height, RGB bytes); alpha composed on black as
    tests/node/golden_look_test.cpp's libpng read does (the goldens are opaque)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, hdr = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    w, h, depth, ctype, _, _, interlace = hdr
    ch = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    if depth != 8 or interlace:
        raise ValueError(f"{path}: only 8-bit non-interlaced PNGs are read")
    raw = zlib.decompress(idat)
    stride, bpp, p = w * ch, ch, 0
    prev, pix = bytearray(stride), bytearray()
    for _ in range(h):
        ft = raw[p]
        line = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if ft == 1:
                line[i] = (line[i] + a) & 255
            elif ft == 2:
                line[i] = (line[i] + b) & 255
            elif ft == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ft == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        pix += line
        prev = line
    rgb = bytearray()
    for i in range(0, len(pix), ch):
        if ch >= 3:
            v = pix[i:i + 3]
        else:
            v = bytes([pix[i]]) * 3
        if ch in (2, 4) and pix[i + ch - 1] != 255:
            v = bytes(round(x * pix[i + ch - 1] / 255) for x in v)
        rgb += v
    return w, h, bytes(rgb)


def golden(skyig, golden_dir, scenes_source, work, out_json, only, deadline):
    """Renders the golden scenes as golden_look_test.cpp does and compares them with its
    tolerances: mean difference <= 1.5 codes and 99% of the values within 6 codes."""
    text = open(scenes_source).read()
    block = text[text.index("kScenes[]"):]
    block = block[:block.index("};")]
    scenes = re.findall(r'\{\s*"([A-Za-z0-9_]+)"\s*,\s*"([^"]*)"\s*\}', block)
    if not scenes:
        raise SystemExit(f"no scenes found in {scenes_source}")
    if only:
        wanted = only.split(",")
        scenes = [s for s in scenes if s[0] in wanted] or scenes[:3]
    os.makedirs(work, exist_ok=True)
    results, broken = [], 0
    for name, args in scenes:
        png = os.path.join(work, name + ".png")
        cmd = [skyig, "render", "--config", os.path.join(golden_dir, "look.toml"), *shlex.split(args), "--png", png]
        r = {"scene": name, "args": args}
        left = deadline - time.time()
        if left < 2:
            r["error"] = "out of budget"
            results.append(r)
            broken += 1
            continue
        try:
            with open(png + ".err", "w") as err:
                rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=err, timeout=left).returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
        if rc != 0:
            r["error"] = f"skyig render: exit status {rc} ({png}.err)"
        else:
            try:
                wa, ha, a = read_png(png)
                wb, hb, b = read_png(os.path.join(golden_dir, name + ".png"))
                if (wa, ha) != (wb, hb):
                    r["error"] = f"size {wa}x{ha}, golden {wb}x{hb}"
                else:
                    d = [abs(x - y) for x, y in zip(a, b)]
                    r["mean_codes"] = round(sum(d) / len(d), 4)
                    r["share_within_6"] = round(sum(1 for v in d if v <= 6) / len(d), 5)
                    r["max_codes"] = max(d)
                    r["within_tolerance"] = r["mean_codes"] <= 1.5 and r["share_within_6"] >= 0.99
            except (OSError, ValueError, KeyError, zlib.error) as e:
                r["error"] = str(e)
        broken += "error" in r
        results.append(r)
        state = r.get("error") or ("within tolerance" if r["within_tolerance"] else "DIFFERS")
        print(f"{name}: {state} (mean {r.get('mean_codes', '-')} codes, {r.get('share_within_6', '-')} within 6)")
    json.dump({"tolerance": {"mean_codes_max": 1.5, "share_within_6_min": 0.99}, "scenes": results},
              open(out_json, "w"), indent=2)
    return 1 if broken else 0


def relocate(src, dst, build_dir):
    """Copies a test program with its compiled-in build directory (the test cache lies under it,
    tests/physics/atmosphere/shared_models.h) replaced by a relative path of the same length, so
    that it writes under the directory it runs in. The path may be stored without its NUL (the
    compiler folds its length), hence the same length."""
    data = open(src, "rb").read()
    old = build_dir.encode()
    n = len(old)
    if n < 4 or data.count(old) == 0:
        print(f"{build_dir!r} is not in {src}: cannot relocate its test cache", file=sys.stderr)
        return 3
    name = b"gc" if n % 2 == 0 else b"gc_"
    new = b"./" * ((n - len(name)) // 2) + name
    assert len(new) == n
    with open(dst, "wb") as f:
        f.write(data.replace(old, new))
    os.chmod(dst, 0o755)
    print(new.decode())
    return 0


def tsv(path):
    rows = []
    if os.path.exists(path):
        for line in open(path):
            rows.append(line.rstrip("\n").split("\t"))
    return rows


def load_json(path):
    try:
        return json.load(open(path))
    except (OSError, ValueError):
        return None


def report(out, elapsed):
    meta = {}
    for row in tsv(os.path.join(out, "meta.tsv")):
        if row and row[0]:
            meta[row[0]] = row[1] if len(row) > 1 else ""
    gpu = meta.get("mode") == "gpu"
    logs = os.path.join(out, "logs")
    figures, steps = {}, []

    def fig(key, value, unit, label, goal=None):
        if value is None:
            return
        f = {"value": value, "unit": unit, "label": label}
        if goal is not None:
            f["goal"] = goal
            if gpu and isinstance(value, (int, float)):
                f["met"] = value < goal
        figures[key] = f

    def read(name, ext):
        try:
            return open(os.path.join(logs, f"{name}.{ext}")).read()
        except OSError:
            return ""

    for name, rc, secs, detail in tsv(os.path.join(out, "steps.tsv")):
        s = {"step": name, "seconds": float(secs)}
        if rc == "skipped":
            s["status"], s["detail"] = "skipped", detail
        else:
            s["exit_status"] = int(rc)
            s["status"] = "ok" if rc == "0" else "timeout" if rc in ("124", "137") else "failed"
        steps.append(s)
    by = {s["step"]: s for s in steps}

    caps = read("caps", "out")
    for key, label in (("GL renderer", "gl_renderer"), ("GL version", "gl_version"), ("GPU timing", "gpu_timing")):
        m = re.search(rf"^{key}:\s*(.*)$", caps, re.M)
        if m:
            fig(label, m.group(1).strip(), "", key)
    m = re.search(r"^(skyig .*)$", caps, re.M)
    if m:
        meta["skyig_version"] = m.group(1)
    if "caps" in by and by["caps"]["status"] == "ok" and "gl_renderer" not in figures:
        by["caps"]["status"], by["caps"]["detail"] = "failed", "no GL renderer line"

    size = meta.get("size", "?")
    def bench(name):
        j = load_json(os.path.join(logs, f"{name}.out"))
        if name in by and by[name]["status"] == "ok" and not isinstance(j, dict):
            by[name]["status"], by[name]["detail"] = "failed", "no JSON"
        return j if isinstance(j, dict) else {}
    day, moonlit, moonless = bench("bench_day"), bench("bench_moonlit_night"), bench("bench_moonless_night")
    if day.get("timing"):
        meta["timing"] = day["timing"]
    fig("sky_pass_ms", day.get("sky_pass_ms"), "ms", f"sky pass, {size}, noon", 0.3)
    fig("sky_pass_ns_per_pixel", day.get("sky_pass_ns_per_pixel"), "ns/pixel", f"sky pass per pixel, {size}")
    fig("day_frame_ms", day.get("sky_and_tone_ms"), "ms", f"day frame (whole channel), {size}", 1.0)
    fig("moonlit_night_frame_ms", moonlit.get("sky_and_tone_ms"), "ms", f"moonlit night frame, {size}")
    fig("moonless_night_frame_ms", moonless.get("sky_and_tone_ms"), "ms", f"moonless night frame, {size}")
    fog = bench("bench_fog")
    fig("fog_sky_pass_ms", fog.get("sky_pass_ms"), "ms", f"sky pass inside a 200 m ground fog, {size}")
    if fog.get("sky_pass_ms") and day.get("sky_pass_ms"):
        fig("fog_over_sky_pass", fog["sky_pass_ms"] / day["sky_pass_ms"] - 1.0, "x",
            "the fog's cost over the clear sky pass (goal 0.2)", 0.2)
    fig("goggle_frame_ms", moonlit.get("goggle_channel_ms"), "ms", f"class A goggle frame, moonlit night, {size}")
    fig("warp_blend_ms", day.get("warp_blend_pass_ms"), "ms", f"warp and blend, one {meta.get('projector', '?')} projector")
    fig("host_frame_ms", day.get("host_frame_ms"), "ms", f"in a host's frame (channel + composite), {size}")
    dome = meta.get("dome_sizes", "").split(",")
    dome_ms = []
    for i, ds in enumerate(dome):
        j = bench(f"bench_dome5_{ds}") if ds else {}
        v = j.get("sky_and_tone_ms")
        fig(f"dome5_channel_{ds}_ms", v, "ms", f"dome5 channel frame, {ds}, noon")
        dome_ms.append(v)
    if len(dome_ms) == 2 and None not in dome_ms:
        fig("dome5_frame_ms", 3 * dome_ms[0] + 2 * dome_ms[1], "ms",
            f"five-channel dome frame (3 x {dome[0]} + 2 x {dome[1]} channels)", 8.0 if gpu else None)

    for t in ("small", "medium", "default"):
        name = f"precompute_{t}"
        if name not in by:
            continue
        m = re.search(r"precomputed (\d+) wavelength groups on the GPU in ([0-9.]+) s", read(name, "err"))
        if m:
            fig(f"precompute_{t}_s", float(m.group(2)), "s", f"precompute, {t} tables (GPU path)",
                1.0 if t == "default" else None)
        elif by[name]["status"] == "ok":
            by[name]["status"], by[name]["detail"] = "failed", "no GPU precompute time in its log"
        if by[name]["status"] == "ok":
            fig(f"precompute_{t}_wall_s", by[name]["seconds"], "s", f"skyig precompute, {t} tables, whole process")

    g = load_json(os.path.join(out, "golden.json"))
    golden_ok = None
    if isinstance(g, dict):
        sc = g.get("scenes", [])
        within = sum(1 for s in sc if s.get("within_tolerance"))
        compared = [s for s in sc if "mean_codes" in s]
        golden_ok = within == len(sc) and len(sc) > 0
        fig("golden_within_tolerance", f"{within}/{len(sc)}", "scenes", "golden images within tolerance")
        if compared:
            fig("golden_worst_mean_codes", max(s["mean_codes"] for s in compared), "codes", "golden images: worst mean difference (<= 1.5)")
            fig("golden_worst_share_within_6", min(s["share_within_6"] for s in compared), "", "golden images: worst share within 6 codes (>= 0.99)")
    elif "golden" in by and by["golden"]["status"] == "ok":
        by["golden"]["status"], by["golden"]["detail"] = "failed", "no golden.json"

    gt = load_json(os.path.join(out, "atmosphere_gpu_tests.json"))
    gpu_tests_ok = None
    if "atmosphere_gpu_tests" in by and by["atmosphere_gpu_tests"]["status"] != "skipped":
        s = by["atmosphere_gpu_tests"]
        if isinstance(gt, dict):
            cases = [c for suite in gt.get("testsuites", []) for c in suite.get("testsuite", [])]
            failed = sum(1 for c in cases if c.get("failures"))
            skipped = sum(1 for c in cases if c.get("result") == "SKIPPED")
            passed = len(cases) - failed - skipped
            fig("atmosphere_gpu_tests", f"{passed} passed, {failed} failed, {skipped} skipped", "tests",
                "GPU precompute against the CPU reference")
            gpu_tests_ok = failed == 0 and skipped == 0 and len(cases) > 0
            if s["status"] == "failed" and s.get("exit_status") == 1:
                s["status"], s["detail"] = "ok", "ran; tests failed"
        elif s["status"] == "ok":
            s["status"], s["detail"] = "failed", "no test report"
    elif "atmosphere_gpu_tests" in by:
        gpu_tests_ok = None

    bad = [s["step"] for s in steps if s["status"] in ("failed", "timeout")]
    plumbing_ok = not bad and "gl_renderer" in figures and "sky_pass_ms" in figures
    renderer_ok = not gpu or "NVIDIA" in str(figures.get("gl_renderer", {}).get("value", "")).upper()
    result = {
        "gpu": gpu,
        "plumbing": "ok" if plumbing_ok else "broken",
        "card": meta.get("card"),
        "driver": meta.get("driver"),
        "gl_renderer": figures.get("gl_renderer", {}).get("value"),
        "timing": meta.get("timing"),
        "size": size,
        "frames": int(meta.get("frames", "0") or 0),
        "tables": meta.get("tables"),
        "golden_within_tolerance": golden_ok,
        "atmosphere_gpu_tests_passed": gpu_tests_ok,
        "failed_steps": bad,
        "elapsed_s": elapsed,
        "budget_s": int(meta.get("budget_s", "0")),
        "skyig": meta.get("skyig"),
        "skyig_version": meta.get("skyig_version"),
        "bundle": meta.get("bundle"),
        "bundle_commit": meta.get("bundle_commit"),
        "egl_vendor": meta.get("egl_vendor"),
        "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "figures": figures,
        "steps": steps,
    }
    if meta.get("renderer_error"):
        result["error"] = meta["renderer_error"]
    if gpu:
        result["passed"] = plumbing_ok and renderer_ok and golden_ok is True and gpu_tests_ok is True
    with open(os.path.join(out, "gpu-check.json"), "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")

    def show(v):
        return f"{v:.3f}" if isinstance(v, float) else str(v)
    where = (f"{meta.get('card', 'GPU')}, driver {meta.get('driver', '?')}" if gpu
             else "no GPU: the plumbing check on llvmpipe, small sizes (not GPU figures)")
    md = [f"GPU check, {result['date']}: {where}",
          f"GL renderer: {result['gl_renderer'] or '?'}; {meta.get('timing', 'no timing')}",
          f"{meta.get('frames', '?')} timed frames (median); {meta.get('tables', '?')} tables; "
          f"{meta.get('skyig_version') or 'skyig'}" + (f", commit {meta['bundle_commit']}" if meta.get("bundle_commit") else ""),
          ""]
    if result.get("error"):
        md += [f"**ERROR: {result['error']}** (the steps after the caps were not run)", ""]
    md += ["| figure | value | goal |", "| --- | --- | --- |"]
    for key, f in figures.items():
        if key in ("gl_renderer", "gl_version", "gpu_timing"):
            continue
        goal = ""
        if "goal" in f and gpu:
            goal = f"< {f['goal']:g} {f['unit']}" + ((" met" if f["met"] else " **not met**") if "met" in f else "")
        md.append(f"| {f['label']} | {show(f['value'])} {f['unit']} | {goal} |".replace("  |", " |"))
    md.append("")
    md.append("| step | status | seconds |")
    md.append("| --- | --- | --- |")
    for s in steps:
        st = s["status"] + (f" ({s['detail']})" if s.get("detail") else "")
        if s.get("exit_status") not in (None, 0):
            st += f", exit {s['exit_status']}"
        md.append(f"| {s['step']} | {st} | {s['seconds']:.1f} |")
    verdict = (f"plumbing {result['plumbing']}" + (f"; passed: {result['passed']}" if gpu else "")
               + f"; {elapsed} s of a {result['budget_s']} s budget")
    md += ["", verdict, ""]
    with open(os.path.join(out, "gpu-check.md"), "w") as f:
        f.write("\n".join(md))
    print("\n".join(md))
    if gpu and not renderer_ok:
        return 2
    if gpu:
        return 0 if result["passed"] else 1
    return 0 if plumbing_ok else 1


if __name__ == "__main__":
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "golden":
        sys.exit(golden(*args[:6], float(args[6])))
    if cmd == "relocate":
        sys.exit(relocate(*args))
    if cmd == "report":
        sys.exit(report(args[0], int(args[1])))
    sys.exit(f"unknown command {cmd}")
PY

rm -rf "${out:?}/golden"
step golden "$t_golden" python3 "$helper" golden "$skyig" "$golden_dir" "$scenes_source" "$out/golden" \
  "$out/golden.json" "$golden_only" "$(( $(date +%s) + deadline - SECONDS - 10 ))"
if [[ -s "$out/logs/golden.out" ]]; then
  log "  $(grep -c 'within tolerance' "$out/logs/golden.out" || true) of $(grep -c . "$out/logs/golden.out") scenes within tolerance"
fi

# atmosphere_gpu_tests: a copy whose test cache (compiled into it under the build directory) is
# relocated into the out directory; not run when that cannot be done.
rm -f "$out/atmosphere_gpu_tests.json"
if [[ -z "$gpu_tests" ]]; then
  record atmosphere_gpu_tests skipped 0 "not built or not bundled"
  log "step: atmosphere_gpu_tests skipped (not built or not bundled)"
elif [[ -z "$compiled_build_dir" ]]; then
  record atmosphere_gpu_tests skipped 0 "its build directory is unknown: its test cache cannot be relocated"
  log "step: atmosphere_gpu_tests skipped (its build directory is unknown)"
elif ! python3 "$helper" relocate "$gpu_tests" "$out/helper/atmosphere_gpu_tests" "$compiled_build_dir" \
       > "$out/logs/relocate.out" 2> "$out/logs/relocate.err"; then
  record atmosphere_gpu_tests skipped 0 "$(head -n 1 "$out/logs/relocate.err")"
  log "step: atmosphere_gpu_tests skipped ($(head -n 1 "$out/logs/relocate.err"))"
else
  mkdir -p "$out/gpu-tests"
  # shellcheck disable=SC2016  # $1 and $2 are the inner shell's
  step atmosphere_gpu_tests "$t_gpu_tests" bash -c 'cd "$1" && LD_LIBRARY_PATH="$5" exec "$2" --gtest_filter="$3" --gtest_output="json:$4"' _ \
    "$out/gpu-tests" "$out/helper/atmosphere_gpu_tests" "$gpu_tests_filter" "$out/atmosphere_gpu_tests.json" "$libs"
fi

elapsed=$(( SECONDS - started ))
log "report: $out/gpu-check.json, $out/gpu-check.md"
echo
rc=0
python3 "$helper" report "$out" "$elapsed" || rc=$?
exit "$rc"
