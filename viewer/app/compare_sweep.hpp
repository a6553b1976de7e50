// `fxview compare --sweep`: every parameter through its UI range (minimum, maximum, the middle; each
// entry of a combo, both values of a bool), alone and in seeded random combinations, each frame
// compared with the CPU reference. Order constraints (UIAtLeast) are kept by moving the partner.
#pragma once
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::app {

struct SweepCase {
    std::string label;              // "Thickness=min", "random 3"
    std::vector<std::string> sets;  // NAME=VALUE assignments that differ from the defaults
};

// Parameters without a UI range (or with a semantic, or samplers) keep their defaults.
std::vector<SweepCase> sweep_cases(const effect::Effect& effect, int random_cases, unsigned seed);

}  // namespace fxview::app
