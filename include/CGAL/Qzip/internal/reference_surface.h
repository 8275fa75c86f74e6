// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_REFERENCE_SURFACE_H
#define CGAL_QZIP_INTERNAL_REFERENCE_SURFACE_H

#include <CGAL/license/Qzip.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// A triangulated surface that answers closest-point queries exactly as `CGAL::AABB_tree::closest_point(p)`
// does (the closest point of the triangles), but that first tries a uniform grid of cells (hashed into
// buckets) around the triangle of a previous answer (the hint): when the sphere through that triangle's
// closest point spans a few cells and a single point is closest among the triangles of their buckets, it is
// the tree's answer. Other queries (a large sphere, two closest points at the same distance, where the
// tree's answer depends on its order) go to the tree, from the hint triangle's closest point. A query without
// a hint takes a triangle of the grid near it as one, so that the tree never needs the k-d tree with which
// it would find hints itself (built at its first query without one: seconds on a million quads).
template <typename GeomTraits>
class Reference_surface
{
  typedef typename GeomTraits::Point_3 Point;
  typedef typename GeomTraits::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Triangle_iterator;
  typedef CGAL::AABB_triangle_primitive<GeomTraits, Triangle_iterator> Primitive;
  typedef CGAL::AABB_traits<GeomTraits, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

  static constexpr int max_cells_per_query = 8;

  std::vector<Triangle> triangles;
  std::unique_ptr<Tree> tree;
  // the grid: cells of side `cell` from `origin`, hashed into 2^bucket_bits buckets; a bucket lists the
  // triangles whose bounding box meets one of its cells (bucket_begin: compressed rows), each with its
  // bounding box (rounded outwards to floats: read in sequence, without visiting the triangle)
  double origin[3] = { 0, 0, 0 };
  double cell = 1;
  long long last_cell[3] = { 0, 0, 0 };
  int bucket_bits = 0;
  struct Entry
  {
    float min[3], max[3];
    std::uint32_t triangle;
  };
  std::vector<std::uint32_t> bucket_begin;
  std::vector<Entry> bucket_entries;
  // a triangle lies in the buckets of all the cells its box meets: one query reaches it once (the round
  // of the query that reached it last; so queries, const as they are, must not run concurrently)
  mutable std::vector<std::uint32_t> reached_in;
  mutable std::uint32_t query_round = 0;

