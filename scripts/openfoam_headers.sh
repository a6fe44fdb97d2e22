#!/usr/bin/env bash
# Fetches the OpenFOAM headers that Debian's `openfoam` package does not ship, and prints the
# include root (the source tree's src/ folder) on stdout; progress goes to stderr.
#
#   scripts/openfoam_headers.sh            # cache: ${MPMICE_OPENFOAM_CACHE:-$HOME/.cache/mpmice/openfoam}
#
# Steps (each skipped when already done, so a second run takes well under a second):
#   1. a deb-src entry, in a NEW file /etc/apt/sources.list.d/mpmice-deb-src.sources derived from
#      the system's deb822 debian.sources (or a one-line sources.list entry); existing files untouched;
#   2. `apt-get update`, only when apt does not yet know the source package;
#   3. `apt-get source openfoam=<source version of the installed package>` into the cache;
#   4. the tree's own `wmake/wmakeLnInclude -u` for the libraries the adapter includes.
# Needs root (or sudo) only for steps 1-2. Works without a TTY. Exit 0 and no stdout if openfoam is
# not installed (nothing to build against); exit non-zero if a step fails.
set -euo pipefail
log() { echo "openfoam_headers: $*" >&2; }
t0=$(date +%s)

cache="${MPMICE_OPENFOAM_CACHE:-$HOME/.cache/mpmice/openfoam}"
if ! ver=$(dpkg-query -W -f='${source:Version}' openfoam 2>/dev/null) || [ -z "$ver" ]; then
  log "the openfoam package is not installed; nothing to do"
  exit 0
fi
upstream="${ver%-*}"; upstream="${upstream#*:}"
stamp="$cache/.done-$ver"
libs="OpenFOAM OSspecific/POSIX finiteVolume meshTools dynamicMesh"

if [ -f "$stamp" ] && [ -d "$(cat "$stamp")/OpenFOAM/lnInclude" ]; then
  cat "$stamp"
  exit 0
fi

SUDO=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null; then SUDO="sudo -n"; fi
fi
export DEBIAN_FRONTEND=noninteractive

# 1. deb-src entry.
have_src() { apt-cache showsrc openfoam 2>/dev/null | grep -q "^Version: $ver\$"; }
if ! have_src; then
  new=/etc/apt/sources.list.d/mpmice-deb-src.sources
  if [ ! -f "$new" ] && ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; then
    tmp=$(mktemp)
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
      # Copy every stanza whose URIs point at a Debian mirror (not -security), as deb-src only.
      awk 'BEGIN{RS=""; ORS="\n\n"} /URIs:[^\n]*debian/ && !/debian-security/ {
             gsub(/Types:[^\n]*/, "Types: deb-src"); print }' /etc/apt/sources.list.d/debian.sources > "$tmp"
    elif [ -f /etc/apt/sources.list ]; then
      grep -E '^deb [^#]*debian' /etc/apt/sources.list | grep -v security | sed 's/^deb /deb-src /' > "$tmp.list"
      new=/etc/apt/sources.list.d/mpmice-deb-src.list; mv "$tmp.list" "$tmp"
    fi
    if [ ! -s "$tmp" ]; then
      log "no Debian apt source entry found to derive a deb-src entry from"; rm -f "$tmp"; exit 1
    fi
    log "adding $new"
    $SUDO install -m 644 "$tmp" "$new"
    rm -f "$tmp"
  fi
  # 2. apt-get update, only because the source package is unknown.
  log "apt-get update"
  $SUDO apt-get update -qq >&2
  if ! have_src; then
    log "apt knows no source package openfoam $ver (no deb-src mirror reachable?)"; exit 1
  fi
fi

# 3. the source package.
mkdir -p "$cache"
src=$(ls -d "$cache"/openfoam-*/ 2>/dev/null | head -n1 || true)
if [ -z "$src" ] || [ ! -x "$src/wmake/wmakeLnInclude" ]; then
  command -v dpkg-source >/dev/null || $SUDO apt-get install -y -qq dpkg-dev >&2
  log "apt-get source openfoam=$ver into $cache"
  (cd "$cache" && apt-get source -qq --download-only "openfoam=$ver" >&2 \
     && dpkg-source --no-check -x "openfoam_$ver.dsc" >&2)
  src=$(ls -d "$cache"/openfoam-*/ | head -n1)
fi
src="${src%/}"

# 4. lnInclude folders (wmakeLnInclude is a POSIX shell script; -u only adds missing links).
for lib in $libs; do
  if [ -d "$src/src/$lib" ]; then
    log "wmakeLnInclude -u src/$lib"
    (cd "$src" && WM_PROJECT_DIR="$src" "$src/wmake/wmakeLnInclude" -u "src/$lib" >&2)
  fi
done
[ -d "$src/src/OpenFOAM/lnInclude" ] || { log "lnInclude missing after wmakeLnInclude"; exit 1; }
echo "$src/src" > "$stamp"
log "done in $(( $(date +%s) - t0 )) s"
echo "$src/src"
