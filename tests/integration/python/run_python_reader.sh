#!/usr/bin/env bash
# Runs mpm_solver alone (tests/integration/restart/mpm_block.yaml: node fields, particle ids, a
# probe) and an MPMD `coupler run` of the tiny cylinder (solid and fluid series, cell fields, the
# coupling and conservation CSVs, a probe), then reads both through python/mpmice (test_reader.py),
# whose values are compared with h5dump's and the CSV text's.
#   run_python_reader.sh BUILD_DIR SOURCE_DIR
set -u
bin=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

sed 's|directory: out|directory: block|' "$src/tests/integration/restart/mpm_block.yaml" > "$work/block.yaml"
{ sed 's|directory: output|directory: cylinder|' "$src/tests/integration/restart/cylinder.yaml"
  printf '  probes:\n    - {name: inner, point: [0.5, 0.0]}\n    - {name: outer, point: [0.0, 1.0]}\n'; } > "$work/cylinder.yaml"
(cd "$work" && "$bin/mpm_solver/mpm_solver" block.yaml) > "$work/block.txt" 2>&1 ||
  { cat "$work/block.txt"; fail "mpm_solver failed"; }
(cd "$work" && "$bin/coupler/coupler" run cylinder.yaml) > "$work/cylinder.txt" 2>&1 ||
  { cat "$work/cylinder.txt"; fail "coupler run failed"; }

cd "$work" && "$src/scripts/python" "$src/tests/integration/python/test_reader.py" -v 2>&1 ||
  fail "test_reader.py failed"
echo "PASS: python reader"
