#!/usr/bin/env bash
# The study tool on the tiny cylinder (a few steps each):
#  1. three points (mpm.shape_function linear, bspline2, bspline3) by mpmice: exit 0, the CSV has a
#     header and three rows in order, every error finite and > 0, every status ok, every wall > 0,
#     steps > 0, iterations per step 1 (monolithic), peak RSS > 0; a run folder per point with its
#     scene, log and result; the Pareto plot when gnuplot is there;
#  2. the same command again: refused (exit 2, naming the folder), nothing changed;
#  3. --resume: every point skipped, the same CSV rows;
#  4. a point stopped by its time limit: status timeout, exit 3, the CSV still written;
#  5. two points through `coupler run` (MPMD, explicit_parallel on 1 + 1 ranks): ok, finite errors;
#  6. SIGTERM to the study: forwarded to the running point, exit 143, no result, nothing left;
#  7. the probe_curve reference: the flap (dx 0.1, 0.05 s) with each solid transport against the
#     shipped MPM + OpenFOAM tip curve: ok, distinct errors, each equal to rms_diff / rms_first of
#     benchmarks/coupled/flap/curve_difference.sh on the point's probes file (an independent awk).
#   run_study.sh BUILD_DIR TINY_CYLINDER_YAML SOURCE_DIR
set -u
bin=$1 scene=$2 src=$3 status=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
study=$bin/study/study
fail() { echo "FAIL: $*"; status=1; }
cd "$work" || exit 1

cat >three.yaml <<EOS
study: three
scene: $scene
program: mpmice
reference: lame_cylinder
time_limit: 60
set: {time.end: 5.0e-5, output.interval: 0}
axes:
  mpm.shape_function: [linear, bspline2, bspline3]
EOS
# 1.
"$study" three.yaml --out out >run1.txt 2>&1
rc=$?
cat run1.txt
[ $rc -eq 0 ] || fail "the study exited $rc"
csv=out/three.csv
[ -f "$csv" ] || { fail "no $csv"; exit 1; }
cat "$csv"
[ "$(head -1 "$csv")" = "point,mpm.shape_function,error,wall_s,cpu_s,runs,steps,iterations_per_step,peak_rss_mb,status,exit_code,run,note" ] ||
  fail "CSV header: $(head -1 "$csv")"
[ "$(tail -n +2 "$csv" | wc -l)" -eq 3 ] || fail "expected 3 rows"
[ "$(tail -n +2 "$csv" | cut -d, -f2 | paste -sd' ')" = "linear bspline2 bspline3" ] || fail "rows out of order"
awk -F, 'NR > 1 {
  if ($3 == "nan" || $3 == "inf" || !($3 + 0 > 0) || !($3 + 0 < 1e3)) { print "FAIL: row " NR - 1 ": error " $3; bad = 1 }
  if ($10 != "ok") { print "FAIL: row " NR - 1 ": status " $10; bad = 1 }
  if (!($4 + 0 > 0)) { print "FAIL: row " NR - 1 ": wall " $4; bad = 1 }
  if (!($5 + 0 > 0)) { print "FAIL: row " NR - 1 ": CPU " $5; bad = 1 }
  if (!($7 + 0 > 0)) { print "FAIL: row " NR - 1 ": steps " $7; bad = 1 }
  if ($8 != "1") { print "FAIL: row " NR - 1 ": iterations per step " $8; bad = 1 }
  if (!($9 + 0 > 0)) { print "FAIL: row " NR - 1 ": peak RSS " $9; bad = 1 }
  if ($11 != "0") { print "FAIL: row " NR - 1 ": exit " $11; bad = 1 }
} END { exit bad }' "$csv" || status=1
for d in 001_linear 002_bspline2 003_bspline3; do
  for f in scene.yaml run.log result.yaml command.txt pressurized_cylinder_run.yaml; do
    [ -f "out/$d/$f" ] || fail "no out/$d/$f"
  done
done
if command -v gnuplot >/dev/null; then
  [ -s out/three_pareto.png ] || fail "gnuplot is installed but no out/three_pareto.png"
fi
# The errors differ between shape functions (the points really ran their own settings).
[ "$(tail -n +2 "$csv" | cut -d, -f3 | sort -u | wc -l)" -eq 3 ] || fail "the three errors are not distinct"

# 2. An existing study folder is refused and left alone.
sum=$(cat out/three.csv out/*/result.yaml | md5sum)
before=$(cut -d, -f1-3,10 out/three.csv)
"$study" three.yaml --out out >run2.txt 2>&1
rc=$?
cat run2.txt
[ $rc -eq 2 ] || fail "an existing study folder: exit $rc, expected 2"
grep -q "the study folder $work/out exists and is not empty" run2.txt || fail "the refusal does not name the folder"
[ "$(cat out/three.csv out/*/result.yaml | md5sum)" = "$sum" ] || fail "the refused run changed the folder"
# A folder the tool did not make is refused even with --resume.
mkdir other && echo keep >other/notes.txt
"$study" three.yaml --out other --resume >run2b.txt 2>&1
rc=$?
[ $rc -eq 2 ] || fail "--resume into a foreign folder: exit $rc, expected 2"
grep -q "not a folder this tool made" run2b.txt || fail "the foreign-folder refusal: $(cat run2b.txt)"
[ "$(cat other/notes.txt)" = keep ] && [ "$(ls other | wc -l)" -eq 1 ] || fail "the foreign folder was touched"

