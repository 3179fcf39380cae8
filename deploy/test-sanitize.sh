#!/usr/bin/env bash
# CI's sanitizer job: the readers of what comes from outside, the protocol tests (CIGI and
# CANaerospace codecs, pcap and candump recordings) and the calibration tests (MPCDI, PFM and
# Bourke files, every way one can be bad), built with AddressSanitizer and
# UndefinedBehaviorSanitizer in build-asan/. Builds only those test programs and the two
# libraries they link (no GL, no tables), then runs their tests; a finding fails its test.
# Extra arguments go to CMake's configure step.
# SKYIG_SANITIZE_TARGETS="protocol_tests node_tests" adds the node's tests (its threads,
# record/replay, the CLI through build-asan/bin/skyig): twenty minutes more on two cores, a
# developer's command before changing the node, not CI's (docs/design.md, "Build habits").
# SKYIG_SANITIZE=thread runs the node tests under ThreadSanitizer in build-tsan/ instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/setup.sh

sanitizers=${SKYIG_SANITIZE:-address,undefined}
if [ "$sanitizers" = thread ]; then
  dir=build-tsan
  targets=(node_tests)
else
  dir=build-asan
  read -r -a targets <<<"${SKYIG_SANITIZE_TARGETS:-protocol_tests calibration_tests}"
fi
start=$SECONDS
# -O1 -g1: half the compile time of -O2 -g with ASan and UBSan (measured on five of the heaviest
# files: 48 s against 98 s), and the line tables are all a sanitizer's stacks need. No -Werror:
# GCC warns spuriously about instrumented code; the main build keeps it.
flags="-O1 -g1 -DNDEBUG"
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKYIG_SANITIZE="$sanitizers" \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" \
      -DSKYIG_BUILD_BENCHMARKS=OFF -DSKYIG_FUZZ_WITH_CLANG=OFF "$@" >/dev/null
cmake --build "$dir" --parallel "$(nproc)" --target "${targets[@]}"
built=$((SECONDS - start))

labels="^($(IFS='|'; echo "${targets[*]}"))\$"
status=0
(cd "$dir" && ctest --output-on-failure --parallel "$(nproc)" --timeout 600 -L "$labels") || status=$?
[ "$status" -eq 0 ] || bash deploy/show-failures.sh "$dir"
result=passed
[ "$status" -eq 0 ] || result=FAILED
echo "test-sanitize: ${result}: ${targets[*]} under -fsanitize=${sanitizers}" \
     "(build ${built} s, tests $((SECONDS - start - built)) s)"
exit "$status"
