#pragma once
// Quadtree node addressing: face (0..29), level (0 = the whole rhombus), and the cell (x, y) of the
// 2^level × 2^level grid over the face's (u, v) square. x grows along u (corner 0 -> corner 1),
// y along v (corner 0 -> corner 3). Packs into a 64-bit key for hashing.
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>

#include "planet/core/hash.h"

namespace globe {

// Deepest addressable level: x and y need `level` bits each and the key has 54 bits for them.
inline constexpr int kMaxNodeLevel = 26;

// 2^-level as an exact double (level 0..kMaxNodeLevel + 1): cheaper than std::ldexp in hot loops.
inline constexpr std::array<double, 64> kInversePowersOfTwo = [] {
  std::array<double, 64> table{};
  double value = 1.0;
  for (double& t : table) {
    t = value;
    value *= 0.5;
  }
  return table;
}();
inline double inversePowerOfTwo(int level) { return kInversePowersOfTwo[static_cast<size_t>(level)]; }

// Node edge directions; equal to the face edge numbering (edge e runs from corner e to corner e+1).
enum NodeEdge : int { kEdgeMinusV = 0, kEdgePlusU = 1, kEdgePlusV = 2, kEdgeMinusU = 3 };

struct NodeId {
  uint8_t face = 0;   // 0..29
  uint8_t level = 0;  // 0..kMaxNodeLevel
  uint32_t x = 0;     // 0 .. 2^level - 1, along u
  uint32_t y = 0;     // 0 .. 2^level - 1, along v

  // face:5 | level:5 | x:27 | y:27 (most significant first). A bijection on valid ids.
  uint64_t key() const { return (uint64_t{face} << 59) | (uint64_t{level} << 54) | (uint64_t{x} << 27) | uint64_t{y}; }
  static NodeId fromKey(uint64_t key) {
    return {static_cast<uint8_t>(key >> 59), static_cast<uint8_t>((key >> 54) & 31u),
            static_cast<uint32_t>((key >> 27) & ((1u << 27) - 1)), static_cast<uint32_t>(key & ((1u << 27) - 1))};
  }

  bool isValid() const;
  uint32_t cellsPerSide() const { return uint32_t{1} << level; }
  // Quadrant within the parent: bit 0 = upper half in u, bit 1 = upper half in v.
  int quadrant() const { return static_cast<int>((x & 1u) | ((y & 1u) << 1)); }
  NodeId parent() const {  // requires level > 0
    assert(level > 0);
    return {face, static_cast<uint8_t>(level - 1), x >> 1, y >> 1};
  }
  NodeId child(int q) const {  // requires level < kMaxNodeLevel
    assert(level < kMaxNodeLevel && q >= 0 && q < 4);
    return {face, static_cast<uint8_t>(level + 1), (x << 1) | static_cast<uint32_t>(q & 1),
            (y << 1) | static_cast<uint32_t>((q >> 1) & 1)};
  }
  NodeId ancestor(int atLevel) const;            // requires atLevel <= level
  bool isAncestorOf(const NodeId& other) const;  // strict ancestor

  // The node's (u, v) square on its face: exact dyadic numbers.
  double uMin() const { return static_cast<double>(x) * inversePowerOfTwo(level); }
  double vMin() const { return static_cast<double>(y) * inversePowerOfTwo(level); }
  double size() const { return inversePowerOfTwo(level); }

  friend bool operator==(const NodeId&, const NodeId&) = default;
};

// The node at the same level across `edge` (a NodeEdge), on this face or across a face seam.
NodeId edgeNeighbour(const NodeId& node, int edge);

struct NodeIdHash {
  size_t operator()(const NodeId& id) const {
    return static_cast<size_t>(mix64(id.key()));  // keys differ in few bits
  }
};

}  // namespace globe
