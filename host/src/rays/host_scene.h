// boreas: the ray structure read back (RayScene::HostCopy) as the scene the traversal
// (cl/shared/ray_cast.h) walks in C++: for the native twin (bench/native_rays.cpp) and the
// tests that check it against the kernel. The copy must outlive the scene.
#pragma once

#include "rays/ray_scene.h"

// The traversal compiled on the host takes the polynomial math the CPU kernels take.
#ifndef BOREAS_FAST_MATH
#define BOREAS_FAST_MATH 1
#endif
#include "shared/ray_cast.h"

namespace boreas::impl {

inline BoreasRayScene host_scene(const RayScene::HostCopy& c) {
  BoreasRayScene s;
  s.top = c.top.data();
  s.top_items = c.top_items.data();
  s.top_root = c.top_root;
  s.wide = c.wide.data();
  s.items = c.items.data();
  s.instances = c.instances.data();
  s.branches = c.branches.data();
  s.shapes = c.shapes.data();
  s.records = c.records.data();
  s.positions = c.positions.data();
  s.trunks = c.trunks.data();
  s.crowns = c.crowns.data();
  s.strips = c.strips.data();
  s.ints = c.ints.data();
  return s;
}

}  // namespace boreas::impl
