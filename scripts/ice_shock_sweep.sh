#!/usr/bin/env bash
# The full ICE shock sweep (docs/ice.md "Shocks"): Sod, Toro's tests 1-5 and water against air at
# the real density ratio (1.2 kg/m^3) at 100, 200, 400, 800 and 1600 cells, for every ICE setting
# (advection order x limiter x pressure solver), default face pressure (riemann) first, then the
# average for comparison, then the semi-implicit pressure with the Crank-Nicolson time weight
# (ice.semi_implicit_theta 0.5) and the riemann face pressure. Prints L1(rho), the fitted order,
# the overshoot behind each shock and the stationary contact's velocity per run, or STOPPED with
# the run's error.
#   bash scripts/ice_shock_sweep.sh [BUILD_DIR] [CELLS]      (about 4 min on an idle core)
set -euo pipefail
build=${1:-build}
cells=${2:-100,200,400,800,1600}
exe="$build/tests/verification/ice/ice_shock_sweep"
[ -x "$exe" ] || { echo "ice_shock_sweep: build the target ice_shock_sweep first ($exe)" >&2; exit 2; }
for fp in riemann average; do
  for adv in second_order first_order; do
    for lim in van_leer minmod superbee; do
      [ "$adv" = first_order ] && [ "$lim" != van_leer ] && continue  # no limiter in first order
      for pr in explicit semi_implicit; do
        echo "### face_pressure $fp"
        "$exe" --advection "$adv" --limiter "$lim" --pressure "$pr" --face-pressure "$fp" --cells "$cells"
      done
    done
  done
done
for adv in second_order first_order; do
  for lim in van_leer minmod superbee; do
    [ "$adv" = first_order ] && [ "$lim" != van_leer ] && continue
    echo "### face_pressure riemann, semi_implicit_theta 0.5"
    "$exe" --advection "$adv" --limiter "$lim" --pressure semi_implicit --theta 0.5 --cells "$cells"
  done
done
