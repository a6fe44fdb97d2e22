#pragma once
/// @brief A bound on every phase of an MPMD launch, from the start to the process's exit, for the
/// calls that wait without a timeout of their own (the collectives that join the programs, the
/// collectives inside one program, MPI_Finalize at the end).
///
/// One per process, started by Participant::join. Three stages:
/// - start-up: the join must finish within coupling.timeout, or the watchdog prints one line
///   naming this program and what it waited for ("the launch did not start within 3 s").
/// - run (after the handshake of a coupled launch): the main thread reports progress (every poll of
///   a timed wait, every step: beat(), step()); no progress for twice coupling.timeout is an
///   error naming this program and the step after which it stopped. Timed waits for the peer run
///   out first (after coupling.timeout) and name the peer; this bound catches this process
///   hanging and the calls without a timeout. A participant whose peer stopped answering is named
///   by the peer's timed wait, and `coupler run` names the stopped one in its closing line.
/// - ending (the coupled Participant destroyed): the process must exit within twice
///   coupling.timeout (MPI_Finalize waits for every process of the launch).
/// When it fires it ends the process with status 1; mpirun then ends the whole launch. A program
/// started alone (uncoupled) runs without it.
#include <string>

namespace mpmice::coupler {

namespace LaunchWatchdog {

/// Starts the process's watchdog in its start-up stage (program: the participant's program name).
void start(const std::string& program, double timeout);
/// The join is complete and coupled: from now on progress is watched.
void joined();
/// The coupled part of the run is over: the process must end within the bound.
void ending();
/// Stops the watchdog (an uncoupled run, or a join that failed with its own error).
void stop();
/// Progress of the main thread (cheap: one atomic store); no-op when no watchdog runs.
void beat() noexcept;
/// Progress: step n of the coupled run is done.
void step(long n) noexcept;

}  // namespace LaunchWatchdog

/// Fault injection for the launch tests: MPMICE_FAULT_STALL_START=<name>:<seconds> makes the
/// participant called <name> sleep that long before it joins (a program stopped at start-up).
void maybeStallAtStart(const std::string& name);

}  // namespace mpmice::coupler
