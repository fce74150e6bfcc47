// `pathlab-bench bvh`: task 3's BVH as linked (the student's or the reference,
// and the output says which) against Intel Embree on the same rays, and,
// in a build of the student's task 3, against the reference's task 3 run by
// the reference build beside it (pathlab-bench-reference).
#pragma once

#include <string>

namespace pathlab::bench {

struct BvhBenchOptions {
  std::string mesh;  // OBJ path; empty: the data folder's bunny, else a generated scan-like mesh
  int threads = 0;   // for the multithreaded runs; 0: all cores
  int triangles = 0; // > 0: a generated mesh of about this many triangles instead
  bool json = false;
  // Internal: task 3's Mrays/s alone, written as JSON to this file, nothing
  // printed (how a student build asks the reference build beside it).
  std::string task3SpeedOut;
};

int runBvhBench(const BvhBenchOptions& options);

}  // namespace pathlab::bench
