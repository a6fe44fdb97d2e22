#!/usr/bin/env bash
# The two programs of an MPMD launch resuming different steps both stop, naming the two steps:
# a full run with checkpoints, then mpm_solver resumes its first checkpoint and ice_solver the
# latest one of the directory.
#   restart_mpmd_mismatch.sh WORK MPIRUN BIN_DIR SCENE BASE
set -u
work=$1 mpirun=$2 bin=$3 scene=$4 base=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$mpirun" -np 1 "$bin/mpm_solver/mpm_solver" "$scene" : -np 1 "$bin/ice_solver/ice_solver" "$scene" > run.log 2>&1 || {
  cat run.log; fail "the run failed"; }
first=$(ls output/"${base}"_solid_checkpoint_*.h5 | sort | head -1)
last=$(ls output/"${base}"_fluid_checkpoint_*.h5 | sort | tail -1)
s1=$(echo "$first" | sed -E 's/.*_0*([0-9]+)\.h5/\1/') s2=$(echo "$last" | sed -E 's/.*_0*([0-9]+)\.h5/\1/')
[ "$s1" != "$s2" ] || fail "the run wrote one checkpoint only"
out=$(timeout 60 "$mpirun" -np 1 "$bin/mpm_solver/mpm_solver" --restart "$first" "$scene" : \
      -np 1 "$bin/ice_solver/ice_solver" --restart output "$scene" 2>&1)
status=$?
echo "$out" | grep -v '^\[' | tail -8
[ $status -ne 0 ] || fail "expected a non-zero exit"
[ $status -ne 124 ] || fail "the launch hung"
grep -qF "this program resumes step $s1, the peer program step $s2" <<<"$out" ||
  grep -qF "this program resumes step $s2, the peer program step $s1" <<<"$out" || fail "the message does not name both steps"
echo "PASS"
