#!/usr/bin/env bash
# Packs a built skyig for deploy/gpu-check.sh on a machine that cannot build it (a GPU machine
# with NVIDIA's driver and glvnd but none of the Debian libraries skyig links):
#
#   deploy/gpu-bundle.sh [BUNDLE_DIR]      # default: .gpu-bundle in the repository root
#
# Run it here, on the Debian build machine, after a build (deploy/build.sh). The bundle holds:
#   bin/skyig                     stripped copy of build/bin/skyig
#   share/skyig/                  its data files (skyig reads <bin>/../share/skyig)
#   tests/atmosphere_gpu_tests    stripped copy: the GPU precompute against the CPU reference
#   lib/                          every shared library they need per ldd, except the glibc
#                                 family, libstdc++/libgcc_s (the target's are newer) and the
#                                 GL dispatch libraries (the target's driver + glvnd provide them)
#   lib-glvnd/                    this machine's glvnd dispatch libraries, used by gpu-check.sh
#                                 only where the target has none (never ahead of the target's)
#   golden/                       the golden scenes and images (tests/data/golden and the scene
#                                 list of tests/node/golden_look_test.cpp) of this build
#   config/dome5.toml             the five-channel dome configuration
#   manifest.txt                  the commit, the build directory compiled into the test binary
#
# The golden-image test binary (node_tests, built from tests/node/golden_look_test.cpp with the
# rest of the node's tests) is not bundled: it compiles in the absolute paths of the source tree,
# the build tree and skyig and is 80 MB; gpu-check.sh renders the same scenes with the bundled
# skyig and compares them with the same tolerances instead.
#
# Then carry the repository with BUNDLE_DIR to the GPU machine and run there:
#   deploy/gpu-check.sh --bundle .gpu-bundle
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build="$repo/build"
bundle=${1:-"$repo/.gpu-bundle"}

log() { printf '[gpu-bundle] %s\n' "$*"; }
die() { printf '[gpu-bundle] error: %s\n' "$*" >&2; exit 1; }

skyig="$build/bin/skyig"
gpu_tests="$build/tests/physics/atmosphere/atmosphere_gpu_tests"
[[ -x "$skyig" ]] || die "$skyig is missing: build first (deploy/build.sh)"
[[ -d "$build/share/skyig" ]] || die "$build/share/skyig (the staged data files) is missing: build first"
command -v ldd >/dev/null || die "ldd not found"
if command -v strip >/dev/null; then strip_cmd=(strip --strip-unneeded)
elif command -v objcopy >/dev/null; then strip_cmd=(objcopy --strip-debug)
else die "neither strip nor objcopy found (binutils)"; fi

# Never write into a directory that is not a bundle: an existing BUNDLE_DIR must be empty or
# hold a manifest.txt of an earlier bundle.
if [[ -e "$bundle" ]]; then
  [[ -d "$bundle" ]] || die "$bundle exists and is not a directory"
  if [[ -n "$(ls -A "$bundle")" && ! -f "$bundle/manifest.txt" ]]; then
    die "$bundle is not empty and holds no manifest.txt: not replacing it"
  fi
  rm -rf "${bundle:?}/bin" "${bundle:?}/lib" "${bundle:?}/lib-glvnd" "${bundle:?}/share" \
         "${bundle:?}/tests" "${bundle:?}/golden" "${bundle:?}/config" "${bundle:?}/manifest.txt"
fi
mkdir -p "$bundle/bin" "$bundle/lib" "$bundle/lib-glvnd" "$bundle/share" "$bundle/tests" \
         "$bundle/golden" "$bundle/config"
bundle=$(cd "$bundle" && pwd)

log "step: binaries (stripped with ${strip_cmd[0]})"
"${strip_cmd[@]}" -o "$bundle/bin/skyig" "$skyig"
binaries=("$skyig")
if [[ -x "$gpu_tests" ]]; then
  "${strip_cmd[@]}" -o "$bundle/tests/atmosphere_gpu_tests" "$gpu_tests"
  binaries+=("$gpu_tests")
else
  log "  $gpu_tests not built: the bundle has no GPU-against-CPU precompute test"
fi
cp -r "$build/share/skyig" "$bundle/share/skyig"

log "step: shared libraries (ldd)"
# Sonames left to the target: glibc's family, the C++ runtime (the target's is newer) and the
# GL dispatch libraries (NVIDIA's driver through glvnd). The last are kept aside in lib-glvnd/.
glibc_re='^(linux-vdso|linux-gate|ld-linux.*|libc|libm|libdl|libpthread|librt|libresolv|libutil|libanl|libmvec|libstdc\+\+|libgcc_s)\.so'
gl_re='^(libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libGLES[A-Za-z0-9_]*)\.so'
declare -A seen=()
for bin in "${binaries[@]}"; do
  while read -r name arrow path _; do
    [[ "$arrow" == "=>" && "$path" == /* ]] || continue
    [[ -n "${seen[$name]:-}" ]] && continue
    seen[$name]=1
    if [[ "$name" =~ $glibc_re ]]; then continue; fi
    if [[ "$name" =~ $gl_re ]]; then cp -L "$path" "$bundle/lib-glvnd/$name"; continue; fi
    cp -L "$path" "$bundle/lib/$name"
  done < <(ldd "$bin")
  if ldd "$bin" | grep -q 'not found'; then die "ldd $bin: a library is not found here"; fi
done
chmod -R u+w "$bundle/lib" "$bundle/lib-glvnd"

log "step: golden scenes and the dome configuration"
cp "$repo"/tests/data/golden/*.png "$repo/tests/data/golden/look.toml" "$bundle/golden/"
cp "$repo/tests/node/golden_look_test.cpp" "$bundle/golden/"
cp "$repo/config/dome5.toml" "$bundle/config/"

build_dir=$(sed -n 's/^skyig_BINARY_DIR:STATIC=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
{
  echo "commit=$(git -C "$repo" rev-parse HEAD 2>/dev/null || echo unknown)$(git -C "$repo" diff --quiet HEAD 2>/dev/null || echo '+changes')"
  echo "made=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "made_on=$(sed -n 's/^PRETTY_NAME=//p' /etc/os-release 2>/dev/null | tr -d '"')"
  echo "skyig=$("$bundle/bin/skyig" --version 2>/dev/null | head -n 1 || echo unknown)"
  echo "build_dir=${build_dir:-$build}"
} > "$bundle/manifest.txt"

log "bundle: $bundle"
log "  libraries: $(find "$bundle/lib" -type f | wc -l) in lib/, $(find "$bundle/lib-glvnd" -type f | wc -l) glvnd fallbacks in lib-glvnd/"
size_mb=$(du -sm "$bundle" | cut -f1)
log "  size: $(du -sh "$bundle" | cut -f1) (${size_mb} MB)"
if (( size_mb > 40 )); then log "  warning: over 40 MB"; fi
log "next: carry the repository and the bundle to the GPU machine, then: deploy/gpu-check.sh --bundle ${bundle#"$repo"/}"
