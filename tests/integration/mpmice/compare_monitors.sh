#!/usr/bin/env bash
# Compares two conservation CSVs (same columns and rows) from the time column on; passes when the
# largest relative difference is at most TOL.   compare_monitors.sh A.csv B.csv TOL WHAT [LAST]
# LAST: compare the columns up to this one only (default: every column).
set -u
a=$1 b=$2 tol=$3 what=$4 last=${5:-0}
[ -s "$a" ] && [ -s "$b" ] || { echo "FAIL: a conservation CSV is missing"; exit 1; }
if [ "$(wc -l < "$a")" != "$(wc -l < "$b")" ] || [ "$(wc -l < "$a")" -lt 3 ]; then
  echo "FAIL: the runs wrote different numbers of rows"; cat "$a" "$b"; exit 1
fi
paste -d, "$a" "$b" | awk -F, -v tol="$tol" -v what="$what" -v n="$(head -1 "$a" | awk -F, '{print NF}')" -v last="$last" '
  NR == 1 { m = n; if (last > 0) for (i = 1; i <= n; ++i) if ($i == last) m = i; next }
  { for (i = 2; i <= m; ++i) {
      x = $i; y = $(i + n); d = x - y; if (d < 0) d = -d
      s = (x < 0 ? -x : x); t = (y < 0 ? -y : y); if (t > s) s = t
      r = d / (s > 1e-300 ? s : 1); if (d < 1e-12) r = 0
      if (r > worst) worst = r } }
  END { printf "largest relative difference of the monitors (%s): %.3g, tolerance %g\n", what, worst, tol
        if (worst > tol) { print "FAIL"; exit 1 }
        print "PASS" }'
