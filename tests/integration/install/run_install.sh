#!/usr/bin/env bash
# cmake --install into a scratch prefix, then use it as a user would (tests/integration/install):
#   run_install.sh CMAKE BUILD_DIR CONSUMER_DIR SCENE_DIR CXX [LAUNCHER]
# 1. the prefix holds the package files, the namespaced headers, the programs and the launch helper;
# 2. consumer/ configures with find_package(mpmice), builds, and takes one coupled step in memory;
# 3. a pkg-config build (scene_summary.cpp) reads a scene;
# 4. the installed `coupler run` launches the installed programs (found beside it) on a 3-step scene,
#    through the installed launch helper, nothing from the build tree; a coupler copied elsewhere
#    finds them on PATH; an empty PATH and no programs beside it is an error naming where it looked.
set -u
cmake=$1 build=$2 consumer=$3 scenes=$4 cxx=$5 launcher=${6:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
prefix=$work/prefix

"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
for f in lib/cmake/mpmice/mpmiceConfig.cmake lib/cmake/mpmice/mpmiceConfigVersion.cmake \
         lib/cmake/mpmice/mpmiceTargets.cmake lib/pkgconfig/mpmice.pc include/mpmice/core/version.h \
         include/mpmice/core/scene/scene.h include/mpmice/couplings/volume/schedule/coupling_schedule.h \
         bin/mpm_solver bin/ice_solver bin/mpmice bin/coupler libexec/mpmice/mpirun lib/libmpmice_core.a; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
for t in core mpm ice coupler coupling; do
  grep -q "add_library(mpmice::$t " "$prefix/lib/cmake/mpmice/mpmiceTargets.cmake" || fail "no exported target mpmice::$t"
done
# Nothing installed points back into the build or source tree.
src=$(cd "$scenes/../../.." && pwd)
if grep -l -e "$build" -e "$src/src" "$prefix"/lib/cmake/mpmice/*.cmake "$prefix/lib/pkgconfig/mpmice.pc"; then
  fail "the package files name the build or source tree"
fi
echo "install: $(cd "$prefix" && find . -type f | wc -l) files under the prefix"

# 2. find_package(mpmice)
launch=()
[ -n "$launcher" ] && launch=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
"$cmake" -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" "${launch[@]}" > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "consumer configure"; }
grep "mpmice 0" "$work/configure.log"
"$cmake" --build "$work/consumer" -j2 > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "consumer build"; }
out=$(cd "$work" && "$work/consumer/coupled_step" "$scenes/tiny_cylinder.yaml" 2>&1) || { echo "$out"; fail "coupled_step"; }
echo "$out"
grep -q "consumer: coupled step ok" <<< "$out" || fail "coupled_step did not take its step"

# 3. pkg-config
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs mpmice) || fail "pkg-config --cflags --libs mpmice"
# shellcheck disable=SC2086
"$cxx" -O0 "$consumer/scene_summary.cpp" $flags -o "$work/scene_summary" > "$work/pc.log" 2>&1 || { cat "$work/pc.log"; fail "pkg-config build"; }
out=$("$work/scene_summary" "$scenes/tiny_cylinder.yaml") || fail "scene_summary"
echo "$out"
grep -q "scene 'pressurized_cylinder', 1 solid(s), 1 fluid(s)" <<< "$out" || fail "scene_summary output"

# 4. the installed coupler run, in a scratch folder (the scene writes output/ there)
mkdir -p "$work/run" && cd "$work/run"
out=$("$prefix/bin/coupler" run "$scenes/tiny_output_interval.yaml" 2>&1); status=$?
echo "$out" | grep -v "^\s*$" | tail -n 12
[ "$status" -eq 0 ] || fail "installed coupler run ended $status"
grep -q "coupler: $prefix/libexec/mpmice/mpirun --tag-output -np 1 $prefix/bin/mpm_solver .* : -np 1 $prefix/bin/ice_solver " <<< "$out" ||
  fail "the installed coupler did not launch the installed programs through the installed helper"
grep -q "coupler: mpm_solver (1 rank): 3 steps to t = " <<< "$out" || fail "the launch did not run its 3 steps"
ls output/*_solid*.h5 > /dev/null 2>&1 || fail "no solid output"
# A coupler without its programs beside it finds them on PATH.
mkdir -p "$work/elsewhere" && cp "$prefix/bin/coupler" "$work/elsewhere/"
out=$(PATH="$prefix/bin:$PATH" "$work/elsewhere/coupler" run --dry-run "$scenes/tiny_output_interval.yaml" 2>&1) ||
  { echo "$out"; fail "coupler run from PATH"; }
grep -q -- "-np 1 $prefix/bin/mpm_solver .* -np 1 $prefix/bin/ice_solver" <<< "$out" || { echo "$out"; fail "not found on PATH"; }
# ... and, with nothing to find, says where it looked (exit 2, nothing launched).
out=$(PATH=/nonexistent "$work/elsewhere/coupler" run --dry-run "$scenes/tiny_output_interval.yaml" 2>&1); status=$?
[ "$status" -eq 2 ] || { echo "$out"; fail "a missing program: status $status, expected 2"; }
grep -q "mpm_solver not found (not beside this coupler in $work/elsewhere, not in its build tree, not on PATH)" <<< "$out" ||
  { echo "$out"; fail "the missing-program message"; }
echo "PASS: install, find_package consumer, pkg-config consumer, installed coupler run"
