#version 450
// Test kernel: IEEE double arithmetic on the device (tests/engine/fp64_test.cpp compares every
// result with the CPU's).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Operands { dvec2 operands[]; };
// Per input: a+b, a-b, a*b, a/b, sqrt(a), and two padding slots (stride 8 doubles).
layout(std430, binding = 1) writeonly buffer Results { double results[]; };
layout(push_constant) uniform Push { uint count; } push;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  dvec2 o = operands[i];
  precise double add = o.x + o.y;
  precise double sub = o.x - o.y;
  precise double mul = o.x * o.y;
  precise double div = o.x / o.y;
  precise double root = sqrt(o.x);
  results[i * 8 + 0] = add;
  results[i * 8 + 1] = sub;
  results[i * 8 + 2] = mul;
  results[i * 8 + 3] = div;
  results[i * 8 + 4] = root;
}
