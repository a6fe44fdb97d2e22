# Sourced by the flap tests (run_flap.sh, run_flap_restart.sh): the coarse flap of configs/flap_openfoam.yaml.
#   coarse_case SRC DEST            the case configs/flap/fluid-openfoam with a coarse mesh, no periodic writes
#   flap_scene SRC SCHEDULE PATCH MODE DAMPING EXTRA    the scene (0.2 s, MPM spacing 0.05, case `case`,
#                                   output `out`), EXTRA: lines after `schedule:` (e.g. the acceleration)
coarse_case() {
  cp -r "$1/configs/flap/fluid-openfoam" "$2"
  sed -i -e 's/^nFlap .*/nFlap 2;/' -e 's/^nHeight .*/nHeight 5;/' -e 's/^nFar .*/nFar 10;/' "$2/system/blockMeshDict"
  sed -i 's/^writeInterval .*/writeInterval   1000;/' "$2/system/controlDict"
}
flap_scene() {
  sed -e 's/end: 5.0/end: 0.2/' -e 's/spacing: \[0.025, 0.025\]/spacing: [0.05, 0.05]/' \
      -e "s/schedule: explicit_serial/schedule: $2/" -e "s#case: flap/fluid-openfoam#case: case#" \
      -e "s/patch: flap/patch: $3/" -e "s/mapping: rbf/mapping: rbf\n    mode: $4/" \
      -e "s/update: usl/update: usl\n  damping: $5/" -e 's#directory: output/flap_openfoam#directory: out#' \
      -e 's/timeout: 120/timeout: 60/' "$1/configs/flap_openfoam.yaml" |
    if [ -n "$6" ]; then awk -v extra="$6" '{print} /schedule: implicit_serial/{print extra}'; else cat; fi
}
