#!/usr/bin/env bash
# README quick start, first command: install, build, and render the default sky (every
# channel of the embedded default configuration) into out/ as OpenEXR and PNG.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/setup.sh
bash deploy/build.sh
mkdir -p out
./build/bin/skyig render --exr out/sky.exr --png out/sky.png "$@"
