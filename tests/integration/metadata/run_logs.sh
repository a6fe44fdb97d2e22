#!/usr/bin/env bash
# Each program keeps what it prints in <output>/log.<program> (core/io/log_file.h), appended run
# after run; an MPMD `coupler run` shows the progress and one labelled summary per side instead of
# the two programs' closing lines (coupler/cli/launch_output.h).
#   run_logs.sh BUILD_DIR SCENE
set -u
bin=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
has() { grep -qF -- "$2" "$1" || { echo "--- $1:"; cat "$1"; fail "$1 lacks '$2'"; }; }
banner="scene pressurized_cylinder ("

# Alone: mpm_solver, ice_solver, mpmice; mpmice's folder holds a log of an earlier run, kept.
for prog in mpm_solver/mpm_solver ice_solver/ice_solver coupler/mpmice; do
  name=$(basename "$prog") dir=$work/$name
  mkdir -p "$dir/output"
  [ "$name" = mpmice ] && echo "an earlier run's line" > "$dir/output/log.mpmice"
  (cd "$dir" && "$bin/$prog" "$scene") > "$dir/terminal.txt" 2>&1 || { cat "$dir/terminal.txt"; fail "$name failed"; }
  log=$dir/output/log.$name
  [ -f "$log" ] || fail "$name wrote no $log"
  has "$log" "==== $name 0."
  has "$log" "done: 3 steps"
  has "$log" "scene pressurized_cylinder"   # the progress banner
  # The log holds what the terminal got, line for line, after its header.
  diff <(grep -v -e "^==== $name " -e "^an earlier run" "$log") "$dir/terminal.txt" > /dev/null ||
    { diff <(grep -v -e "^==== $name " "$log") "$dir/terminal.txt"; fail "$log differs from the terminal"; }
done
has "$work/mpmice/output/log.mpmice" "$banner"
[ "$(head -n1 "$work/mpmice/output/log.mpmice")" = "an earlier run's line" ] || fail "the earlier log was not kept"

# MPMD, twice into one folder: each program its own log, the second run appended.
dir=$work/mpmd
mkdir -p "$dir"
for run in 1 2; do
  (cd "$dir" && "$bin/coupler/coupler" run --bin-dir "$bin" "$scene") > "$dir/terminal$run.txt" 2>&1 ||
    { cat "$dir/terminal$run.txt"; fail "coupler run $run failed"; }
done
t=$dir/terminal2.txt
cat "$t"
has "$t" "$banner"
has "$t" "coupler: mpm_solver (1 rank): 3 steps to t = "
has "$t" "coupler: ice_solver (1 rank): 3 steps to t = "
grep -E -q "^coupler: ice_solver \(1 rank\): 3 steps to t = [0-9.e+-]+ s, compute [0-9.e+-]+ s, wait [0-9.e+-]+ s, 3 coupling iterations \(1 per step\), wall" "$t" ||
  fail "the fluid's summary lacks steps, compute and wait time or iterations"
if grep -q -e "^done:" -e "^coupling (" "$t"; then fail "the programs' own closing lines reached the terminal"; fi
[ "$(grep -c "^scene pressurized_cylinder (" "$t")" -eq 1 ] || fail "not one progress banner"
# One coupled progress line (coupler/cli/launch_output.h) for the last step at least; the solid's
# own progress lines only in its log.
grep -E -q "^coupler: step 3  t = [0-9.e+-]+ / [0-9.e+-]+ s \([0-9.]+%\)  ETA [0-9.e+-]+ s  coupling iterations 1 \(1 per step\)  dt set by (the solid side|the fluid side|time.end|time.dt_max)$" "$t" ||
  fail "no coupled progress line for the last step (with what set the step)"
if grep -q "^step " "$t"; then fail "a program's own progress line reached the terminal"; fi
grep -q "^step 3  t = .*  iters=1  iters_total=3.*  dt_by=" "$dir/output/log.mpm_solver" || fail "the solid's log lacks its progress line"
for side in mpm_solver ice_solver; do
  log=$dir/output/log.$side
  [ "$(grep -c "^==== $side 0." "$log")" -eq 2 ] || { cat "$log"; fail "$log does not hold both runs"; }
  [ "$(grep -c "^done: 3 steps" "$log")" -eq 2 ] || fail "$log lacks its closing lines"
  has "$log" "coupling ($side, coupled to "
done
has "$dir/output/log.mpm_solver" "$banner"
echo "PASS: log files and labelled summaries"
