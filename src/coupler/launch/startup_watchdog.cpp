#include "coupler/launch/startup_watchdog.h"

#include <chrono>
#include <cstdlib>
#include <sstream>

#include "core/util/error_line.h"

namespace mpmice::coupler {

StartupWatchdog::StartupWatchdog(std::string program, double timeout) {
  thread_ = std::thread([this, program = std::move(program), timeout] {
    std::unique_lock lock(m_);
    const auto limit = std::chrono::duration<double>(timeout);
    if (cv_.wait_for(lock, limit, [this] { return done_; })) return;
    std::ostringstream os;
    os << "the launch did not start within " << timeout << " s (coupling.timeout): the other program "
       << "of the MPMD launch did not join (it stopped or hangs during start-up)";
    core::writeErrorLine(program, os.str());
    std::_Exit(1);
  });
}

StartupWatchdog::~StartupWatchdog() {
  {
    std::lock_guard lock(m_);
    done_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void maybeStallAtStart(const std::string& name) {
  const char* spec = std::getenv("MPMICE_FAULT_STALL_START");
  if (!spec) return;
  const std::string s(spec);
  const auto colon = s.find(':');
  if (colon == std::string::npos || s.substr(0, colon) != name) return;
  std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(s.c_str() + colon + 1)));
}

}  // namespace mpmice::coupler
