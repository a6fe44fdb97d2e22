#pragma once
/// @brief output.fields: which grid fields and particle arrays a program writes.
///
/// An empty list writes everything. An entry selects a field named exactly so, or, for the
/// per-material fields of a fluid solver, every "<material>_<entry>" ("velocity" selects
/// air_velocity and water_velocity; "air_velocity" selects one). Particle positions are always
/// written. A standalone program refuses an entry that selects nothing it offers (the error lists
/// what it offers); a coupled program writes its side's part of the list (the other side's
/// entries select nothing here and are the peer's to write).
#include <string>
#include <vector>

#include "core/field/field.h"
#include "core/io/particle_output.h"

namespace mpmice::core {

/// Whether `name` is selected by `wanted` (prefixes: the material names of per-material fields).
bool outputSelected(const std::vector<std::string>& wanted, const std::string& name,
                    const std::vector<std::string>& prefixes = {});

/// The selected fields of `all`.
std::vector<Field> selectFields(std::vector<Field> all, const std::vector<std::string>& wanted,
                                const std::vector<std::string>& prefixes = {});

/// The selected particle arrays (positions always).
ParticleOutput selectParticles(ParticleOutput all, const std::vector<std::string>& wanted);

/// Throws std::invalid_argument naming `program` and the valid names when an entry of `wanted`
/// selects none of `offered` (full field names).
void checkOutputFields(const std::vector<std::string>& wanted, const std::vector<std::string>& offered,
                       const std::vector<std::string>& prefixes, const std::string& program);

}  // namespace mpmice::core
