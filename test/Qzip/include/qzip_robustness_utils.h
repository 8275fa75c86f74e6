// Helpers of the robustness checks (test_bad_input, the fuzz harness, the stress benchmark): what a
// refused or undone operation must leave unchanged, and what a successful one must preserve.
#ifndef QZIP_ROBUSTNESS_UTILS_H
#define QZIP_ROBUSTNESS_UTILS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace qzip_robustness {

/// The mesh as geometry: for each face the cycle of its points (its lexicographically smallest rotation), sorted,
/// then the sorted points of all vertices. Descriptor-free: equal after an undo or a refusal, even when
/// elements were re-created with new descriptors.
template <typename Point>
struct Fingerprint
{
  std::vector<std::vector<Point> > faces;
  std::vector<Point> points;
  bool operator==(const Fingerprint& o) const { return faces == o.faces && points == o.points; }
  bool operator!=(const Fingerprint& o) const { return !(*this == o); }
};

template <typename Mesh>
auto fingerprint(const Mesh& m)
  -> Fingerprint<typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type>
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  Fingerprint<Point> fp;
  const auto vpm = get(CGAL::vertex_point, m);
  for(auto f : faces(m))
  {
    std::vector<Point> cycle;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) cycle.push_back(get(vpm, v));
    // the lexicographically smallest rotation (several corners may share the smallest point)
    std::vector<Point> best = cycle;
    for(std::size_t k = 1; k < cycle.size(); ++k)
    {
      std::rotate(cycle.begin(), cycle.begin() + 1, cycle.end());
      if(cycle < best) best = cycle;
    }
    fp.faces.push_back(best);
  }
  std::sort(fp.faces.begin(), fp.faces.end());
  for(auto v : vertices(m)) fp.points.push_back(get(vpm, v));
  std::sort(fp.points.begin(), fp.points.end());
  return fp;
}

/// An order-independent 64-bit hash of the same information as `fingerprint()` (cheaper to keep and compare
/// on large meshes; a collision could only hide a difference, never report a false one).
template <typename Mesh>
std::uint64_t geometry_hash(const Mesh& m)
{
  const auto vpm = get(CGAL::vertex_point, m);
  auto mix = [](std::uint64_t h) { h ^= h >> 33; h *= 0xff51afd7ed558ccdULL; h ^= h >> 33; h *= 0xc4ceb9fe1a85ec53ULL; h ^= h >> 33; return h; };
  auto point_hash = [&](typename boost::graph_traits<Mesh>::vertex_descriptor v)
  {
    const auto& p = get(vpm, v);
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for(int i = 0; i < 3; ++i)
    {
      double c = CGAL::to_double(p[i]);
      if(c == 0) c = 0; // -0 and +0
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = mix(h ^ bits) + 0x632be59bd9b4e019ULL * std::uint64_t(i + 1);
    }
    return h;
  };
  std::uint64_t total = 0;
  for(auto f : faces(m))
  {
    // a cyclic sequence: hash of the rotation starting at each vertex, combined order-independently
    // over rotations (sum) would lose the orientation, so use successive pairs (p_i, p_i+1) instead
    std::uint64_t fh = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
      fh += mix(point_hash(source(h, m)) * 31 + mix(point_hash(target(h, m))));
    total += mix(fh + 0x2545f4914f6cdd1dULL);
  }
  for(auto v : vertices(m)) total += mix(point_hash(v) ^ 0x5851f42d4c957f2dULL);
  return total;
}

/// What a Q-zip or the preprocessing may not change: Euler characteristic, the faces that are not quads
/// (quads come and go), the border.
struct Shape
{
  long chi = 0;
  std::map<std::size_t, std::size_t> non_quad_faces;
  std::size_t border_halfedges = 0;
  std::size_t border_cycles = 0;
  bool operator==(const Shape& o) const
  { return same_up_to_border_length(o) && border_halfedges == o.border_halfedges; }
  bool operator!=(const Shape& o) const { return !(*this == o); }
  // what a Q-zip that moves a border defect keeps (it splits a border vertex: one more border edge)
  bool same_up_to_border_length(const Shape& o) const
  { return chi == o.chi && non_quad_faces == o.non_quad_faces && border_cycles == o.border_cycles; }
};

template <typename Mesh>
Shape shape(const Mesh& m)
{
  Shape s;
  s.chi = long(vertices(m).size()) - long(edges(m).size()) + long(faces(m).size());
  for(auto f : faces(m))
  {
    const std::size_t d = CGAL::halfedges_around_face(halfedge(f, m), m).size();
    if(d != 4) ++s.non_quad_faces[d];
  }
  std::set<typename boost::graph_traits<Mesh>::halfedge_descriptor> seen;
  for(auto h : halfedges(m))
  {
    if(!is_border(h, m)) continue;
    ++s.border_halfedges;
    if(!seen.insert(h).second) continue;
    ++s.border_cycles;
    for(auto g = next(h, m); g != h; g = next(g, m)) seen.insert(g);
  }
  return s;
}

/// interior vertices whose valence is not 4 (isolated vertices excluded)
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> singular_interior_vertices(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> out;
  for(auto v : vertices(m))
  {
    if(halfedge(v, m) == boost::graph_traits<Mesh>::null_halfedge()) continue;
    std::size_t d = 0;
    bool border = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) { ++d; if(is_border_edge(h, m)) border = true; }
    if(!border && d != 4) out.push_back(v);
  }
  return out;
}

} // namespace qzip_robustness

#endif // QZIP_ROBUSTNESS_UTILS_H
