#!/usr/bin/env bash
# Runs a command in a scratch directory; passes when it exits non-zero and its output contains
# every given pattern.   expect_failure.sh PATTERN [PATTERN...] -- COMMAND [ARGS...]
set -u
patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do patterns+=("$1"); shift; done
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$(cd "$work" && "$@" 2>&1)
status=$?
echo "$out" | grep -v '^\[' | tail -20
echo "exit status: $status"
[ $status -ne 0 ] || { echo "FAIL: expected a non-zero exit"; exit 1; }
for p in "${patterns[@]}"; do
  grep -q -- "$p" <<<"$out" || { echo "FAIL: output lacks '$p'"; exit 1; }
done
echo "PASS"
