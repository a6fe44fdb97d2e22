#!/usr/bin/env bash
# A restart is refused, with a clear message and a non-zero exit, when the checkpoint is of
# another scene (hash mismatch), another rank count, or when PATH holds no checkpoint.
#   restart_refused.sh WORK MPIRUN PROGRAM SCENE BASE SED
# SED (a sed expression) changes a material of the scene (what the scene hash covers).
set -u
work=$1 mpirun=$2 program=$3 scene=$4 base=$5 change=$6
rm -rf "$work" && mkdir -p "$work/empty" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$mpirun" -np 1 "$program" "$scene" > run.log 2>&1 || { cat run.log; fail "the run failed"; }
ck=$(ls */"${base}"_checkpoint_*.h5 | head -1)  # the scene's output directory
[ -n "$ck" ] || fail "no checkpoint written"
# expect PATTERN... -- COMMAND...: non-zero exit, every pattern in the output.
expect() {
  local patterns=()
  while [ "$1" != "--" ]; do patterns+=("$1"); shift; done
  shift
  local out status
  out=$("$@" 2>&1)
  status=$?
  echo "$out" | tail -5
  [ $status -ne 0 ] || fail "expected a non-zero exit from: $*"
  for p in "${patterns[@]}"; do grep -qF -- "$p" <<<"$out" || fail "output lacks '$p'"; done
}
expect "written by 1 ranks, this run has 2" "$ck" -- "$mpirun" -np 2 "$program" --restart "$ck" "$scene"
sed -e "$change" "$scene" > other.yaml
cmp -s other.yaml "$scene" && fail "the test could not change the scene with '$change'"
expect "the checkpoint is of another scene" "$ck" -- "$mpirun" -np 1 "$program" --restart "$ck" other.yaml
expect "holds no checkpoint" "empty" -- "$mpirun" -np 1 "$program" --restart empty "$scene"
expect "no checkpoint file" -- "$mpirun" -np 1 "$program" --restart "$(dirname "$ck")/${base}_checkpoint_999999.h5" "$scene"
echo "PASS"
