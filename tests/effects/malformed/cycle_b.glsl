// part of include_cycle.fx
#include "cycle_a.glsl"