  static float round_down(double x)
  {
    const float f = float(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  }
  static float round_up(double x)
  {
    const float f = float(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  }

  // the cell of coordinate x along `axis`, clamped to the cells of the triangles' bounding box (the others
  // hold no triangle)
  long long cell_index(double x, int axis) const
  {
    const double t = (x - origin[axis]) / cell;
    if(!(t > 0)) return 0;
    return t < double(last_cell[axis]) ? (long long)(t) : last_cell[axis];
  }

  std::size_t bucket(long long i, long long j, long long k) const
  {
    const std::uint64_t key = (std::uint64_t(i) << 42) | (std::uint64_t(j) << 21) | std::uint64_t(k);
    return std::size_t((key * 0x9E3779B97F4A7C15ULL) >> (64 - bucket_bits));
  }

  template <typename F>
  void for_each_cell(const Bbox_3& b, F f) const
  {
    for(long long i = cell_index(b.xmin(), 0); i <= cell_index(b.xmax(), 0); ++i)
      for(long long j = cell_index(b.ymin(), 1); j <= cell_index(b.ymax(), 1); ++j)
        for(long long k = cell_index(b.zmin(), 2); k <= cell_index(b.zmax(), 2); ++k)
          f(bucket(i, j, k));
  }

  // the tree's answer, searched from the closest point to p of the hint triangle (a point of the surface, as
  // the tree requires of a hint); the hint becomes the triangle of the answer
  Point fallback(const Point& p, std::size_t& hint) const
  {
    const Triangle_iterator t = triangles.begin() + std::ptrdiff_t(hint - 1);
    const auto r = tree->closest_point_and_primitive(p, std::make_pair(GeomTraits().construct_projected_point_3_object()(*t, p), t));
    hint = std::size_t(r.second - triangles.begin()) + 1;
    return r.first;
  }

  // a hint for a query without one: a triangle of the bucket of p's cell (the first triangle if it has none)
  std::size_t triangle_near(const Point& p) const
  {
    const std::size_t b = bucket(cell_index(CGAL::to_double(p.x()), 0), cell_index(CGAL::to_double(p.y()), 1),
                                 cell_index(CGAL::to_double(p.z()), 2));
    return bucket_begin[b] < bucket_begin[b + 1] ? std::size_t(bucket_entries[bucket_begin[b]].triangle) + 1 : 1;
  }

public:
  // adds the triangle (a, b, c) unless it is degenerate; returns 1 + its index, or 0
  std::size_t add(const Point& a, const Point& b, const Point& c)
  {
    const Triangle t(a, b, c);
    if(GeomTraits().is_degenerate_3_object()(t)) return 0;
    triangles.push_back(t);
    return triangles.size();
  }

  bool empty() const { return triangles.empty(); }

  void build()
  {
    if(triangles.empty()) return;
    tree.reset(new Tree(triangles.begin(), triangles.end()));
    tree->do_not_accelerate_distance_queries(); // every query has a hint (see triangle_near())
    tree->build();
    std::vector<Bbox_3> boxes;
    boxes.reserve(triangles.size());
    Bbox_3 all;
    double extent = 0;
    for(const Triangle& t : triangles)
    {
      boxes.push_back(t.bbox());
      all += boxes.back();
      extent += (std::max)({ boxes.back().xmax() - boxes.back().xmin(), boxes.back().ymax() - boxes.back().ymin(),
                             boxes.back().zmax() - boxes.back().zmin() });
    }
    origin[0] = all.xmin(); origin[1] = all.ymin(); origin[2] = all.zmin();
    cell = extent / double(triangles.size());
    const double span = (std::max)({ all.xmax() - all.xmin(), all.ymax() - all.ymin(), all.zmax() - all.zmin() });
    cell = (std::max)(cell, span / double(1LL << 20)); // every index within 21 bits
    if(!(cell > 0)) cell = 1;
    last_cell[0] = (long long)((all.xmax() - origin[0]) / cell);
    last_cell[1] = (long long)((all.ymax() - origin[1]) / cell);
    last_cell[2] = (long long)((all.zmax() - origin[2]) / cell);
    bucket_bits = 1;
    while((std::size_t(1) << bucket_bits) < 4 * triangles.size()) ++bucket_bits;
    bucket_begin.assign((std::size_t(1) << bucket_bits) + 1, 0);
    for(const Bbox_3& b : boxes) for_each_cell(b, [&](std::size_t c) { ++bucket_begin[c + 1]; });
    for(std::size_t c = 1; c < bucket_begin.size(); ++c) bucket_begin[c] += bucket_begin[c - 1];
    bucket_entries.resize(bucket_begin.back());
    std::vector<std::uint32_t> cursor(bucket_begin.begin(), bucket_begin.end() - 1);
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      const Bbox_3& b = boxes[t];
      const Entry e{ { round_down(b.xmin()), round_down(b.ymin()), round_down(b.zmin()) },
                     { round_up(b.xmax()), round_up(b.ymax()), round_up(b.zmax()) }, std::uint32_t(t) };
      for_each_cell(b, [&](std::size_t c) { bucket_entries[cursor[c]++] = e; });
    }
    reached_in.assign(triangles.size(), 0);
  }

  // the closest point to p as `tree.closest_point(p)` gives it; `hint` (1 + the index of a triangle near p,
  // or 0) is updated to the triangle of the answer
  Point closest_point(const Point& p, std::size_t& hint) const
  {
    if(hint > triangles.size()) hint = 0;
    if(hint == 0) hint = triangle_near(p);
    std::size_t best_triangle = hint - 1;
    Point best = GeomTraits().construct_projected_point_3_object()(triangles[best_triangle], p);
    // every triangle at most as far as `best` has its bounding box within r of p (r slightly enlarged
    // against rounding)
    const double r2 = CGAL::to_double(CGAL::squared_distance(p, best)) * (1 + 1e-9);
    const double r = std::sqrt(r2) * (1 + 1e-9) + 1e-9 * cell;
    const double c[3] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
    long long lo[3], hi[3];
    long long n = 1;
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = cell_index(c[a] - r, a);
      hi[a] = cell_index(c[a] + r, a);
      n *= hi[a] - lo[a] + 1;
    }
    if(n > max_cells_per_query) return fallback(p, hint);
    if(++query_round == 0) { std::fill(reached_in.begin(), reached_in.end(), 0u); query_round = 1; }
    reached_in[hint - 1] = query_round;
    bool tie = false; // another point as close as `best`
    for(long long i = lo[0]; i <= hi[0]; ++i)
      for(long long j = lo[1]; j <= hi[1]; ++j)
        for(long long k = lo[2]; k <= hi[2]; ++k)
        {
          const std::size_t bk = bucket(i, j, k);
          for(std::size_t e = bucket_begin[bk]; e < bucket_begin[bk + 1]; ++e)
          {
            const Entry& b = bucket_entries[e];
            const double dx = (std::max)((std::max)(double(b.min[0]) - c[0], c[0] - double(b.max[0])), 0.);
            double d2 = dx * dx;
            if(d2 > r2) continue;
            const double dy = (std::max)((std::max)(double(b.min[1]) - c[1], c[1] - double(b.max[1])), 0.);
            d2 += dy * dy;
            if(d2 > r2) continue;
            const double dz = (std::max)((std::max)(double(b.min[2]) - c[2], c[2] - double(b.max[2])), 0.);
            if(d2 + dz * dz > r2) continue;
            const std::size_t t = b.triangle;
            if(reached_in[t] == query_round) continue;
            reached_in[t] = query_round;
            const Point q = GeomTraits().construct_projected_point_3_object()(triangles[t], p);
            const CGAL::Comparison_result cmp = GeomTraits().compare_distance_3_object()(p, q, best);
            if(cmp == CGAL::SMALLER) { best = q; best_triangle = t; tie = false; }
            else if(cmp == CGAL::EQUAL && q != best) tie = true;
          }
        }
    if(tie) return fallback(p, hint);
    hint = best_triangle + 1;
    return best;
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_REFERENCE_SURFACE_H
