// MpmSolver's restart state: what a step reads that the scene does not give again. The solver a
// restart builds from the scene recomputes the grid, the models, the mass floors and the
// decomposition exactly as the original run did; the particles (every column, in their stored
// order, so sums run in the same order), the clock and the collapse reference come from here.
#include <stdexcept>

#include "mpm/solver/mpm_solver.h"

namespace mpmice::mpm {

void MpmSolver::saveCheckpoint(core::CheckpointData& data, const std::string& prefix) const {
  std::vector<double> buf;
  buf.reserve(p_.size() * ParticleSet::packedSize());
  for (std::size_t i = 0; i < p_.size(); ++i) p_.pack(i, buf);
  data.put(prefix + ".particles", std::move(buf));
  data.put(prefix + ".clock", std::vector<double>{time_, static_cast<double>(step_), dt_, collapse_.first()});
  data.put(prefix + ".energy_ledger", std::vector<double>{ledger_.transfer, ledger_.integration, ledger_.damping,
                                                          ledger_.keParticles, ledger_.work, ledger_.keNodes});
  data.put(prefix + ".outflow", ledger_.outflow.pack());
}

void MpmSolver::loadCheckpoint(const core::CheckpointData& data, const std::string& prefix) {
  const auto& buf = data.get(prefix + ".particles");
  const std::size_t w = ParticleSet::packedSize();
  if (buf.size() % w != 0)
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".particles' holds " +
                                std::to_string(buf.size()) + " values, not a multiple of the " + std::to_string(w) +
                                " per particle of this program");
  stencilsValid_ = false;
  signalSpeedValid_ = false;
  p_.resize(0);
  p_.reserve(buf.size() / w);
  for (std::size_t k = 0; k < buf.size(); k += w) p_.unpack(buf.data() + k);
  p_.updateMaterialRanges(static_cast<int>(scene_.materials.size()));
  if (!p_.groupedByMaterial())
    throw std::invalid_argument(data.source() + ": the checkpoint's particles are not grouped by material");
  const auto& clock = data.get(prefix + ".clock");
  if (clock.size() != 4)
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".clock' has " +
                                std::to_string(clock.size()) + " values, expected 4");
  time_ = clock[0];
  step_ = static_cast<long>(clock[1]);
  dt_ = clock[2];
  collapse_.resumeFirst(clock[3]);
  const auto& ledger = data.get(prefix + ".energy_ledger");
  if (ledger.size() != 6)
    throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".energy_ledger' has " +
                                std::to_string(ledger.size()) + " values, expected 6");
  ledger_ = {ledger[0], ledger[1], ledger[2], ledger[3], ledger[4], ledger[5], {}};
  // The particles removed through outflow faces so far (absent in checkpoints written before it).
  if (data.has(prefix + ".outflow")) {
    const auto& out = data.get(prefix + ".outflow");
    if (out.size() != ParticleOutflow{}.pack().size())
      throw std::invalid_argument(data.source() + ": checkpoint entry '" + prefix + ".outflow' has " +
                                  std::to_string(out.size()) + " values, expected " +
                                  std::to_string(ParticleOutflow{}.pack().size()));
    ledger_.outflow = ParticleOutflow::unpack(out);
  }
}

}  // namespace mpmice::mpm
