#!/usr/bin/env bash
# The difference of two tip curves (probes CSV files, columns `time` and tip_ux by name; '#'
# comment lines and blank lines skipped): the second is interpolated linearly at the first's times
# over their common time range. rms_diff / rms_first is the study's `probe_curve` error
# (src/study/reference/probe_curve.h).
# Prints: samples, t_end, max |u2 - u1| and its time, rms(u2 - u1), rms(u1), mean(u2 - u1).
#   curve_difference.sh output/flap_openfoam/flap_openfoam_probes.csv output/flap_mpmice/flap_mpmice_probes.csv
set -euo pipefail
col="${COLUMN:-tip_ux}"
awk -F, -v col="$col" '
  FNR == 1 { head = 0 }
  /^[ \t]*#/ || /^[ \t\r]*$/ { next }
  !head { head = 1; tc = 0; uc = 0
             for (i = 1; i <= NF; ++i) { if ($i == "time") tc = i; if ($i == col) uc = i }
             if (!tc || !uc) { print "curve_difference: no time or " col " column in " FILENAME > "/dev/stderr"; exit 2 }
             file++; next }
  file == 1 { t1[n1] = $tc; u1[n1++] = $uc; next }
  file == 2 { t2[n2] = $tc; u2[n2++] = $uc }
  END {
    k = 0; n = 0; s2 = 0; r2 = 0; sd = 0; mx = 0; tmx = 0
    for (i = 0; i < n1; ++i) {
      t = t1[i]; if (t < t2[0] || t > t2[n2 - 1]) continue
      while (k + 1 < n2 - 1 && t2[k + 1] < t) ++k
      w = (t2[k + 1] > t2[k]) ? (t - t2[k]) / (t2[k + 1] - t2[k]) : 0
      u = u2[k] + w * (u2[k + 1] - u2[k]); d = u - u1[i]
      n++; s2 += d * d; r2 += u1[i] * u1[i]; sd += d; tend = t
      if (d * d > mx * mx) { mx = d; tmx = t }
    }
    printf "samples,t_end,max_diff,max_diff_time,rms_diff,rms_first,mean_diff\n"
    printf "%d,%.4f,%.6g,%.3f,%.8g,%.8g,%.6g\n", n, tend, mx, tmx, sqrt(s2 / n), sqrt(r2 / n), sd / n
  }' "$1" "$2"
