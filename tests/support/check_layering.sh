#!/usr/bin/env bash
# The layers of src/ (docs/architecture.md): core, mpm and ice include nothing from the coupler
# or the couplings; mpm and ice know nothing of each other; the coupler includes core only; the
# study (core + coupler) runs the programs and includes no solver.
#   check_layering.sh SRC_DIR
set -u
src=$1 status=0
check() {  # check DIR PATTERN WHAT
  local hits
  hits=$(grep -rnE "#include \"($2)/" "$src/$1" || true)
  if [ -n "$hits" ]; then echo "FAIL: $1 includes $3:"; echo "$hits"; status=1; fi
}
check core 'mpm|ice|coupler|couplings|study' 'a layer above it'
check mpm 'ice|coupler|couplings' 'ICE or the coupling'
check ice 'mpm|coupler|couplings' 'MPM or the coupling'
check coupler 'mpm|ice|couplings' 'a solver or a coupling'
check study 'mpm|ice|couplings' 'a solver or a coupling (it runs the programs)'
[ $status -eq 0 ] && echo "layering: ok"
exit $status
