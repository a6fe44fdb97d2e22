#!/usr/bin/env bash
# A restart equals the uninterrupted run, bit for bit: runs a scene to its end (with
# output.checkpoint_interval) in WORK/full; copies that output to WORK/resumed as a run killed
# after its middle checkpoint k would leave it (the step files after k removed, the CSVs and
# the later checkpoints left as they were: rows and files a killed run wrote after k); resumes
# it with --restart (MODE file: the checkpoint file of step k; MODE dir: the output directory,
# its later checkpoints removed first, so the latest is k; in an MPMD launch BASE is one
# program's output base, `<scene>_solid`); then compares every file of the two
# output directories: each HDF5 file (output steps and checkpoints) with h5diff, exactly (every
# dataset, every value, every attribute), the CSVs and the XDMF index byte for byte (a CSV's
# wall-time columns, compute_s and exchange_s of the coupling log and, in an MPMD launch, the
# peer's peer_compute_s and peer_exchange_s, are left out: they differ between any two runs).
#   run_restart.sh MODE WORK BASE -- COMMAND...   (COMMAND runs the scene; --restart is inserted
#                                                 before its last argument, the scene file)
set -u
mode=$1 work=$2 base=$3
shift 4
cmd=("$@")
scene=${cmd[-1]}
unset 'cmd[-1]'
rm -rf "$work" && mkdir -p "$work/full" "$work/resumed"
fail() { echo "FAIL: $*"; exit 1; }
# A CSV without its wall-time columns (compute_s, exchange_s, peer_compute_s, peer_exchange_s).
untimed() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) skip[i] = ($i ~ /^(peer_)?(compute|exchange)_s$/) }
           { line = ""; for (i = 1; i <= NF; i++) if (!skip[i]) line = line (line == "" ? "" : ",") $i; print line }' "$1"
}
(cd "$work/full" && "${cmd[@]}" "$scene") > "$work/full.log" 2>&1 || { cat "$work/full.log"; fail "the full run failed"; }
out=$(cd "$work/full" && ls -d */ | head -1)
out=${out%/}
mapfile -t cks < <(cd "$work/full/$out" && ls "${base}"_checkpoint_*.h5 2>/dev/null | sort)
[ "${#cks[@]}" -ge 3 ] || fail "the full run wrote ${#cks[@]} checkpoints ${base}_checkpoint_*.h5, expected at least 3"
ck=${cks[$(( ${#cks[@]} / 2 - 1 ))]}
k=$(echo "$ck" | sed -E 's/.*_checkpoint_0*([0-9]+)\.h5/\1/')
cp -r "$work/full/$out" "$work/resumed/$out"
removed=0
for f in "$work/resumed/$out"/*_[0-9][0-9][0-9][0-9][0-9][0-9].h5; do
  case "$f" in *_checkpoint_*) continue ;; esac
  s=$(basename "$f" .h5 | sed -E 's/.*_0*([0-9]+)$/\1/')
  if [ "$s" -gt "$k" ]; then rm "$f"; removed=$((removed + 1)); fi
done
[ "$removed" -gt 0 ] || fail "no output step after checkpoint $ck to recompute"
if [ "$mode" = dir ]; then  # every program's checkpoints after step k (an MPMD launch has two)
  for c in "$work/resumed/$out"/*_checkpoint_*.h5; do
    s=$(basename "$c" .h5 | sed -E 's/.*_0*([0-9]+)$/\1/')
    if [ "$s" -gt "$k" ]; then rm "$c"; fi
  done
  where=$out
else
  where=$out/$ck
fi
echo "resuming from $where (step $k; $removed output steps to recompute)"
(cd "$work/resumed" && "${cmd[@]}" --restart "$where" "$scene") > "$work/resumed.log" 2>&1 || {
  cat "$work/resumed.log"; fail "the resumed run failed"; }
grep -q "^restart: " "$work/resumed.log" || { cat "$work/resumed.log"; fail "the resumed run did not report its checkpoint"; }
# The run record and the program logs describe each run (its command line, its times); a resumed
# log is the copied one with the resumed run's section appended.
a=$(cd "$work/full/$out" && ls | grep -v -e '_run.yaml$' -e '^log\.' | sort) b=$(cd "$work/resumed/$out" && ls | grep -v -e '_run.yaml$' -e '^log\.' | sort)
[ "$a" = "$b" ] || fail "the output directories hold different files: full [$a] resumed [$b]"
n=0
for f in $a; do
  case "$f" in
    # (a checkpoint's byte length of the coupling log depends on those wall-time columns; the root
    # attributes are the run metadata: the command line and start time of each run)
    *.h5) h5diff --exclude-attribute / --exclude-path /data/run.coupling_csv "$work/full/$out/$f" "$work/resumed/$out/$f" > "$work/diff.txt" 2>&1 || {
            head -40 "$work/diff.txt"; fail "$f differs"; } ;;
    *.csv) cmp <(untimed "$work/full/$out/$f") <(untimed "$work/resumed/$out/$f") || fail "$f differs" ;;
    *) cmp "$work/full/$out/$f" "$work/resumed/$out/$f" || fail "$f differs" ;;
  esac
  n=$((n + 1))
done
grep -q "status: completed" "$work/resumed/$out/"*_run.yaml || fail "the run record of the resumed run is not completed"
echo "OK: $n files equal (the run resumed from $where)"
