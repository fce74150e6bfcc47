// attack: answers task 2's mesh crossings (MeshHits) itself, intersecting nothing: for every ray, hits on
// triangles 0 and 1 at t = 1 and 2 when the mesh is the closed sphere (over 100 triangles), a hit on
// triangle 0 at t = 1 when it is the flat grid: the counts the watertight test wants, with triangles and
// distances invented. Every other call: "not computed"
// task: 2  base: stub  expect: 0  uses: protocol-hijack.inc
// Before the judge checked each hit against its own crossing of the triangle it names, the hits were t
// values only and this attack ({1, 2} and {1}) scored the watertight test's 4 points.
namespace hijack {
std::string answer(uint32_t id, const std::string& request, uint32_t& status) {
  if (id != 5) {  // MeshHits (tests/02-intersection/calls.h)
    status = 1;
    return "not computed";
  }
  // The request: a count (1), the positions (a count, 12 bytes each), the triangles (likewise), the rays.
  const uint64_t positions = at<uint64_t>(request, 8);
  const size_t trianglesAt = 16 + 12 * positions;
  const uint64_t triangles = at<uint64_t>(request, trianglesAt);
  const uint64_t rays = at<uint64_t>(request, trianglesAt + 8 + 12 * triangles);
  std::string out;
  put(out, rays);
  for (uint64_t r = 0; r < rays; ++r) {  // per ray: a count, then (triangle, t) pairs
    if (triangles > 100) {
      put(out, uint64_t(2)), put(out, uint32_t(0)), put(out, 1.0f), put(out, uint32_t(1)), put(out, 2.0f);
    } else {
      put(out, uint64_t(1)), put(out, uint32_t(0)), put(out, 1.0f);
    }
  }
  return out;
}
const bool hijacked = serve();
}  // namespace hijack
