// Building the render path's 8-wide tree (wide_bvh.h) from task 3's binary
// tree: which binary nodes become one wide node, and the leaves' packets.
// The walks are in wide_bvh.cpp.
#include <array>
#include <bit>

#include "core/leaf_geometry.h"
#include "render/wide_bvh.h"

namespace pathlab {
namespace {

float surfaceArea(const Aabb& box) {
  const Vec3 e = box.extent();
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace

// Wide node `wide` takes the place of binary interior node `binary`: start
// from its two children and open the largest interior child until there
// are kWidth (the surface area says which box rays reach most often). A
// subtree of at most kPacketSize (8) primitives becomes one leaf, so its
// triangles fill one packet, tested at once, instead of several.
void WideBvh::collapse(const Bvh& bvh, const LeafGeometry& geometry, const std::vector<uint32_t>& below,
                       uint32_t wide, uint32_t binary) {
  auto opens = [&](uint32_t n) { return !bvh.nodes[n].isLeaf() && below[n] > kPacketSize; };
  std::array<uint32_t, kWidth> children;
  std::array<float, kWidth> openArea;  // surface area of a child that can be opened, else -1
  uint32_t count = 0;
  auto addChild = [&](uint32_t k, uint32_t n) {
    children[k] = n;
    openArea[k] = opens(n) ? surfaceArea(bvh.nodes[n].bounds) : -1.0f;
  };
  addChild(count++, bvh.nodes[binary].leftOrFirst);
  addChild(count++, bvh.nodes[binary].leftOrFirst + 1);
  while (count < kWidth) {
    uint32_t largest = 0;
    for (uint32_t k = 1; k < count; ++k) {
      if (openArea[k] > openArea[largest]) largest = k;
    }
    if (openArea[largest] < 0.0f) break;
    const uint32_t opened = bvh.nodes[children[largest]].leftOrFirst;
    addChild(largest, opened);
    addChild(count++, opened + 1);
  }
  Node node{};
  node.count = count;
  for (uint32_t k = 0; k < count; ++k) {
    const BvhNode& child = bvh.nodes[children[k]];
    for (int axis = 0; axis < 3; ++axis) {
      node.bounds[axis][k] = child.bounds.min[axis];
      node.bounds[axis + 3][k] = child.bounds.max[axis];
    }
    if (openArea[k] >= 0.0f) {
      node.child[k] = uint32_t(nodes_.size());
      nodes_.emplace_back();
    } else {
      node.child[k] = kLeaf | addLeaf(bvh, geometry, children[k]);
    }
  }
  nodes_[wide] = node;
  for (uint32_t k = 0; k < count; ++k) {
    if (!(node.child[k] & kLeaf)) collapse(bvh, geometry, below, node.child[k], children[k]);
  }
}

// One leaf holding every primitive below binary node `subtree`, in the
// order task 3's leaves list them (read from `geometry`, which holds them in
// that order: one pass through memory, no lookups in the scene).
uint32_t WideBvh::addLeaf(const Bvh& bvh, const LeafGeometry& geometry, uint32_t subtree) {
  Leaf out{uint32_t(packets_.size()), 0, uint32_t(spherePackets_.size()), 0};
  int lane = kPacketSize, sphereLane = kSpherePacketSize;
  auto add = [&](const LeafGeometry::Slot& slot) {
    if (slot.isSphere) {
      if (sphereLane == kSpherePacketSize) {
        spherePackets_.emplace_back();
        ++out.spherePacketCount;
        sphereLane = 0;
      }
      SpherePacket& packet = spherePackets_.back();
      for (int axis = 0; axis < 3; ++axis) packet.center[axis][sphereLane] = slot.a[axis];
      packet.radius[sphereLane] = slot.b.x;
      packet.primitive[sphereLane] = slot.primitive;
      packet.lanes |= 1u << sphereLane++;
      return;
    }
    if (lane == kPacketSize) {
      packets_.emplace_back();
      ++out.packetCount;
      lane = 0;
    }
    TrianglePacket& packet = packets_.back();
    const Point3 p[3] = {slot.a, slot.b, slot.c};
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) packet.vertex[k][axis][lane] = p[k][axis];
    }
    packet.primitive[lane] = slot.primitive;
    // A zero-area triangle has no normal, and the reference never reports a hit on it.
    const Vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f) packet.lanes |= 1u << lane;
    ++lane;
  };
  uint32_t stack[kMaxBvhDepth + 1];  // not zeroed: only [0, size) is read
  stack[0] = subtree;
  for (int size = 1; size > 0;) {
    const BvhNode& node = bvh.nodes[stack[--size]];
    if (!node.isLeaf()) {
      stack[size++] = node.leftOrFirst + 1;
      stack[size++] = node.leftOrFirst;
      continue;
    }
    for (uint32_t slot = node.leftOrFirst; slot < node.leftOrFirst + node.count; ++slot) add(geometry.slot(slot));
  }
  leaves_.push_back(out);
  return uint32_t(leaves_.size() - 1);
}

double WideBvh::laneOccupancy() const {
  size_t used = 0;
  for (const TrianglePacket& p : packets_) used += size_t(std::popcount(p.lanes));
  return packets_.empty() ? 0.0 : double(used) / double(kPacketSize * packets_.size());
}

}  // namespace pathlab
