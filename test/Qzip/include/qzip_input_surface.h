// The surface of a mesh, to measure how far the vertices of another mesh (an optimized copy) lie from it.
#ifndef QZIP_INPUT_SURFACE_H
#define QZIP_INPUT_SURFACE_H

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cmath>
#include <vector>

namespace qzip_test {

// Each quad counts as the union of its two triangulations (the optimizer projects onto one of them, the
// caller cannot tell which), other faces as fans. Distances are in mean edge lengths of the mesh measured.
template <typename Kernel>
class Input_surface
{
  typedef typename Kernel::Point_3 Point;
  typedef typename Kernel::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Iterator> > > Tree;

  std::vector<Triangle> triangles;
  Tree tree;
  double mean_edge = 0;

public:
  template <typename Mesh>
  explicit Input_surface(const Mesh& m)
  {
    for(auto e : edges(m))
      mean_edge += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, m, source(e, m)),
                                                                   get(CGAL::vertex_point, m, target(e, m)))));
    mean_edge /= double(num_edges(m));
    for(auto f : faces(m))
    {
      std::vector<Point> p;
      for(auto v : vertices_around_face(halfedge(f, m), m)) p.push_back(get(CGAL::vertex_point, m, v));
      for(std::size_t i = 1; i + 1 < p.size(); ++i) triangles.emplace_back(p[0], p[i], p[i + 1]);
      if(p.size() == 4) { triangles.emplace_back(p[1], p[2], p[3]); triangles.emplace_back(p[1], p[3], p[0]); }
    }
    tree.insert(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
  }

  // the distance from p to the surface
  double distance(const Point& p) const { return std::sqrt(CGAL::to_double(tree.squared_distance(p))) / mean_edge; }

  // the largest distance from a vertex of `m` to the surface
  template <typename Mesh>
  double largest_distance(const Mesh& m) const
  {
    double d = 0;
    for(auto v : vertices(m)) d = (std::max)(d, distance(get(CGAL::vertex_point, m, v)));
    return d;
  }
};

} // namespace qzip_test

#endif // QZIP_INPUT_SURFACE_H
