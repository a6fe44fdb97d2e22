#!/bin/bash
# Runs two mpm_solver binaries on the same scenes and compares every output file (HDF5 datasets
# with h5diff, exactly; the run metadata attributes of the root excluded) and the energies CSV
# byte for byte. Proves that a change to the MPM step gives bit-identical results.
#
#   benchmarks/mpm/compare_bits.sh OLD/mpm_solver NEW/mpm_solver [workdir]
#
# Scenes: the colliding disks (linear, usf / usl / musl; bspline2 usl; 1 and 2 ranks), the Lame
# cylinder (bspline2 usl with loads and mirror planes; linear, gimp, bspline3 usl), the vibrating
# bar (gimp musl, bspline3 usf), and the disks in 3D (bspline2 usl). Exit status 1 on any difference.
set -u
old=$1; new=$2; work=${3:-$(mktemp -d)}
mkdir -p "$work"
here=$(cd "$(dirname "$0")/../.." && pwd)
mpirun="$here/scripts/mpirun"
fail=0; n=0
variant() {  # name base.yaml ranks sed-expressions...
  local name=$1 base=$2 ranks=$3; shift 3
  local yaml="$work/$name.yaml"
  sed "$@" "$here/configs/$base" > "$yaml"
  for side in old new; do
    local bin=$old; [ "$side" = new ] && bin=$new
    local out="$work/$side/$name"
    rm -rf "$out"; mkdir -p "$out"
    sed -i "s|^  directory: .*|  directory: $out|" "$yaml"
    if [ "$ranks" = 1 ]; then "$bin" "$yaml" > "$out.log" 2>&1; else "$mpirun" -np "$ranks" "$bin" "$yaml" > "$out.log" 2>&1; fi || { echo "$name: $side run failed (see $out.log)"; fail=1; }
  done
  local files=0 diffs=0
  for f in "$work/old/$name"/*; do
    local g="$work/new/$name/$(basename "$f")"
    case "$f" in
      */log.*|*_run.yaml) continue ;;  # the program log and the run record: paths and timings
    esac
    files=$((files + 1))
    case "$f" in
      *.h5) h5diff --exclude-attribute / "$f" "$g" > /dev/null 2>&1 || diffs=$((diffs + 1)) ;;
      *) cmp -s "$f" "$g" || diffs=$((diffs + 1)) ;;
    esac
  done
  n=$((n + 1))
  echo "$name: $files files, $diffs differ"
  [ "$diffs" = 0 ] && [ "$files" -gt 0 ] || fail=1
}
disks=mpm_colliding_disks.yaml; lame=mpm_lame_cylinder.yaml; bar=mpm_vibrating_bar.yaml
variant disks_linear_musl $disks 1 -e 's/^  end: 3.0/  end: 0.6/'
variant disks_linear_usl $disks 1 -e 's/^  end: 3.0/  end: 0.6/' -e 's/update: musl/update: usl/'
variant disks_linear_usf $disks 1 -e 's/^  end: 3.0/  end: 0.6/' -e 's/update: musl/update: usf/'
variant disks_bspline2_usl $disks 1 -e 's/^  end: 3.0/  end: 0.6/' -e 's/update: musl/update: usl/' -e 's/shape_function: linear/shape_function: bspline2/'
variant disks_linear_musl_2ranks $disks 2 -e 's/^  end: 3.0/  end: 0.6/'
variant disks_bspline2_3d $disks 1 -e 's/^  end: 3.0/  end: 0.2/' -e 's/dim: 2/dim: 3/' -e 's/lower: \[0.0, 0.0\]/lower: [0.0, 0.0, 0.0]/' \
  -e 's/upper: \[1.0, 1.0\]/upper: [1.0, 1.0, 0.5]/' -e 's/cells: \[40, 40\]/cells: [20, 20, 10]/' -e 's/center: \[0.25, 0.25\]/center: [0.25, 0.25, 0.25]/' \
  -e 's/center: \[0.75, 0.75\]/center: [0.75, 0.75, 0.25]/' -e 's/velocity: \[0.1, 0.1\]/velocity: [0.1, 0.1, 0.0]/' -e 's/velocity: \[-0.1, -0.1\]/velocity: [-0.1, -0.1, 0.0]/' \
  -e 's/  y+: noslip_wall/  y+: noslip_wall\n  z-: slip_wall\n  z+: slip_wall/' -e 's/update: musl/update: usl/' -e 's/shape_function: linear/shape_function: bspline2/'
variant lame_bspline2_usl $lame 1 -e 's/^  end: 4.0e-3/  end: 1.0e-3/'
variant lame_linear_usl $lame 1 -e 's/^  end: 4.0e-3/  end: 1.0e-3/' -e 's/shape_function: bspline2/shape_function: linear/'
variant lame_gimp_usl $lame 1 -e 's/^  end: 4.0e-3/  end: 1.0e-3/' -e 's/shape_function: bspline2/shape_function: gimp/'
variant lame_bspline3_usl $lame 1 -e 's/^  end: 4.0e-3/  end: 1.0e-3/' -e 's/shape_function: bspline2/shape_function: bspline3/'
variant bar_gimp_musl $bar 1 -e 's/^  end: 10.0/  end: 5.0/' -e 's/shape_function: .*/shape_function: gimp/' -e 's/update: .*/update: musl/'
variant bar_bspline3_usf $bar 1 -e 's/^  end: 10.0/  end: 5.0/' -e 's/shape_function: .*/shape_function: bspline3/' -e 's/update: .*/update: usf/'
echo "$n scenes compared in $work: $([ $fail = 0 ] && echo 'all bit-identical' || echo 'DIFFERENCES')"
exit $fail
