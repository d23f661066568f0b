// Private to cpp/src/simulate: the checks of simulate's and step's options, shared by the runs of bodies and scenes.
#pragma once
#include "rigiddyn/simulate/simulate.hpp"

#include <cstdint>

namespace rigiddyn {

// Throws std::invalid_argument naming the argument for dt <= 0, non-finite t0 or gravity, a bad load,
// and (stepping: simulate, not step) steps < 0 or record_every < 1.
void check_options(const SimulationOptions& o, bool stepping);

// Throws std::invalid_argument naming record_every when a recording of `bytes` [B] (steps recorded every
// record_every-th) exceeds the memory available.
void check_recording_fits(double bytes, std::int64_t steps, std::int64_t record_every);

}  // namespace rigiddyn
