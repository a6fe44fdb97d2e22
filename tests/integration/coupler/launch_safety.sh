#!/usr/bin/env bash
# `coupler run` on hostile file names, stopped by a signal, and started twice on one scene.
#   launch_safety.sh COUPLER BIN_DIR SHORT_SCENE LONG_SCENE MODE   (LONG_SCENE: its time.end is moved far away)
# MODE no_shell:       scenes named x;touch${IFS}INJECTED;.yaml, with ( & ' $HOME, run to their end
#                      (exit 0) and nothing is injected.
# MODE sigterm, sigint: SIGTERM (SIGINT, as ^C sends) to a running `coupler run` ends it within a few
#                      seconds with status 128 + signal, naming the signal, and no mpirun /
#                      mpm_solver / ice_solver of it remains.
# MODE second_run:     a second `coupler run` of the scene into the same output directory is
#                      refused at start naming the holder (pid, host); a stale lock is taken over.
# MODE stall_mid_run:  ice_solver sleeps for ever after step 5 (MPMICE_FAULT_STALL; LONG_SCENE with a
#                      short coupling.timeout): the launch ends non-zero, its closing line names
#                      ice_solver as the participant that stopped answering, nothing remains.
# MODE sigstop_mid_run: the same with mpm_solver stopped by SIGSTOP after a second of steps.
# MODE stall_at_the_end: ice_solver sleeps for ever after its last step (SHORT_SCENE's step count
#                      given in STALL_STEP): mpm_solver's wait at the end of the run names it.
# MODE stale_io_semaphore: a run killed inside an HDF5 file's creation leaves Open MPI's OMPIO
#                      shared-file-pointer semaphore (/dev/shm/sem.OMPIO_<file>) at 0; with the sm
#                      component the next run that creates that file waited on it for ever (the
#                      watchdog then ended the launch). scripts/mpirun excludes that component
#                      (--mca sharedfp ^sm) and so does every program's MPI start (MpiSession, for
#                      a program started alone or by another mpirun): SHORT_SCENE under a fresh
#                      name completes beside such a semaphore for its first output file, by
#                      `coupler run` and by `mpmice` alone (the semaphores made here, removed at the end).
set -u
coupler=$1 bin=$2 scene=$3 long=$4 mode=$5
work=$(mktemp -d)
trap 'pkill -KILL -f -- "$work/" 2>/dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
# A scene running long enough to be caught: time.end far away, no step limit.
long_scene() { sed -e 's/^  end: .*/  end: 1.0e3/' "$long" > "$1"; }
case "$mode" in
  no_shell)
    for name in 'x;touch${IFS}INJECTED;.yaml' "a (b) & c's \$HOME.yaml"; do
      cp "$scene" "$work/$name"
      out=$("$coupler" run --bin-dir "$bin" "$name" 2>&1); status=$?
      echo "$out" | grep -v '^\[' | tail -5
      [ $status -eq 0 ] || fail "exit status $status for '$name'"
      [ ! -e INJECTED ] && [ ! -e "$HOME/INJECTED" ] || fail "the scene name ran a command"
      quoted="'${name//\'/\'\\\'\'}'"
      grep -qF -- "$quoted" <<<"$out" || fail "the printed line lacks the quoted name $quoted"
    done ;;
  sigterm|sigint)
    sig=$(tr a-z A-Z <<<"$mode"); want=$(( 128 + $(kill -l "${sig#SIG}") ))
    long_scene "$work/long.yaml"
    "$coupler" run --bin-dir "$bin" "$work/long.yaml" > log 2>&1 &
    pid=$!
    for _ in $(seq 100); do pgrep -f -- "ice_solver $work/long.yaml" > /dev/null && break; sleep 0.1; done
    pgrep -f -- "ice_solver $work/long.yaml" > /dev/null || { cat log; fail "the launch did not start"; }
    sleep 1
    kill -"${sig#SIG}" $pid
    for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
    kill -0 $pid 2>/dev/null && fail "coupler run still runs 10 s after $sig"
    wait $pid; status=$?
    grep -v '^\[' log | tail -5
    echo "exit status: $status"
    [ $status -eq $want ] || fail "expected exit status $want (128 + $sig)"
    grep -q "coupler: stopped by $sig" log || fail "the output does not name $sig"
    sleep 0.5
    left=$(pgrep -af -- "$work/long.yaml")
    [ -z "$left" ] || fail "left running: $left" ;;
  second_run)
    long_scene "$work/long.yaml"
    "$coupler" run --bin-dir "$bin" "$work/long.yaml" > first.log 2>&1 &
    pid=$!
    for _ in $(seq 100); do pgrep -f -- "ice_solver $work/long.yaml" > /dev/null && break; sleep 0.1; done
    lock=$(ls output/*.lock 2>/dev/null | head -1)
    [ -n "$lock" ] || { cat first.log; fail "no lock in output/"; }
    out=$("$coupler" run --bin-dir "$bin" "$work/long.yaml" 2>&1); status=$?
    echo "$out"; echo "exit status: $status"
    kill -TERM $pid; wait $pid
    [ $status -ne 0 ] || fail "the second run was not refused"
    grep -q "the output directory is in use: output/pressurized_cylinder.lock is held by pid $pid on host $(hostname) (coupler)" <<<"$out" ||
      fail "the refusal does not name the holder"
    # mpmice on the same scene while an MPMD launch of it runs: refused as well.
    "$coupler" run --bin-dir "$bin" "$work/long.yaml" > first.log 2>&1 &
    pid=$!
    for _ in $(seq 100); do pgrep -f -- "ice_solver $work/long.yaml" > /dev/null && break; sleep 0.1; done
    out=$(timeout 20 "$bin/coupler/mpmice" "$work/long.yaml" 2>&1); status=$?
    echo "$out" | grep -v '^\['; echo "exit status: $status"
    kill -TERM $pid; wait $pid
    [ $status -ne 0 ] || fail "mpmice was not refused"
    grep -q "mpmice: error: the output directory is in use: output/pressurized_cylinder" <<<"$out" || fail "mpmice's refusal"
    # A stale lock (its process gone) is taken over with a note and the run goes on.
    sh -c 'exit 0' & dead=$!; wait $dead
    echo "$dead $(hostname) coupler" > output/pressurized_cylinder.lock
    out=$("$coupler" run --bin-dir "$bin" "$scene" 2>&1); status=$?
    echo "$out" | grep -v '^\[' | tail -5
    [ $status -eq 0 ] || fail "the run with a stale lock failed ($status)"
    grep -q "note: taking over the stale lock output/pressurized_cylinder.lock of pid $dead" <<<"$out" || fail "no note of the stale lock"
    [ ! -e output/pressurized_cylinder.lock ] || fail "the lock was not released at the end" ;;
  stale_io_semaphore)
    name=stale_sem_$$ alone=stale_sem_alone_$$
    sems="/OMPIO_${name}_fluid_000000.h5.part /OMPIO_${alone}_000000.h5.part"
    trap 'pkill -KILL -f -- "$work/" 2>/dev/null; rm -rf "$work"; for s in $sems; do rm -f "/dev/shm/sem.${s#/}"; done' EXIT
    for s in $sems; do
      python3 -c '
import ctypes, os, sys
libc = ctypes.CDLL("libc.so.6", use_errno=True)
libc.sem_open.restype = ctypes.c_void_p
s = libc.sem_open(sys.argv[1].encode(), os.O_CREAT | os.O_EXCL, 0o644, 0)
if not s: sys.exit("sem_open: " + os.strerror(ctypes.get_errno()))
libc.sem_close(ctypes.c_void_p(s))' "$s" || fail "could not make the semaphore $s"
      [ -e "/dev/shm/sem.${s#/}" ] || fail "no /dev/shm/sem.${s#/}"
    done
    sed -e "s/^scene: .*/scene: $name/" "$scene" > "$work/$name.yaml"
    out=$("$coupler" run --bin-dir "$bin" "$work/$name.yaml" 2>&1); status=$?
    echo "$out" | grep -v '^\[' | tail -3
    [ $status -eq 0 ] || fail "coupler run beside a stale OMPIO semaphore failed ($status)"
    ls "$work"/output/${name}_fluid_000000.h5 > /dev/null || fail "no first output file of coupler run"
    mkdir "$work/alone" && sed -e "s/^scene: .*/scene: $alone/" "$scene" > "$work/alone/$alone.yaml"
    out=$(cd "$work/alone" && timeout 30 "$bin/coupler/mpmice" "$alone.yaml" 2>&1); status=$?
    echo "$out" | tail -1
    [ $status -eq 0 ] || fail "mpmice alone beside a stale OMPIO semaphore failed ($status)"
    ls "$work"/alone/output/${alone}_000000.h5 > /dev/null || fail "no first output file of mpmice" ;;
  stall_mid_run|sigstop_mid_run|stall_at_the_end)
    if [ "$mode" = stall_at_the_end ]; then cp "$scene" "$work/long.yaml"; else long_scene "$work/long.yaml"; fi
    case "$mode" in
      stall_mid_run) MPMICE_FAULT_STALL=ice:5 "$coupler" run --bin-dir "$bin" "$work/long.yaml" > log 2>&1 & ;;
      stall_at_the_end) MPMICE_FAULT_STALL=ice:$STALL_STEP "$coupler" run --bin-dir "$bin" "$work/long.yaml" > log 2>&1 & ;;
      *) "$coupler" run --bin-dir "$bin" "$work/long.yaml" > log 2>&1 & ;;
    esac
    pid=$!
    stopped=ice_solver healthy=mpm_solver
    if [ "$mode" = sigstop_mid_run ]; then
      stopped=mpm_solver healthy=ice_solver  # the program itself (^...), not mpirun naming it
      for _ in $(seq 100); do victim=$(pgrep -f -- "^[^ ]*/mpm_solver $work/long.yaml"); [ -n "$victim" ] && break; sleep 0.1; done
      [ -n "$victim" ] || { cat log; fail "the launch did not start"; }
      for _ in $(seq 200); do grep -q '^step ' log && break; sleep 0.1; done
      sleep 1
      kill -STOP $victim
    fi
    wait $pid; status=$?
    grep -v '^\[' log | tail -8
    echo "exit status: $status"
    [ $status -ne 0 ] || fail "expected a non-zero exit"
    [ "$mode" = sigstop_mid_run ] || grep -q "ice: MPMICE_FAULT_STALL: sleeping for ever after step" log || fail "no stall"
    grep -q "$healthy: error: coupler: .*from participant '${stopped%_solver}' within 3 s (coupling.timeout)" log ||
      fail "$healthy did not name its peer's timeout"
    last=$(grep '^coupler: ' log | tail -1)
    [ "$last" = "coupler: $stopped stopped answering: $healthy waited 3 s (coupling.timeout) for it; the launch was ended" ] ||
      fail "the closing line does not name $stopped: '$last'"
    sleep 0.5
    left=$(pgrep -af -- "$work/long.yaml")
    [ -z "$left" ] || fail "left running: $left" ;;
esac
echo PASS
