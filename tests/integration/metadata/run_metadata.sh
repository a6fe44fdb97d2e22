#!/usr/bin/env bash
# Every HDF5 file every program writes describes its run (core/io/run_metadata.h), as the run
# record does: mpm_solver (2 ranks), ice_solver, mpmice, and the MPMD launch of `coupler run`
# (each side its own program, command line and place in the launch).
#   run_metadata.sh CHECKER MPIRUN BUILD_DIR SCENE
set -u
check=$1 mpirun=$2 bin=$3 scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
name=pressurized_cylinder
run() {  # run FOLDER COMMAND...
  local dir=$work/$1
  shift
  mkdir -p "$dir" && (cd "$dir" && "$@") > "$dir.log" 2>&1 || { cat "$dir.log"; fail "$* failed"; }
}
verify() {  # verify FOLDER SUFFIX PROGRAM LAYOUT
  local files=("$work/$1/output/${name}$2"_0*.h5)
  [ -e "${files[0]}" ] || fail "$1: no output files ${name}$2_*.h5"
  "$check" "$work/$1/output/${name}$2_run.yaml" "$3" "$4" "${files[@]}" || fail "$1: metadata differ"
}
run mpm "$mpirun" -np 2 "$bin/mpm_solver/mpm_solver" "$scene"
verify mpm "" mpm_solver "mpm_solver: 2 ranks"
run ice "$bin/ice_solver/ice_solver" "$scene"
verify ice "" ice_solver "ice_solver: 1 rank"
run mono "$bin/coupler/mpmice" "$scene"
verify mono "" mpmice "mpmice: 1 rank"
run mpmd "$bin/coupler/coupler" run --bin-dir "$bin" --mpm-ranks 2 "$scene"
verify mpmd _solid mpm_solver "mpm_solver: 2 ranks (world ranks 0-1 of a 3-rank launch)"
verify mpmd _fluid ice_solver "ice_solver: 1 rank (world rank 2 of a 3-rank launch)"
grep -q "command_line: \".*/mpm_solver/mpm_solver $scene\"" "$work/mpmd/output/${name}_solid_run.yaml" || fail "the solid's command line"
echo "PASS: run metadata in every output file"
