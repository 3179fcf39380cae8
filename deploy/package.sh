#!/usr/bin/env bash
# Builds skyig's Debian package: build-package/skyig_VERSION_ARCH.deb (the executable, stripped;
# the data files in /usr/share/skyig; the systemd unit and its sysusers.d user; the example
# configuration as the conffile /etc/skyig/skyig.toml). Its dependencies are the runtime
# libraries only, found by dpkg-shlibdeps. Needs the build set of deploy/setup.sh (dpkg-dev).
# Prints the package's path on its last line. Extra arguments go to CMake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
build="build-package"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_INSTALL_PREFIX=/usr -DCMAKE_INSTALL_SYSCONFDIR=/etc \
      -DSKYIG_BUILD_TESTS=OFF -DSKYIG_BUILD_BENCHMARKS=OFF "$@" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls -t "$build"/skyig_*.deb | head -n 1)
dpkg-deb --info "$deb" | sed -n '/Package:/,$p' >&2
echo "$deb"
