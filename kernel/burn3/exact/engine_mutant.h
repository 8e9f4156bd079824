// engine_mutant.h -- deliberate breakages of the exact burning engine itself (not of its
// output), selected through ExactBurningOptions::mutant, so that the checks of the engine
// (closed-form tests, the proof-check report's exact-engine rows) can show that they detect
// a wrong junction rule (4.2.1, Definition 9) or a wrong pseudo-source rule (4.2.2).
// Each mutant changes one decision of the engine:
//  - kth_arrival: a singular edge with k sides burns at the k-th arrival (Definition 9 says
//    the (k-1)-th);
//  - first_arrival: ... at the first arrival;
//  - no_kink_emission: kink points of the junction rule emit no point source;
//  - mirrored_rotation: a piece continued across a singular edge enters the other sides
//    mirrored across the edge (the rotation about the edge replaced by a reflection of the
//    source through the edge's line in the entered sheet's frame);
//  - sampled_crossings: the crossings of two arrivals along an edge found from sign changes
//    at 32 samples (the engine's behaviour before certified isolation);
//  - double_bending: whether a fan bends decided by a double sum of atan2 with a 1e-6
//    margin (no certified stage).
// Contract: none is the engine; the others are for checks only (never for results).
#pragma once

#include <cstdint>

namespace grassfire {

enum class EngineMutant : std::uint8_t {
  none,
  kth_arrival,
  first_arrival,
  no_kink_emission,
  mirrored_rotation,
  sampled_crossings,
  double_bending
};

// "engine-kth-arrival", ... (the proof-check report's names).
inline const char* engine_mutant_name(EngineMutant m) {
  switch (m) {
    case EngineMutant::none: return "engine-none";
    case EngineMutant::kth_arrival: return "engine-kth-arrival";
    case EngineMutant::first_arrival: return "engine-first-arrival";
    case EngineMutant::no_kink_emission: return "engine-no-kink-emission";
    case EngineMutant::mirrored_rotation: return "engine-mirrored-rotation";
    case EngineMutant::sampled_crossings: return "engine-sampled-crossings";
    case EngineMutant::double_bending: return "engine-double-bending";
  }
  return "engine-?";
}

}  // namespace grassfire
