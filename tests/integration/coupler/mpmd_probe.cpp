// mpmd_probe: a tiny participant for the coupler's integration tests (real MPMD launches).
//
//   scripts/mpirun -np 1 mpmd_probe a 8x6 ok : -np 2 mpmd_probe b 8x6 ok
//
// Each program joins the launch under its name, handshakes on the mesh, then "a" sends a
// two-component cell field (a formula of the global cell index) and "b" checks every value and
// sends back twice the values, which "a" checks. Modes of "b": ok, die (exits abruptly after the
// handshake), hang (stops answering). Exit 0 when every received value is right.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

#include "coupler/exchange/cell_exchange.h"
#include "coupler/launch/handshake.h"
#include "coupler/launch/participant.h"
#include "coupler/launch/timed_wait.h"
#include "core/parallel/mpi_session.h"

using namespace mpmice;

namespace {
double formula(int i, int j, int c) { return 100.0 * c + i + 0.01 * j; }
}

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  if (argc < 4) {
    std::cerr << "usage: mpmd_probe NAME NXxNY MODE\n";
    return 2;
  }
  const std::string name = argv[1], meshText = argv[2], mode = argv[3];
  int nx = 0, ny = 0;
  if (std::sscanf(meshText.c_str(), "%dx%d", &nx, &ny) != 2) return 2;
  try {
    auto p = coupler::Participant::join(session.world(), name, 3.0);
    if (!p.coupled()) {
      std::cout << "probe " << name << ": started alone, uncoupled\n";
      return 0;
    }
    coupler::handshake(p, {{"mesh", meshText}, {"exchanged fields", "f"}});
    const core::Mesh mesh(2, {0, 0, 0}, {1, 1, 1}, {nx, ny, 1});
    const core::Decomposition mine(mesh, p.local().size()), peer(mesh, p.peerSize());
    coupler::CellExchange ex(p, mine, peer);
    const core::Box owned = mine.cellBox(p.local().rank());
    core::Field f("f", core::Centering::Cell, owned, 2, 0, -1.0);
    int bad = 0;
    if (name == "a") {
      core::forEach(owned, [&](int i, int j, int k) {
        for (int c = 0; c < 2; ++c) f(i, j, k, c) = formula(i, j, c);
      });
      ex.send({&f}, 1, "field f");
      ex.receive({&f}, 2, "field 2f");
      core::forEach(owned, [&](int i, int j, int k) {
        for (int c = 0; c < 2; ++c) bad += f(i, j, k, c) != 2 * formula(i, j, c);
      });
    } else {
      if (mode == "die") std::_Exit(3);
      if (mode == "hang") std::this_thread::sleep_for(std::chrono::seconds(3600));
      ex.receive({&f}, 1, "field f");
      core::forEach(owned, [&](int i, int j, int k) {
        for (int c = 0; c < 2; ++c) {
          bad += f(i, j, k, c) != formula(i, j, c);
          f(i, j, k, c) *= 2;
        }
      });
      ex.send({&f}, 2, "field 2f");
    }
    const int totalBad = p.local().max(bad);
    if (p.local().root())
      std::cout << "probe " << name << ": " << p.local().size() << " ranks, peer '" << p.peerName() << "' "
                << p.peerSize() << " ranks, exchange " << (totalBad ? "WRONG" : "ok") << "\n";
    return totalBad ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << std::endl;
    core::MpiSession::abortAll(3);
  }
}
