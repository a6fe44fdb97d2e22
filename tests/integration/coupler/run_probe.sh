#!/usr/bin/env bash
# Runs one MPMD probe launch and checks its exit status and output.
#   run_probe.sh MPIRUN PROBE NA NB MESH_A MESH_B MODE EXPECT_STATUS(0|nonzero) PATTERN
set -u
mpirun=$1 probe=$2 na=$3 nb=$4 mesh_a=$5 mesh_b=$6 mode=$7 expect=$8 pattern=$9
out=$("$mpirun" -np "$na" "$probe" a "$mesh_a" ok : -np "$nb" "$probe" b "$mesh_b" "$mode" 2>&1)
status=$?
echo "$out"
echo "exit status: $status"
if [ "$expect" = 0 ] && [ $status -ne 0 ]; then echo "FAIL: expected success"; exit 1; fi
if [ "$expect" != 0 ] && [ $status -eq 0 ]; then echo "FAIL: expected a non-zero exit"; exit 1; fi
if ! grep -q -- "$pattern" <<<"$out"; then echo "FAIL: output lacks '$pattern'"; exit 1; fi
echo "PASS"
