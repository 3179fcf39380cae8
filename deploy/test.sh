#!/usr/bin/env bash
# README quick start, second command: install, build with warnings as errors, run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/setup.sh
bash deploy/build.sh -DSKYIG_WERROR=ON
cd build
status=0
ctest --output-on-failure --parallel "$(nproc)" --timeout 600 || status=$?
[ "$status" -eq 0 ] || bash ../deploy/show-failures.sh .
exit "$status"
