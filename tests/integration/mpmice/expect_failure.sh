#!/usr/bin/env bash
# Runs a command in a scratch directory; passes when it exits non-zero (with --status N: exactly
# N), its output contains every given pattern and none of the --not ones.
#   expect_failure.sh [--status N] [--not PATTERN]... PATTERN [PATTERN...] -- COMMAND [ARGS...]
set -u
patterns=()
absent=()
want=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --status) want=$2; shift 2 ;;
    --not) absent+=("$2"); shift 2 ;;
    *) patterns+=("$1"); shift ;;
  esac
done
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
for p in "${absent[@]+"${absent[@]}"}"; do
  if grep -q -- "$p" <<<"$out"; then echo "FAIL: output holds '$p'"; exit 1; fi
done
echo "PASS"
