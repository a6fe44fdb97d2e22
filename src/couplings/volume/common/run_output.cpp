#include "couplings/volume/common/run_output.h"

namespace mpmice::coupler {

SideTotals SideTotals::unpack(const std::vector<double>& v) {
  SideTotals t;
  if (v.size() != 12) return t;
  t.mass = v[0];
  t.momentum = {v[1], v[2], v[3]};
  t.kinetic = v[4];
  t.internal = v[5];
  t.heat = v[6];
  t.transfer = v[7];
  t.integration = v[8];
  t.damping = v[9];
  t.massOut = v[10];
  t.energyOut = v[11];
  return t;
}

RunOutput::RunOutput(const core::Scene& scene, const core::Comm& comm, const core::Decomposition& decomp,
                     const std::string& suffix, bool writeCsv, const core::CheckpointData* resumed)
    : scene_(scene), enabled_(scene.output.enabled) {
  if (!enabled_) return;
  writer_ = std::make_unique<core::OutputWriter>(comm, decomp, scene.output.directory, scene.name + suffix);
  if (resumed) writer_->resumeIndex(resumed->text("run.xdmf"));
  if (writeCsv) {
    const std::string path = scene.output.directory + "/" + scene.name + "_conservation.csv";
    if (resumed)
      core::CsvWriter::cutForResume(comm, path, static_cast<std::int64_t>(resumed->scalar("run.conservation_csv")));
    csv_ = std::make_unique<core::CsvWriter>(
        comm, path,
        std::vector<std::string>{"step", "time", "solid_mass", "fluid_mass", "momentum_x", "momentum_y",
                                 "momentum_z", "solid_energy", "fluid_energy", "total_energy", "solid_kinetic",
                                 "solid_elastic", "solid_heat", "fluid_kinetic", "fluid_internal", "mpm_transfer",
                                 "mpm_stress_integration", "mpm_damping", "balance", "solid_mass_outflow",
                                 "solid_energy_outflow"},
        0, resumed ? core::CsvWriter::Mode::Append : core::CsvWriter::Mode::Truncate);
  }
}

void RunOutput::save(core::CheckpointData& data) const {
  data.putText("run.xdmf", writer_ ? writer_->index().serialize() : std::string());
  data.put("run.conservation_csv", static_cast<double>(csv_ ? csv_->length() : 0));
}

void RunOutput::writeFields(long step, double time, const std::vector<const core::Field*>& fields,
                            const core::ParticleOutput* particles) {
  if (!enabled_) return;
  writer_->writeStep(static_cast<int>(step), time, fields, scene_.output.particles ? particles : nullptr);
}

void RunOutput::writeTotals(long step, double time, const SideTotals& s, const SideTotals& f) {
  if (!enabled_ || !csv_) return;
  const double total = s.energy() + f.energy(), created = s.created() + f.created();
  csv_->row({double(step), time, s.mass, f.mass, s.momentum[0] + f.momentum[0], s.momentum[1] + f.momentum[1],
             s.momentum[2] + f.momentum[2], s.kinetic + s.internal, f.energy(), total, s.kinetic, s.internal, s.heat,
             f.kinetic, f.internal, s.transfer, s.integration, s.damping, total - created, s.massOut,
             s.energyOut});
}

}  // namespace mpmice::coupler
