#!/usr/bin/env bash
# Runs mpm_solver on a scene through the launch helper in a fresh directory, then the checker.
#   run_mpm_output.sh MPIRUN NP MPM_SOLVER SCENE WORKDIR CHECKER
set -eu
mpirun=$1 np=$2 solver=$3 scene=$4 work=$5 checker=$6
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$mpirun" -np "$np" "$solver" "$scene"
"$checker" out "$np"
