#!/usr/bin/env bash
# A killed mpm_solver loses nothing it reported (issue 11): SIGKILL mid-run (no chance to flush or
# close anything), then the energies CSV holds its header and a complete row for every output
# step written under its final name (the CSV goes through the flushing writer, row by row), and
# every HDF5 step under its final name is readable (a step is written as <name>.part and renamed when
# complete; h5dump -H when installed).
#   killed_run_keeps_its_rows.sh MPM_SOLVER SCENE
set -u
solver=$1 scene=$2
work=$(mktemp -d)
trap 'pkill -KILL -f -- "$work/" 2>/dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
# Runs for ever (time.end far away), an output every 0.01 s of simulated time.
sed -e 's/^  end: .*/  end: 1.0e3/' "$scene" > "$work/long.yaml"
"$solver" "$work/long.yaml" > log 2>&1 &  # a singleton MPI process
pid=$!
csv=out/mpm_output_block_energies.csv
rows() { [ -f "$csv" ] && tail -n +2 "$csv" | grep -c . || echo 0; }
for _ in $(seq 600); do [ "$(rows)" -ge 4 ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.1; done
[ "$(rows)" -ge 4 ] || { cat log; fail "no 4 energy rows within 60 s while the run went on (unflushed CSV?)"; }
kill -KILL $pid
wait $pid; status=$?
echo "killed: exit status $status"
[ $status -eq 137 ] || fail "expected the run to be killed (137), got $status"
head -1 "$csv" | grep -qx "step,time,kinetic,strain,total" || fail "the header: $(head -1 "$csv")"
bad=$(tail -n +2 "$csv" | awk -F, 'NF != 5' | head -1)
[ -z "$bad" ] || fail "an incomplete row: '$bad'"
[ -z "$(tail -c 1 "$csv")" ] || fail "the last row does not end with a newline"
steps=$(ls out/mpm_output_block_[0-9]*.h5 2>/dev/null | wc -l)
n=$(rows)
echo "energy rows: $n, HDF5 steps: $steps"
[ "$steps" -ge 1 ] || fail "no HDF5 step under its final name"
[ "$n" -ge "$steps" ] || fail "$steps HDF5 steps but the CSV has only $n rows"
if command -v h5dump > /dev/null; then
  for f in out/*.h5; do h5dump -H "$f" > /dev/null 2>&1 || fail "$f is under its final name but unreadable"; done
fi
echo PASS
