#!/usr/bin/env bash
# Runs mpmice on the tiny cylinder in a scratch folder and checks its XDMF index with Debian's
# ParaView (pvpython under xvfb-run, check_xdmf.py). Installs paraview and xvfb when missing and
# root with apt-get is available; otherwise skips (exit 77) saying why.
#   run_paraview_check.sh MPMICE_BINARY SCENE
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
mpmice="$(realpath "$1")"
scene="$(realpath "$2")"
if ! command -v pvpython >/dev/null 2>&1 || ! command -v xvfb-run >/dev/null 2>&1; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "paraview check: installing paraview and xvfb (Debian packages, a few minutes)"
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y -qq paraview python3-paraview xvfb >/dev/null 2>&1 ||
      { apt-get update -qq && apt-get install -y -qq paraview python3-paraview xvfb >/dev/null; } ||
      { echo "paraview check: SKIPPED: apt-get install paraview python3-paraview xvfb failed"; exit 77; }
  else
    echo "paraview check: SKIPPED: pvpython/xvfb-run absent and cannot install them (not root or no apt-get);"
    echo "  install with: apt-get install -y paraview xvfb"
    exit 77
  fi
fi
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
"$mpmice" "$scene" >run.log 2>&1 || { cat run.log; exit 1; }
xmf="$(ls "$scratch"/output/*.xmf)"
xvfb-run -a pvpython "$here/check_xdmf.py" "$xmf" 2>&1 | grep -v -e "^$" -e "^HDF5-DIAG" -e "^ *#[0-9]" -e "major:" -e "minor:"
exit "${PIPESTATUS[0]}"
