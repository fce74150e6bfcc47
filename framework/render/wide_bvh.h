// The framework's render path (--accel fast): task 3's binary tree collapsed
// into an 8-wide tree whose eight child boxes are tested together (AVX2 where
// the CPU has it, else four at a time), with the triangles of each leaf (at
// most eight) stored in one packet and tested together, as Embree lays out
// its own, and its spheres four to a packet. The packet tests are the reference task 2's
// watertight triangle test (pbrt-v4) and sphere test, done lane by lane with
// the same arithmetic, so the hits are task 3's; the rare ray exactly on a
// triangle's edge goes to the linked task 2 through its table. Use it where
// task 2 is the reference (defaultTraversal in accelerator.h decides); the
// tree must have passed validateBvh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/hit.h"
#include "core/leaf_geometry.h"
#include "core/scene.h"
#include "core/task_functions.h"
#include "tasks/bvh.h"

namespace pathlab {

class WideBvh {
 public:
  WideBvh() = default;
  // `geometry` holds `bvh`'s primitives in leaf order (LeafGeometry(scene,
  // bvh.primitives, ...)); `tests` are task 2's (kLinkedTasks.primitives),
  // for rays on a triangle's edge.
  //
  // The box and triangle tests use AVX2 (eight per instruction) where the
  // CPU has it, else the baseline: SSE2 (four at a time), or plain code off x86.
  // Both give the same hits; Baseline forces the second (for tests).
  enum class Instructions { Best, Baseline };
  WideBvh(const Bvh& bvh, const LeafGeometry& geometry, const PrimitiveTests& tests,
          Instructions instructions = Instructions::Best);

  // The same answers as task 3's intersectClosest / intersectAny over `bvh`.
  std::optional<PrimitiveHit> intersectClosest(const Ray& ray, Interval range) const;
  bool intersectAny(const Ray& ray, Interval range) const;

  bool usesAvx2() const { return avx2_; }
  size_t nodeCount() const { return nodes_.size(); }
  size_t packetCount() const { return packets_.size(); }
  size_t spherePacketCount() const { return spherePackets_.size(); }
  // Share of packet lanes that hold a triangle (empty lanes cost as much).
  double laneOccupancy() const;

  // Up to kWidth children: their boxes one lane each (structure of arrays, so
  // one load gives an axis of four or eight children), and what each child is.
  static constexpr int kWidth = 8;
  struct alignas(32) Node {
    float bounds[6][kWidth];   // min x, min y, min z, max x, max y, max z; lane = child
    uint32_t child[kWidth];    // a node index, or kLeaf | index into leaves_
    uint32_t count = 0;        // children in use, lanes [0, count)
  };
  // Up to eight triangles, vertex by vertex and axis by axis (tested eight
  // at a time with AVX2, else four and four).
  static constexpr int kPacketSize = 8;
  struct alignas(32) TrianglePacket {
    float vertex[3][3][kPacketSize];  // [vertex][axis][lane]
    uint32_t primitive[kPacketSize];  // scene primitive of each lane
    uint32_t lanes = 0;               // bit l: lane l holds a triangle with non-zero area
    uint32_t unused[7] = {};
  };
  // Up to four spheres, axis by axis.
  struct alignas(16) SpherePacket {
    float center[3][4];      // [axis][lane]
    float radius[4];
    uint32_t primitive[4];   // scene primitive of each lane
    uint32_t lanes = 0;      // bit l: lane l holds a sphere
    uint32_t unused[3] = {};
  };
  // A leaf of task 3's tree: its triangles as packets, then its spheres.
  struct Leaf {
    uint32_t firstPacket, packetCount, firstSpherePacket, spherePacketCount;
  };
  static constexpr uint32_t kLeaf = 1u << 31;
  static constexpr int kSpherePacketSize = 4;

 private:
  struct Walk;  // the traversals (wide_bvh.cpp)
  void collapse(const Bvh& bvh, const LeafGeometry& geometry, const std::vector<uint32_t>& below, uint32_t wide,
                uint32_t binary);
  uint32_t addLeaf(const Bvh& bvh, const LeafGeometry& geometry, uint32_t subtree);

  std::vector<Node> nodes_;
  std::vector<TrianglePacket> packets_;
  std::vector<SpherePacket> spherePackets_;
  std::vector<Leaf> leaves_;
  PrimitiveTests tests_;
  bool avx2_ = false;
};

}  // namespace pathlab
