#pragma once
/// @brief The CFL signal speed of elastic particles: the largest P-wave speed plus particle speed.
#include <cstddef>

#include "mpm/particles/particle_set.h"

namespace mpmice::mpm {

/// ConstitutiveModel::maxSignalSpeed for the P-wave speed sqrt(M / rho) of a modulus M (K + 4 G / 3):
/// the max over particles [begin, end) of sqrt(M / (m / V)) + |v| (the first `dim` velocity
/// components), 0 for an empty range; `*arg` (when asked for) the first particle reaching it (end
/// if none).
double maxElasticSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg,
                             double modulus);
/// The same with each particle's modulus: denseModulus where V <= denseRatio V0 (a crushable foam
/// compacted to its solid), `modulus` elsewhere.
double maxTwoModulusSignalSpeed(const ParticleSet& p, std::size_t begin, std::size_t end, int dim, std::size_t* arg,
                                double modulus, double denseModulus, double denseRatio);

}  // namespace mpmice::mpm
