#version 460
// Two loops in one invocation, each `iterations.x` long. A device that runs
// every loop to its end counts both in full; llvmpipe ends every loop once
// the invocation's loops have run LP_MAX_TGSI_LOOP_ITERATIONS (65535) times
// between them (test LavapipeLimits.LoopsShareOneIterationBudget).
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer Counts { uint counts[3]; };  // [2] = 1, the step
layout(push_constant) uniform Push { uvec4 iterations; };

void main() {
    // The step comes from memory so the compiler cannot fold a loop into a product.
    uint step = counts[2];
    uint first = 0u, second = 0u;
    for (uint i = 0u; i < iterations.x; ++i) first += step;
    for (uint i = 0u; i < iterations.x; ++i) second += step;
    counts[0] = first;
    counts[1] = second;
}
