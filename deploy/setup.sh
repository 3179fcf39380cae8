#!/usr/bin/env bash
# Installs every package skyig needs to build, test and run on Debian 12 (bookworm).
# Idempotent: packages already present are left alone, and apt's lists are refreshed only
# when a package is missing. Runs apt-get as root, or through sudo.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git python3
  # GL: EGL headless (Mesa llvmpipe where there is no GPU) and GLFW windows
  libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev libglm-dev
  # GLSL compiler: the tests compile the atmosphere's physics and passes as GLSL
  glslang-tools
  # images, geodesy, plumbing
  libopenexr-dev python3-imath libpng-dev libgeographiclib-dev
  libtomlplusplus-dev libcli11-dev libspdlog-dev nlohmann-json3-dev libpcap-dev
  # tests and benchmarks (Xvfb: the windowed GLFW path is tested on a virtual X display)
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth
  # protocol tests: files skyig writes checked by Wireshark, tcpdump and can-utils
  tshark tcpdump can-utils
  # independent ephemerides for the ephemeris comparison test and benchmark (validation only)
  libswe-dev swe-basic-data liberfa-dev
  # libFuzzer targets (tests/fuzz), built with clang even when the rest uses gcc
  clang-14 libclang-rt-14-dev
  # the code's style (.clang-format)
  clang-format-14
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get -o DPkg::Lock::Timeout=300 update -q
"${as_root[@]}" apt-get -o DPkg::Lock::Timeout=300 install -y -q --no-install-recommends "${missing[@]}"
