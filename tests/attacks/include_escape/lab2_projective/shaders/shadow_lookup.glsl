// Attack: the solution's lookup, included from outside the labs tree by a
// relative path that climbs out of it.
#include "@RELATIVE_SOURCE_DIR@/solutions/lab2_projective/shaders/shadow_lookup.glsl"
