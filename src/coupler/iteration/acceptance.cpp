#include "coupler/iteration/acceptance.h"

namespace mpmice::coupler {

bool stepAccepted(int iteration, int minIterations, std::span<const MeasureOutcome> outcomes) {
  if (iteration < minIterations || outcomes.empty()) return false;
  bool all = true, suffices = false, strictFails = false;
  for (const MeasureOutcome& o : outcomes) {
    all = all && o.holds;
    if (o.strict && !o.holds) strictFails = true;
    if (!o.strict && o.holds) suffices = true;
  }
  return all || (suffices && !strictFails);
}

}  // namespace mpmice::coupler
