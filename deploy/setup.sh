#!/usr/bin/env bash
# Installs the Debian 12 (bookworm) packages skyig needs.
#   deploy/setup.sh            build, test and run (a developer's machine, CI)
#   deploy/setup.sh --runtime  run only: the libraries the skyig executable links and Mesa's
#                              EGL/llvmpipe drivers it loads (an IG node built elsewhere; the
#                              .deb of deploy/package.sh depends on the same, through dpkg)
# Idempotent: packages already present are left alone, and apt's lists are refreshed only
# when a package is missing. Runs apt-get as root, or through sudo.
set -euo pipefail

runtime=(
  # GL: EGL headless (Mesa llvmpipe where there is no GPU) and GLFW windows; GLX and Xlib to ask
  # the X display for swap-barrier hardware (GLX_NV_swap_group)
  libegl1 libegl-mesa0 libgl1-mesa-dri libglfw3 libglx0 libx11-6
  # images, geodesy, configuration, logging
  libopenexr-3-1-30 libpng16-16 libgeographiclib23 libtomlplusplus3 libspdlog1.10 libfmt9
)

build_and_test=(
  # toolchain; dpkg-dev (in build-essential) gives dpkg-shlibdeps to deploy/package.sh
  build-essential cmake ninja-build pkg-config git python3
  # GL headers and loaders
  # (X11: swap groups through GLX, and the window tests read the windows back with XGetImage)
  libegl-dev libgl-dev libgles-dev libglfw3-dev libglm-dev libglx-dev libx11-dev
  # GLSL compiler: the tests compile the atmosphere's physics and passes as GLSL
  glslang-tools
  # images, geodesy, plumbing
  libopenexr-dev python3-imath libpng-dev libgeographiclib-dev
  libtomlplusplus-dev libcli11-dev libspdlog-dev nlohmann-json3-dev libpcap-dev
  # projector calibration: MPCDI files are zip archives holding an XML description
  libzip-dev libtinyxml2-dev
  # tests and benchmarks (Xvfb: the windowed GLFW path is tested on a virtual X display;
  # systemd: systemd-analyze verifies the unit, deploy/skyig.service)
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth systemd
  # protocol tests: files skyig writes checked by Wireshark, tcpdump and can-utils
  tshark tcpdump can-utils
  # independent ephemerides for the ephemeris comparison test and benchmark (validation only)
  libswe-dev swe-basic-data liberfa-dev
  # libFuzzer targets (tests/fuzz), built with clang even when the rest uses gcc
  clang-14 libclang-rt-14-dev
  # the code's style (.clang-format)
  clang-format-14
  # deploy/test-package.sh (by hand, not in CI): a clean Debian 12 chroot to install the .deb in
  debootstrap
)

case "${1:-}" in
  "") packages=("${runtime[@]}" "${build_and_test[@]}") ;;
  --runtime) packages=("${runtime[@]}") ;;
  *) echo "usage: $0 [--runtime]" >&2; exit 2 ;;
esac

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
