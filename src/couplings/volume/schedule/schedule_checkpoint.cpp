// The partitioned schedules' restart state: whether the first (serial-order) step is done, and
// for the implicit ones the acceleration's history (coupler/acceleration: IQN-ILS columns, QR).
#include "couplings/volume/schedule/explicit_schedule.h"
#include "couplings/volume/schedule/implicit_schedule.h"

namespace mpmice::coupler {

void ExplicitSchedule::save(core::CheckpointData& data, const std::string& prefix) const {
  data.put(prefix + ".first", first_ ? 1.0 : 0.0);
}

void ExplicitSchedule::load(const core::CheckpointData& data, const std::string& prefix) {
  first_ = data.scalar(prefix + ".first") != 0.0;
}

void ImplicitSchedule::save(core::CheckpointData& data, const std::string& prefix) const {
  data.put(prefix + ".first", first_ ? 1.0 : 0.0);
  iteration_.save(data, prefix + ".acceleration");
}

void ImplicitSchedule::load(const core::CheckpointData& data, const std::string& prefix) {
  first_ = data.scalar(prefix + ".first") != 0.0;
  iteration_.load(data, prefix + ".acceleration");
}

}  // namespace mpmice::coupler
