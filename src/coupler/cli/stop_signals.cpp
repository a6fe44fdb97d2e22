#include "coupler/cli/stop_signals.h"

namespace mpmice::coupler {

namespace {
volatile std::sig_atomic_t g_stopSignal = 0;
extern "C" void recordStopSignal(int sig) { g_stopSignal = sig; }
}  // namespace

StopSignals::StopSignals() {
  g_stopSignal = 0;
  struct sigaction sa {};
  sa.sa_handler = recordStopSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: poll() and sleeps return at once
  sigaction(SIGINT, &sa, &oldInt_);
  sigaction(SIGTERM, &sa, &oldTerm_);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &oldInt_, nullptr);
  sigaction(SIGTERM, &oldTerm_, nullptr);
  g_stopSignal = 0;
}

int StopSignals::received() { return g_stopSignal; }

std::string signalName(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal " + std::to_string(sig);
  }
}

}  // namespace mpmice::coupler
