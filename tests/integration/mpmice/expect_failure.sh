#!/usr/bin/env bash
# Runs a command in a scratch directory; passes when it exits non-zero (with --status N: exactly
# N) and its output contains every given pattern.
#   expect_failure.sh [--status N] PATTERN [PATTERN...] -- COMMAND [ARGS...]
set -u
patterns=()
want=""
if [ "${1:-}" = "--status" ]; then want=$2; shift 2; fi
while [ $# -gt 0 ] && [ "$1" != "--" ]; do patterns+=("$1"); shift; done
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$(cd "$work" && "$@" 2>&1)
status=$?
echo "$out" | grep -v '^\[' | tail -20
echo "exit status: $status"
[ $status -ne 0 ] || { echo "FAIL: expected a non-zero exit"; exit 1; }
[ -z "$want" ] || [ "$status" = "$want" ] || { echo "FAIL: expected exit status $want"; exit 1; }
for p in "${patterns[@]}"; do
  grep -q -- "$p" <<<"$out" || { echo "FAIL: output lacks '$p'"; exit 1; }
done
echo "PASS"
