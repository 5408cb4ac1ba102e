// Attack: the solution's bias, included by its absolute path.
#include "@SOURCE_DIR@/solutions/lab3_bias/shaders/bias.glsl"
