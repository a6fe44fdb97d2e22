#include "coupler/launch/participant.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "coupler/launch/launch_watchdog.h"
#include "coupler/launch/timed_wait.h"

namespace mpmice::coupler {

Participant::Participant(Participant&& o) noexcept { *this = std::move(o); }

Participant& Participant::operator=(Participant&& o) noexcept {
  std::swap(local_, o.local_);
  std::swap(localRaw_, o.localRaw_);
  std::swap(inter_, o.inter_);
  std::swap(name_, o.name_);
  std::swap(peerName_, o.peerName_);
  std::swap(peerSize_, o.peerSize_);
  std::swap(firstWorld_, o.firstWorld_);
  std::swap(timeout_, o.timeout_);
  return *this;
}

Participant::~Participant() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  if (inter_ != MPI_COMM_NULL) LaunchWatchdog::ending();  // the coupled run is over: bound the exit
  if (inter_ != MPI_COMM_NULL) MPI_Comm_free(&inter_);
  if (localRaw_ != MPI_COMM_NULL) MPI_Comm_free(&localRaw_);
}

Participant Participant::join(const core::Comm& world, const std::string& name, double timeout) {
  maybeStallAtStart(name);
  // The collectives below wait without a bound of their own: the watchdog bounds them, and once
  // the launch is joined every later phase (launch_watchdog.h).
  LaunchWatchdog::start(name == "mpm" ? "mpm_solver" : name == "ice" ? "ice_solver" : name, timeout);
  struct StopUnlessJoined {  // uncoupled, or a join that failed with its own error
    bool joined = false;
    ~StopUnlessJoined() {
      if (!joined) LaunchWatchdog::stop();
    }
  } guard;
  Participant p;
  p.name_ = name;
  p.timeout_ = timeout;
  int* appnumPtr = nullptr;
  int flag = 0;
  MPI_Comm_get_attr(world.raw(), MPI_APPNUM, &appnumPtr, &flag);
  const int appnum = (flag && appnumPtr) ? *appnumPtr : 0;

  std::vector<int> apps(world.size());
  MPI_Allgather(&appnum, 1, MPI_INT, apps.data(), 1, MPI_INT, world.raw());
  std::vector<int> distinct = apps;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() > 2)
    throw std::runtime_error("coupler: the launch holds " + std::to_string(distinct.size()) +
                             " programs; a coupled run has exactly two participants");

  MPI_Comm_split(world.raw(), appnum, world.rank(), &p.localRaw_);
  p.local_ = core::Comm(p.localRaw_);
  p.firstWorld_ = static_cast<int>(std::find(apps.begin(), apps.end(), appnum) - apps.begin());
  if (distinct.size() == 1) return p;  // started alone: uncoupled

  const int other = distinct[0] == appnum ? distinct[1] : distinct[0];
  const int remoteLeader = static_cast<int>(std::find(apps.begin(), apps.end(), other) - apps.begin());
  MPI_Intercomm_create(p.localRaw_, 0, world.raw(), remoteLeader, 4242, &p.inter_);
  MPI_Comm_remote_size(p.inter_, &p.peerSize_);

  // Leaders trade names (fixed-size buffers); then each leader tells its ranks.
  char mine[64] = {0}, theirs[64] = {0};
  name.copy(mine, sizeof(mine) - 1);
  if (p.local_.root()) {
    std::vector<MPI_Request> reqs(2);
    MPI_Irecv(theirs, 64, MPI_CHAR, 0, 1, p.inter_, &reqs[0]);
    MPI_Isend(mine, 64, MPI_CHAR, 0, 1, p.inter_, &reqs[1]);
    waitAll(reqs, timeout, "the other program", "name at start-up");
  }
  MPI_Bcast(theirs, 64, MPI_CHAR, 0, p.localRaw_);
  p.peerName_ = theirs;
  if (p.peerName_ == name)
    throw std::runtime_error("coupler: both programs of the launch are '" + name +
                             "'; couple two different participants (e.g. mpm_solver and ice_solver)");
  LaunchWatchdog::joined();
  guard.joined = true;
  return p;
}

}  // namespace mpmice::coupler
