#!/usr/bin/env bash
# README quick start, second command: install, build with warnings as errors, run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/setup.sh
bash deploy/build.sh -DSKYIG_WERROR=ON
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
