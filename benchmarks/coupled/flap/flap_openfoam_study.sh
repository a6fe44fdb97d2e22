#!/usr/bin/env bash
# The perpendicular flap with MPM + OpenFOAM: the runs and figures of docs/flap.md.
#
# Usage:  benchmarks/coupled/flap/flap_openfoam_study.sh [BUILD_DIR] [OUT_DIR]
#         (defaults: build, output/flap_openfoam_study; run from the repository root)
# Runs `coupler run` on configs/flap_openfoam.yaml and variants, one after the other:
#   explicit   explicit_serial, RBF (thin-plate) mapping, MPM dx 0.025   (the scene as it is)
#   implicit   implicit_serial, IQN-ILS, |d~ - d| <= 1e-4 |d~|
#   nearest    explicit, nearest_neighbor mapping
#   fine       explicit, MPM dx 0.0125
#   fluid_fine explicit, the fluid mesh refined twice in each direction (about 11,000 cells)
#   one_way    configs/flap_openfoam_oneway.yaml
#   fluid_alone  pimpleFoam alone around the rigid flap (no adapter, no mesh motion solve of
#              consequence): the peer's own cost of the same 5 s, for the wall-time comparison
# then writes OUT_DIR/summary.csv (first peak, its time, period, mean, the one-way static tip,
# mean iterations per window, wall time) with flap_tip, and OUT_DIR/tip.png (gnuplot).
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
out="${2:-output/flap_openfoam_study}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
mkdir -p "$out"; out="$(cd "$out" && pwd)"
case_dir="$root/configs/flap/fluid-openfoam"

variant() {  # name, sed expressions...
  local name="$1"; shift
  sed -e "s#case: flap/fluid-openfoam#case: $case_dir#" -e "s#directory: output/flap_openfoam#directory: $out/$name#" \
      -e "s/^scene: flap_openfoam/scene: flap_$name/" "$@" "$root/configs/flap_openfoam.yaml" > "$out/$name.yaml"
}
variant explicit -e 's/x/x/'
variant implicit -e 's/schedule: explicit_serial/schedule: implicit_serial\n  max_iterations: 30\n  acceleration: {type: iqn_ils, relaxation: 0.5}\n  convergence: [{field: interface_displacement, type: relative, limit: 1.0e-4, strict: true}]/'
variant nearest -e 's/mapping: rbf/mapping: nearest_neighbor/'
variant fine -e 's/spacing: \[0.025, 0.025\]/spacing: [0.0125, 0.0125]/'
rm -rf "$out/fluid-openfoam-fine"; cp -r "$case_dir" "$out/fluid-openfoam-fine"
sed -i -e 's/^nFlap .*/nFlap 6;/' -e 's/^nHeight .*/nHeight 30;/' -e 's/^nFar .*/nFar 60;/' \
    "$out/fluid-openfoam-fine/system/blockMeshDict"
variant fluid_fine -e "s#case: $case_dir#case: $out/fluid-openfoam-fine#"
sed -e "s#case: flap/fluid-openfoam#case: $case_dir#" -e "s#directory: output/flap_openfoam_oneway#directory: $out/one_way#" \
    -e "s/^scene: flap_openfoam_oneway/scene: flap_one_way/" "$root/configs/flap_openfoam_oneway.yaml" > "$out/one_way.yaml"

[ -f "$out/summary.csv" ] && [ -n "${VARIANTS:-}" ] || \
echo "variant,first_peak_m,first_peak_time_s,period_s,period_maxima_s,mean_m,max_m,final_m,iterations_per_window,wall_s" > "$out/summary.csv"
for v in ${VARIANTS-explicit implicit nearest fine fluid_fine one_way}; do
  [ "$v" = fluid_alone ] && continue
  echo "flap_openfoam_study: $v" >&2
  t0=$(date +%s.%N)
  "$build/coupler/coupler" run "$out/$v.yaml" --bin-dir "$build" > "$out/$v.log" 2>&1
  t1=$(date +%s.%N)
  probes="$out/$v/flap_${v}_probes.csv"
  m=$("$build/benchmarks/coupled/flap/flap_tip" "$probes" | tail -n1)
  iters=$(awk -F, 'NR > 1 { s += $4; n++ } END { printf "%.3f", s / n }' "$out/$v/flap_${v}_coupling.csv")
  ext=$(awk -F, 'NR > 1 { if ($5 > mx || NR == 2) mx = $5; last = $5 } END { printf "%.5f,%.5f", mx, last }' "$probes")
  echo "$v,$(echo "$m" | cut -d, -f2,3,4,5,8),$ext,$iters,$(echo "$t1 - $t0" | bc)" >> "$out/summary.csv"
done
if [ -z "${VARIANTS:-}" ] || [[ " $VARIANTS " == *" fluid_alone "* ]]; then
  echo "flap_openfoam_study: fluid_alone" >&2
  rm -rf "$out/fluid_alone"; cp -r "$case_dir" "$out/fluid_alone"
  export WM_PROJECT_DIR=/usr/share/openfoam
  blockMesh -case "$out/fluid_alone" > "$out/fluid_alone/log.blockMesh" 2>&1
  t0=$(date +%s.%N)
  pimpleFoam -case "$out/fluid_alone" > "$out/fluid_alone/log.pimpleFoam" 2>&1
  t1=$(date +%s.%N)
  echo "fluid_alone,,,,,,,,,$(echo "$t1 - $t0" | bc)" >> "$out/summary.csv"
fi
LABEL="two-way explicit" bash "$root/benchmarks/coupled/flap/plot_tip.sh" "$out/explicit/flap_explicit_probes.csv" \
  "$out/implicit/flap_implicit_probes.csv" "two-way implicit (IQN-ILS)" \
  "$out/one_way/flap_one_way_probes.csv" "one-way (relaxation after the fluid's 5 s)" "$out/tip.png"
cat "$out/summary.csv"
