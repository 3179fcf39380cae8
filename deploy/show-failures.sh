#!/usr/bin/env bash
# After a failed ctest run in build folder $1: each failed test's output again, without
# GoogleTest's bookkeeping lines and cut to its first LINES lines (the first failure is the one to
# read), at the end of the log, where a CI log that keeps only its head and tail still shows why.
set -uo pipefail
dir=${1:?usage: show-failures.sh BUILD_DIR [LINES]}
lines=${2:-40}
failed="$dir/Testing/Temporary/LastTestsFailed.log"
log="$dir/Testing/Temporary/LastTest.log"
[ -f "$failed" ] && [ -f "$log" ] || exit 0
while IFS= read -r entry; do
  name=${entry#*:}
  echo "---- why $name failed ----"
  # LastTest.log holds each test's output between "Output:" and "<end of output>", after a
  # "N/M Test: NAME" line.
  awk -v want="$name" '
    /^[0-9]+\/[0-9]+ Test: / { name = substr($0, index($0, "Test: ") + 6) }
    /^<end of output>/ { capture = 0 }
    capture && name == want { print }
    /^Output:/ { capture = 1 }
  ' "$log" | grep -Ev '^(-{20,}|\[(-{10}|={10}|  PASSED  |  FAILED  |       OK | RUN      )\]|Running main|Note: Google Test filter| *[0-9]+ FAILED TESTS?$|$)' |
    head -n "$lines" || true
done <"$failed"
# A report, never a verdict: the caller's exit status says whether tests failed (head closing
# the pipe early would otherwise leave 141, SIGPIPE, as this script's status and the caller's).
exit 0
