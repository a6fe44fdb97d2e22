#!/usr/bin/env bash
# Every program answers --help and --version on stdout with exit 0, naming itself; a missing or
# extra scene file is exit 2 with usage on stderr (issue 15).
#   help_version.sh BUILD_DIR
set -u
bin=$1 status=0 work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; status=1; }
# expect STATUS PATTERN STREAM -- COMMAND...: the exit status and an extended regex on stdout/stderr
expect() {
  local want=$1 pattern=$2 stream=$3; shift 4
  "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  [ "$rc" -eq "$want" ] || fail "'$*' exited $rc, expected $want (stderr: $(head -c 400 "$work/err"))"
  grep -qE -- "$pattern" "$work/$stream" || fail "'$*': $stream lacks /$pattern/: $(head -c 400 "$work/$stream")"
}
for p in mpm_solver/mpm_solver ice_solver/ice_solver coupler/mpmice coupler/coupler; do
  exe=$bin/$p name=${p##*/}
  expect 0 "^Usage: $name|^usage: $name" out -- "$exe" --help
  expect 0 "Sample runs" out -- "$exe" --help
  expect 0 "^$name [0-9]+\.[0-9]+\.[0-9]+ \(.+\)$" out -- "$exe" --version
  expect 0 "^$name [0-9]" out -- "$exe" -V
  if [ "$name" != coupler ]; then
    expect 2 "usage: $name scene.yaml" err -- "$exe"
    expect 2 "usage: $name scene.yaml" err -- "$exe" a.yaml b.yaml
    expect 2 "usage: $name scene.yaml" err -- "$exe" --no-such-option a.yaml
  fi
done
c=$bin/coupler/coupler
expect 0 "^usage: coupler run" out -- "$c" run --help
expect 0 "--bin-dir DIR" out -- "$c" run --help
expect 0 "--mpm-ranks N" out -- "$c" run --help
expect 0 "--dry-run" out -- "$c" run --help
expect 0 "^usage: coupler check" out -- "$c" check --help
expect 0 "--quiet" out -- "$c" check --help
expect 0 "^coupler [0-9]" out -- "$c" run --version
expect 0 "^coupler [0-9]" out -- "$c" check --version
expect 2 "no command given" err -- "$c"
st=$bin/study/study
expect 0 "^usage: study" out -- "$st" --help
expect 0 "--resume" out -- "$st" --help
expect 0 "Sample runs" out -- "$st" --help
expect 0 "^study [0-9]+\.[0-9]+\.[0-9]+ \(.+\)$" out -- "$st" --version
expect 2 "usage: study study.yaml" err -- "$st"
expect 2 "usage: study study.yaml" err -- "$st" --no-such-option a.yaml
[ $status -eq 0 ] && echo "help_version: ok"
exit $status
