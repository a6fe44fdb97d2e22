#!/bin/bash
# The stability map (docs/stability.md): runs the two studies configs/studies/stability_{piston,slab}.yaml
# with the study tool, then writes docs/stability_{piston,slab}.csv and the PNG maps
# (benchmarks/coupled/stability_map.py, gnuplot).
#   bash scripts/stability_map.sh [BUILD_DIR [SCRATCH_DIR]]
# BUILD_DIR defaults to build/ (it needs study, mpmice); SCRATCH_DIR (new or empty) holds the study folders.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$(mktemp -d /tmp/stability_map.XXXXXX)}
for s in piston slab; do
  # exit 3: the CSV is written and some point stopped, which is what the map records
  "$build/study/study" "$root/configs/studies/stability_$s.yaml" --out "$out/stability_$s" || [ $? -eq 3 ]
done
python3 "$root/benchmarks/coupled/stability_map.py" "$out/stability_piston" "$out/stability_slab" "$root/docs"
echo "stability map: study folders in $out; CSVs and maps in $root/docs"
