// part of include_cycle.fx
#include "cycle_b.glsl"
