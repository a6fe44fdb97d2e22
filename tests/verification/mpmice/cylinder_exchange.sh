#!/usr/bin/env bash
# The seed cylinder at one momentum exchange K (issue 12): runs SCENE with ice.exchange.momentum = K
# in a scratch directory and passes when
#   done:  the run ends 0 with "done: N steps, t = <the scene's end>" and N <= MAX_STEPS, and, with
#          --leak-below X, cylinder_lame's gas leak (the fraction of the gas inside r_i that left it)
#          is below X;
#   stop:  the run ends non-zero, its output holds every PATTERN, and its error line names a step
#          N <= MAX_STEPS ("(step N)"): it stopped within the bound, not after a spin.
#   cylinder_exchange.sh MPMICE CYLINDER_LAME SCENE K MAX_STEPS done [--leak-below X]
#   cylinder_exchange.sh MPMICE CYLINDER_LAME SCENE K MAX_STEPS stop PATTERN [PATTERN...]
set -u
mpmice=$1 lame=$2 scene=$3 K=$4 max=$5 want=$6
shift 6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -q '^  exchange: {momentum: 1.0e15' "$scene" || { echo "FAIL: $scene lacks 'exchange: {momentum: 1.0e15'"; exit 1; }
sed "s/^  exchange: {momentum: 1.0e15/  exchange: {momentum: $K/" "$scene" > "$work/scene.yaml"
out=$(cd "$work" && "$mpmice" scene.yaml 2>&1)
status=$?
echo "$out" | grep -v '^step ' | tail -8
echo "K = $K: exit status $status"
if [ "$want" = done ]; then
  [ $status -eq 0 ] || { echo "FAIL: expected the run to complete (exit 0)"; exit 1; }
  end=$(sed -n 's/^  end: *\([0-9.eE+-]*\).*/\1/p' "$scene" | head -1)
  line=$(grep '^done: ' <<<"$out" | tail -1)
  n=$(sed -n 's/^done: \([0-9]*\) steps, t = \([0-9.eE+-]*\) s.*/\1/p' <<<"$line")
  t=$(sed -n 's/^done: \([0-9]*\) steps, t = \([0-9.eE+-]*\) s.*/\2/p' <<<"$line")
  [ -n "$n" ] || { echo "FAIL: no 'done: N steps, t = T s' line"; exit 1; }
  awk -v t="$t" -v e="$end" 'BEGIN { exit !(t + 0 >= 0.999999 * e) }' || { echo "FAIL: ended at t = $t, not $end"; exit 1; }
  [ "$n" -le "$max" ] || { echo "FAIL: $n steps, more than $max"; exit 1; }
  if [ "${1:-}" = "--leak-below" ]; then
    dir=$(sed -n 's/^  directory: *\([^ ]*\).*/\1/p' "$scene" | head -1)
    name=$(sed -n 's/^scene: *\([^ ]*\).*/\1/p' "$scene" | head -1)
    lout=$(cd "$work" && "$lame" "$dir/$name" --scene scene.yaml 2>&1) || { echo "$lout"; echo "FAIL: cylinder_lame"; exit 1; }
    echo "$lout" | head -2
    leak=$(sed -n 's/.*: leak \([0-9.eE+-]*\) of it.*/\1/p' <<<"$lout")
    [ -n "$leak" ] || { echo "FAIL: no leak figure from cylinder_lame"; exit 1; }
    awk -v l="$leak" -v b="$2" 'BEGIN { exit !(l + 0 < b + 0) }' || { echo "FAIL: leak $leak not below $2"; exit 1; }
  fi
else
  [ $status -ne 0 ] || { echo "FAIL: expected a non-zero exit"; exit 1; }
  for p in "$@"; do
    grep -qF -- "$p" <<<"$out" || { echo "FAIL: output lacks '$p'"; exit 1; }
  done
  n=$(grep 'error' <<<"$out" | sed -n 's/.*(step \([0-9]*\)).*/\1/p' | head -1)
  [ -n "$n" ] || { echo "FAIL: the error names no '(step N)'"; exit 1; }
  [ "$n" -le "$max" ] || { echo "FAIL: stopped at step $n, after the bound $max"; exit 1; }
fi
echo "PASS"
