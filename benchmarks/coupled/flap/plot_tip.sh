#!/usr/bin/env bash
# Plots the perpendicular flap's tip x-displacement against time (gnuplot, PNG).
#
# Usage:  plot_tip.sh <probes.csv> [<other probes.csv> <label> ...] <out.png>
#   plot_tip.sh output/flap_mpmice/flap_mpmice_probes.csv tip.png
#   plot_tip.sh dx0.025/flap_mpmice_probes.csv dx0.05/flap_mpmice_probes.csv "dx 0.05" tip.png
# The first file is labelled after its name (without _probes.csv), or by $LABEL; the others by
# the label that follows each. Columns are found by name in the header: `time` and $COLUMN
# (default tip_ux), so any probes CSV of mpm_solver, mpmice or the MPMD launch works. The band
# 0.17-0.20 m of the published first peaks is drawn for reference (REFERENCE=0 leaves it out).
set -euo pipefail

if [ $# -lt 2 ] || [ $(( ($# - 2) % 2 )) -ne 0 ]; then
  echo "usage: plot_tip.sh <probes.csv> [<other probes.csv> <label> ...] <out.png>" >&2
  exit 2
fi
command -v gnuplot > /dev/null || { echo "plot_tip.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }

args=("$@")
out="${args[$#-1]}"
column="${COLUMN:-tip_ux}"
files=("${args[0]}")
first_label="${LABEL:-$(basename "${args[0]}" .csv)}"
labels=("${first_label%_probes}")
for ((i = 1; i < $# - 1; i += 2)); do
  files+=("${args[$i]}")
  labels+=("${args[$((i + 1))]}")
done

# Column numbers from the header (gnuplot then needs no header handling).
column_of() {  # file name
  head -n 1 "$1" | tr ',' '\n' | grep -n -x "$2" | cut -d: -f1
}
plot=""
for k in "${!files[@]}"; do
  f="${files[$k]}"
  [ -r "$f" ] || { echo "plot_tip.sh: cannot read '$f'" >&2; exit 1; }
  ct=$(column_of "$f" time) cu=$(column_of "$f" "$column")
  [ -n "$ct" ] && [ -n "$cu" ] || { echo "plot_tip.sh: '$f' has no columns 'time' and '$column'" >&2; exit 1; }
  plot+="${plot:+, }'$f' every ::1 using $ct:$cu with lines lw 2 title '${labels[$k]//\'/}'"
done
if [ "${REFERENCE:-1}" != 0 ] && [ "$column" = tip_ux ]; then
  plot+=", 0.17 with lines dt 2 lc rgb 'gray50' title 'published first peak 0.17-0.20 m', 0.20 with lines dt 2 lc rgb 'gray50' notitle"
fi

gnuplot <<EOF
set terminal pngcairo size 1000,600 noenhanced
set output '$out'
set datafile separator ','
set xlabel 'time [s]'
set ylabel '$column [m]'
set title 'Perpendicular flap: tip displacement'
set grid
set key bottom right
plot $plot
EOF
echo "plot_tip.sh: wrote $out"
