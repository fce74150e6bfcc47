// attack: builds a valid tree itself (a median split), so that task 3's traversal tests are reached, and
// answers every traversal whose primitive tests the judge serves with found flags and counts it invents:
// "blocked" for every shadow ray, "no hit" for every closest-hit ray, each with one node visited and no test;
// for a lone ray over a small tree it asks for every slot once and claims "no hit" and the tree's size as
// its counts, whatever the judge's replies said. Every other call: "not computed"
// task: 3  base: stub  expect: 5  uses: protocol-hijack.inc
// 5 is what its honest part alone earns: measured with kLie = false below (the same tree, every traversal
// refused), this file graded by tools/grade --tasks 3: T3.2 "every primitive in exactly one leaf" (4) and
// "spaced ever wider apart" (1); the other tests need a traversal, a slab test or SAH's cost. With its lies,
// it scored 10 before the judge checked traversals' claims against the tests it served (issue 79).
#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>
namespace hijack {
constexpr bool kLie = true;  // false: the honest part alone

// BuildBvh: a count (1), then the boxes (a count, six floats each); the answer a Bvh (grader/wire/wire.h).
std::string tree(const std::string& request) {
  const uint64_t n = at<uint64_t>(request, 8);
  std::vector<pathlab::Aabb> boxes(n);
  for (uint64_t i = 0; i < n; ++i) {
    const size_t at0 = 16 + 24 * i;
    boxes[i].min = {at<float>(request, at0), at<float>(request, at0 + 4), at<float>(request, at0 + 8)};
    boxes[i].max = {at<float>(request, at0 + 12), at<float>(request, at0 + 16), at<float>(request, at0 + 20)};
  }
  std::vector<uint32_t> slots(n);
  std::iota(slots.begin(), slots.end(), 0u);
  std::vector<pathlab::BvhNode> nodes;
  if (n > 0) nodes.push_back({pathlab::Aabb{}, 0, uint32_t(n)});
  for (size_t k = 0; k < nodes.size(); ++k) {  // each node in turn: its box, then halves by the median centroid
    const uint32_t first = nodes[k].leftOrFirst, count = nodes[k].count;
    pathlab::Aabb box, centroids;
    for (uint32_t s = first; s < first + count; ++s) box.grow(boxes[slots[s]]), centroids.grow(boxes[slots[s]].centroid());
    nodes[k].bounds = box;
    if (count <= pathlab::kMaxLeafSize) continue;
    const int axis = centroids.largestAxis();
    std::nth_element(slots.begin() + first, slots.begin() + first + count / 2, slots.begin() + first + count,
                     [&](uint32_t a, uint32_t b) { return boxes[a].centroid()[axis] < boxes[b].centroid()[axis]; });
    nodes[k].leftOrFirst = uint32_t(nodes.size());
    nodes[k].count = 0;
    nodes.push_back({pathlab::Aabb{}, first, count / 2});
    nodes.push_back({pathlab::Aabb{}, first + count / 2, count - count / 2});
  }
  std::string out;
  put(out, uint64_t(nodes.size()));
  for (const pathlab::BvhNode& node : nodes) {
    for (int a = 0; a < 3; ++a) put(out, node.bounds.min[a]);
    for (int a = 0; a < 3; ++a) put(out, node.bounds.max[a]);
    put(out, node.leftOrFirst), put(out, node.count);
  }
  put(out, n);
  for (uint32_t s : slots) put(out, s);
  return out;
}

// One ask of the judge (grader/wire/protocol.h): ray 0's test of `slot` over [0, inf); the reply is read and
// ignored.
void askFor(uint32_t slot) {
  std::string question;
  put(question, uint32_t(0)), put(question, slot), put(question, 0.0f), put(question, std::numeric_limits<float>::infinity());
  const Header ask{0x53455250u, 4u, question.size()};
  writeAll(4, &ask, sizeof ask);
  writeAll(4, question.data(), question.size());
  Header reply;
  if (!readAll(3, &reply, sizeof reply)) _exit(0);
  std::string ignored(reply.size, '\0');
  if (!readAll(3, ignored.data(), ignored.size())) _exit(0);
}

// TraverseServed: a count (1), the tree, the scene, the rays (a count, then a Ray and an Interval: 32 bytes
// each), whether any hit. The rays' count is found from the end: the count just before that many rays.
std::string traverse(const std::string& request) {
  const uint64_t nodes = at<uint64_t>(request, 8), slots = at<uint64_t>(request, 16 + 32 * nodes);
  const bool anyHit = request.back() == 1;
  uint64_t rays = 0;
  for (uint64_t k = 0; 17 + 32 * k <= request.size(); ++k) {
    if (at<uint64_t>(request, request.size() - 9 - 32 * k) == k) {
      rays = k;
      break;
    }
  }
  const bool alone = rays == 1 && slots <= 64;
  if (alone)
    for (uint32_t s = 0; s < slots; ++s) askFor(s);
  std::string out;
  put(out, rays);
  for (uint64_t r = 0; r < rays; ++r) {
    out.push_back(alone ? 0 : anyHit);
    put(out, uint32_t(alone ? nodes : 1)), put(out, uint32_t(alone ? nodes : 1)), put(out, uint32_t(alone ? slots : 0));
  }
  return out;
}

std::string answer(uint32_t id, const std::string& request, uint32_t& status) {
  if (id == 2) return tree(request);                  // BuildBvh (tests/03-bvh/calls.h)
  if (id == 5 && kLie) return traverse(request);      // TraverseServed
  status = 1;
  return "not computed";
}
const bool hijacked = serve();
}  // namespace hijack