# 3. --resume skips finished points.
"$study" three.yaml --out out --resume >run3.txt 2>&1
rc=$?
cat run3.txt
[ $rc -eq 0 ] || fail "--resume exited $rc"
[ "$(grep -c 'finished before, skipped' run3.txt)" -eq 3 ] || fail "--resume did not skip the three points"
[ "$(cut -d, -f1-3,10 out/three.csv)" = "$before" ] || fail "--resume changed the rows"

# 4. A point stopped by its time limit.
cat >slow.yaml <<EOS
study: slow
scene: $scene
reference: lame_cylinder
time_limit: 1
set: {time.end: 10.0, output.interval: 0}
points:
  - {mesh.spacing: 0.025}
EOS
"$study" slow.yaml --out slow >run4.txt 2>&1
rc=$?
cat run4.txt
[ $rc -eq 3 ] || fail "a timed-out point: exit $rc, expected 3"
[ "$(tail -n +2 slow/slow.csv | cut -d, -f10)" = timeout ] || fail "status of the timed-out point: $(cat slow/slow.csv)"
[ "$(tail -n +2 slow/slow.csv | cut -d, -f3)" = nan ] || fail "a timed-out point has an error"

# 5. The MPMD program.
cat >mpmd.yaml <<EOS
study: mpmd
scene: $scene
program: coupler_run
reference: lame_cylinder
time_limit: 90
set: {time.end: 5.0e-5, output.interval: 0, coupling.schedule: explicit_parallel}
points:
  - {mpm.shape_function: linear}
  - {mpm.shape_function: bspline2}
EOS
"$study" mpmd.yaml --out mpmd >run5.txt 2>&1
rc=$?
cat run5.txt
[ $rc -eq 0 ] || fail "the MPMD study exited $rc"
awk -F, 'NR > 1 && ($10 != "ok" || $3 == "nan" || !($3 + 0 > 0) || !($5 + 0 > 0)) { print "FAIL: MPMD row " NR - 1 ": " $0; bad = 1 }
         END { exit bad || NR != 3 }' mpmd/mpmd.csv || { fail "MPMD CSV"; cat mpmd/mpmd.csv; }
[ -f mpmd/001_linear/pressurized_cylinder_solid_run.yaml ] || fail "the MPMD point left no solid run record"

# 6. SIGTERM to the study reaches the running point: the study ends 128 + 15 without a result for
#    it, and no process of the point is left.
cat >stop.yaml <<EOS
study: stop
scene: $scene
reference: lame_cylinder
time_limit: 120
set: {time.end: 10.0, output.interval: 0}
points:
  - {mesh.spacing: 0.05}
EOS
"$study" stop.yaml --out stop >run6.txt 2>&1 &
spid=$!
for _ in $(seq 100); do [ -s stop/001_0.05/run.log ] && break; sleep 0.1; done
kill -TERM $spid
wait $spid
rc=$?
cat run6.txt
[ $rc -eq 143 ] || fail "a stopped study: exit $rc, expected 143"
grep -q "stopped by SIGTERM during point 1" run6.txt || fail "the stop is not reported"
[ ! -e stop/001_0.05/result.yaml ] || fail "a stopped point has a result"
for _ in $(seq 50); do pgrep -f "$work/stop/001_0.05/scene.yaml" >/dev/null || break; sleep 0.1; done
pgrep -af "$work/stop/001_0.05/scene.yaml" && fail "the stopped point's program is still running"

# 7. A probe's record against a reference curve.
cat >curve.yaml <<EOS
study: curve
scene: $src/configs/flap_mpmice.yaml
reference: probe_curve
reference_curve: $src/configs/studies/flap_openfoam_tip.csv
reference_column: tip_ux
time_limit: 90
set: {mesh.spacing: 0.1, time.end: 0.05, output.interval: 0}
points:
  - {coupling.solid_transport: mpm}
  - {coupling.solid_transport: ice}
EOS
"$study" curve.yaml --out curve >run7.txt 2>&1
rc=$?
cat run7.txt
[ $rc -eq 0 ] || fail "the probe_curve study exited $rc"
cat curve/curve.csv
awk -F, 'NR > 1 && ($10 != "ok" || $3 == "nan" || !($3 + 0 > 0)) { print "FAIL: probe_curve row " NR - 1 ": " $0; bad = 1 }
         END { exit bad || NR != 3 }' curve/curve.csv || fail "probe_curve CSV"
[ "$(tail -n +2 curve/curve.csv | cut -d, -f3 | sort -u | wc -l)" -eq 2 ] || fail "the two transports gave one error"
for p in 001_mpm 002_ice; do
  err=$(awk -F, -v p="$p" 'NR > 1 && $12 == p { print $3 }' curve/curve.csv)
  ref=$(bash "$src/benchmarks/coupled/flap/curve_difference.sh" "$src/configs/studies/flap_openfoam_tip.csv" \
          "curve/$p/flap_mpmice_probes.csv" | awk -F, 'NR == 2 { printf "%.10g", $5 / $6 }')
  echo "probe_curve $p: study $err, curve_difference.sh $ref"
  awk -v a="$err" -v b="$ref" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(b > 0 && d <= 1e-6 * b) }' ||
    fail "probe_curve $p: the study's error $err is not curve_difference.sh's $ref"
done

[ $status -eq 0 ] && echo "study_tiny_cylinder: ok"
exit $status
