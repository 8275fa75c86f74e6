// Tests of the singularity optimizer: batches of Q-zips, scoring, smoothing, features, protected regions.
#include "qzip_test_utils.h"
#include "qzip_input_surface.h"

#include <CGAL/Qzip/optimize_singularities.h>
#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/internal/optimizer/Look_ahead.h>

#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <tuple>

using namespace qzip_test;
namespace Q = CGAL::Qzip;
namespace PMP = CGAL::Polygon_mesh_processing;

struct Counting_visitor : public Q::Default_optimizer_visitor<Surface_mesh>
{
  int started = 0, batches = 0, surgeries = 0, undone = 0, finished = 0;
  std::size_t last_singularities = 0;
  void on_started(const Q::Optimizer_statistics&) { ++started; }
  void on_surgery(const Q::Surgery_plan<Surface_mesh>&, double score, int predicted) { assert(score < 0 && predicted <= 0); ++surgeries; }
  void on_undo(const Q::Surgery_plan<Surface_mesh>&) { ++undone; }
  void on_batch_finished(const Q::Optimizer_statistics& s)
  {
    ++batches;
    assert(s.batch == std::size_t(batches));
    assert(batches == 1 || s.number_of_singularities <= last_singularities); // never more singularities
    last_singularities = s.number_of_singularities;
  }
  void on_finished(const Q::Optimizer_statistics&) { ++finished; }
};

// a "subdivision-style" input: a triangle mesh (icosahedron) Catmull-Clark subdivided: 12 v5 + 20 v3
template <typename Mesh>
void make_cc_sphere(Mesh& m, int levels)
{
  clear(m);
  CGAL::make_icosahedron(m, Point(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(levels));
}

template <typename Mesh>
std::size_t singularities(const Mesh& m) { return Q::compute_mesh_report(m).total_absolute_defect; }

template <typename Mesh>
std::vector<Point> sorted_points(const Mesh& m)
{
  std::vector<Point> p;
  for(auto v : vertices(m)) p.push_back(get(CGAL::vertex_point, m, v));
  std::sort(p.begin(), p.end());
  return p;
}

template <typename Mesh>
void check_result(const Mesh& m, long chi, const Q::Optimizer_statistics& s)
{
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(all_faces_have_degree(m, 4));
  assert(euler_characteristic(m) == chi);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_inverted_quads == 0);
  assert(s.number_of_singularities == r.total_absolute_defect);
  assert(s.number_of_faces == r.number_of_faces);
  assert(double(r.number_of_faces) <= 1.1 * double(s.initial_number_of_faces) + 1);
  assert(double(r.number_of_faces) >= 0.9 * double(s.initial_number_of_faces) - 1);
}

// subdivision-style input: the count drops by half, invariants hold, the visitor is called,
// the same seed gives the same mesh, on Surface_mesh and on Polyhedron_3.
void test_subdivision_sphere()
{
  Surface_mesh sm;
  make_cc_sphere(sm, 2);
  const long chi = euler_characteristic(sm);
  const std::size_t before = singularities(sm);
  assert(before == 32);
  Counting_visitor vis;
  const Q::Optimizer_statistics s = Q::optimize_singularities(sm, CGAL::parameters::random_seed(3).visitor(std::ref(vis)));
  std::cout << "cc sphere (Surface_mesh): " << before << " -> " << s.number_of_singularities << " singularities, "
            << s.initial_number_of_faces << " -> " << s.number_of_faces << " quads, " << s.batch << " batches, "
            << s.number_of_surgeries << " surgeries, " << s.elapsed_seconds << " s" << std::endl;
  check_result(sm, chi, s);
  assert(2 * s.number_of_singularities <= before);
  assert(vis.started == 1 && vis.finished == 1 && vis.batches == int(s.batch) && vis.surgeries == int(s.number_of_surgeries));
  assert(vis.undone == int(s.number_of_undone_surgeries));

  // determinism: same seed, same mesh (connectivity and positions)
  Surface_mesh sm2;
  make_cc_sphere(sm2, 2);
  const Q::Optimizer_statistics s2 = Q::optimize_singularities(sm2, CGAL::parameters::random_seed(3));
  assert(s2.number_of_surgeries == s.number_of_surgeries && s2.number_of_singularities == s.number_of_singularities);
  assert(are_isomorphic(sm, sm2));
  assert(sorted_points(sm) == sorted_points(sm2));

  // another seed takes other decisions
  Surface_mesh sm3;
  make_cc_sphere(sm3, 2);
  Q::optimize_singularities(sm3, CGAL::parameters::random_seed(4));
  assert(sorted_points(sm3) != sorted_points(sm));

  // the same result on Polyhedron_3
  Polyhedron ph;
  make_cc_sphere(ph, 2);
  const Q::Optimizer_statistics sp = Q::optimize_singularities(ph, CGAL::parameters::random_seed(3));
  std::cout << "cc sphere (Polyhedron_3): " << sp.number_of_singularities << " singularities, "
            << sp.number_of_surgeries << " surgeries" << std::endl;
  check_result(ph, chi, sp);
  assert(sp.number_of_surgeries == s.number_of_surgeries && sp.number_of_singularities == s.number_of_singularities);
  assert(are_isomorphic(sm, ph));
  assert(sorted_points(sm) == sorted_points(ph));
}

// a plain breadth-first search from v (a vertex of a closed mesh): the distance of every vertex (in `dist`),
// and the distances of the singular vertices other than v, x1 and x2 in the order the search meets them
template <typename PolygonMesh>
std::vector<int> singular_distances_from(const PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                         typename boost::graph_traits<PolygonMesh>::vertex_descriptor x1,
                                         typename boost::graph_traits<PolygonMesh>::vertex_descriptor x2,
                                         std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, int>& dist)
{
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> queue(1, v);
  dist[v] = 0;
  std::vector<int> singular_distances;
  for(std::size_t i = 0; i < queue.size(); ++i)
  {
    const auto u = queue[i];
    if(u != v && u != x1 && u != x2 && degree(u, pm) != 4) singular_distances.push_back(dist[u]);
    for(auto h : CGAL::halfedges_around_target(halfedge(u, pm), pm))
      if(dist.emplace(source(h, pm), dist[u] + 1).second) queue.push_back(source(h, pm));
  }
  return singular_distances;
}

// the context's closest singularities of v (closed mesh) are the closest ones by a plain breadth-first search
template <typename PolygonMesh, typename Context>
void check_nearest_singularities(const PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                 const Context& ctx)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  std::map<typename GT::vertex_descriptor, int> dist;
  const std::vector<int> singular_distances = singular_distances_from(pm, v, GT::null_vertex(), GT::null_vertex(), dist);
  const auto nb = ctx.nearest_singularities(v);
  assert(nb.size > 0 && nb.feature_distance == std::numeric_limits<int>::max());
  std::size_t k = 0;
  for(const auto& j : nb)
  {
    assert(j.distance == singular_distances[k++]);
    assert(j.distance == dist[j.vertex] && j.defect == int(degree(j.vertex, pm)) - 4 && ctx.defect(j.vertex) == j.defect);
  }
}

// the variant of nearest_singularities() that skips two singularities and stops after n is the beginning of
// the full list without them (asked first, so that the full list is then found by a second search)
template <typename Context, typename Vertex>
void check_partial_nearest_singularities(const Context& ctx, Vertex v, Vertex x1, Vertex x2, std::size_t n)
{
  const auto part = ctx.nearest_singularities(v, x1, x2, n);
  const auto full = ctx.nearest_singularities(v);
  assert(part.feature_distance == full.feature_distance);
  std::size_t k = 0;
  for(const auto& j : full)
  {
    if(j.vertex == x1 || j.vertex == x2) continue;
    if(k == n) break;
    assert(k < part.size && part.items[k].vertex == j.vertex && part.items[k].distance == j.distance);
    ++k;
  }
  assert(k == part.size);
}

// opposite_singularity_distance() is the distance of the first singularity of the opposite sign in the full
// list without x1 and x2 (asked first, so that its early stop is followed by a second search)
template <typename Context, typename Vertex>
void check_opposite_singularity_distance(const Context& ctx, Vertex v, int sign, Vertex x1, Vertex x2)
{
  const int d = ctx.opposite_singularity_distance(v, sign, x1, x2);
  int expected = -1;
  for(const auto& j : ctx.nearest_singularities(v))
    if(j.vertex != x1 && j.vertex != x2 && j.defect * sign < 0) { expected = j.distance; break; }
  assert(d == expected);
}

// stop predicates, no smoothing, a custom scoring functor
struct No_collapse_scoring
{
  mutable std::size_t* calls;
  template <typename PolygonMesh, typename Context>
  double operator()(const Q::Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    ++*calls;
    assert(c.plan != nullptr && c.plan->is_realizable());
    assert(c.source_defect != 0 && c.target_defect != 0);
    if(*calls % 16 == 1)
    {
      check_nearest_singularities(ctx.mesh(), c.source, ctx);
      check_nearest_singularities(ctx.mesh(), c.source_landing, ctx);
    }
    if(*calls % 16 == 2 && c.target_landing != boost::graph_traits<PolygonMesh>::null_vertex())
      check_partial_nearest_singularities(ctx, c.target_landing, c.source, c.target, 1 + *calls % 3);
    if(*calls % 16 == 3 && c.source_landing != boost::graph_traits<PolygonMesh>::null_vertex())
      check_opposite_singularity_distance(ctx, c.source_landing, c.source_defect, c.source, c.target);
    if(c.plan->number_of_collapses() > 0) return 1.; // refuse every surgery that collapses a quad
    return Q::Default_scoring()(c, ctx);
  }
};

void test_policies()
{
  Surface_mesh ref;
  make_cc_sphere(ref, 2);
  {
    Surface_mesh m;
    make_cc_sphere(m, 2);
    const auto s = Q::optimize_singularities(m, Q::parameters::stop_predicate(Q::Batch_count_stop_predicate(2)));
    assert(s.batch == 2);
    check_result(m, euler_characteristic(ref), s);
  }
  {
    Surface_mesh m;
    make_cc_sphere(m, 2);
    const auto s = Q::optimize_singularities(m, Q::parameters::combine(CGAL::parameters::random_seed(3),
                                                 Q::parameters::do_smooth(false)));
    std::cout << "no smoothing: " << s.initial_number_of_singularities << " -> " << s.number_of_singularities
              << ", " << s.number_of_undone_surgeries << " undone" << std::endl;
    check_result(m, euler_characteristic(ref), s);
  }
  Surface_mesh def, custom;
  make_cc_sphere(def, 2);
  make_cc_sphere(custom, 2);
  const auto sd = Q::optimize_singularities(def, CGAL::parameters::random_seed(3));
  std::size_t calls = 0;
  No_collapse_scoring scoring{ &calls };
  const auto sc = Q::optimize_singularities(custom, Q::parameters::scoring_functor(scoring, CGAL::parameters::random_seed(3)));
  std::cout << "custom scoring: " << sc.number_of_singularities << " singularities, " << sc.number_of_faces
            << " quads (default: " << sd.number_of_singularities << ", " << sd.number_of_faces << "), "
            << calls << " calls" << std::endl;
  check_result(custom, euler_characteristic(ref), sc);
  assert(calls > 0);
  assert(sorted_points(def) != sorted_points(custom));
  // without collapses in the chains the quads can only be created (clean-ups aside)
  assert(sc.number_of_faces + sc.number_of_surgeries >= sc.initial_number_of_faces);
}

typedef boost::graph_traits<Surface_mesh>::vertex_descriptor sm_vertex;

// the feature edges of a mesh (dihedral angle above 60 degrees) and the positions of their vertices
struct Features
{
  std::vector<std::pair<Point, Point> > segments;
  std::set<std::pair<sm_vertex, sm_vertex> > edges;
  std::map<sm_vertex, int> degree;
  std::map<sm_vertex, Point> points;

  // marks the edges whose dihedral angle is above 60 degrees in `feature`
  template <typename FeatureMap>
  static void mark_sharp_edges(const Surface_mesh& m, FeatureMap feature)
  {
    for(auto e : CGAL::edges(m))
    {
      const auto h = halfedge(e, m);
      if(is_border_edge(h, m)) continue;
      const auto n1 = PMP::compute_face_normal(face(h, m), m), n2 = PMP::compute_face_normal(face(opposite(h, m), m), m);
      if(n1 * n2 < std::cos(60. * CGAL_PI / 180.)) put(feature, e, true);
    }
  }

  // marks the sharp edges and records them
  template <typename FeatureMap>
  void mark(const Surface_mesh& m, FeatureMap feature)
  {
    mark_sharp_edges(m, feature);
    record(m, feature);
  }

  // the feature edges as `feature` marks them now
  template <typename FeatureMap>
  void record(const Surface_mesh& m, FeatureMap feature)
  {
    for(auto e : CGAL::edges(m))
    {
      if(!get(feature, e)) continue;
      const auto h = halfedge(e, m);
      segments.emplace_back(m.point(source(h, m)), m.point(target(h, m)));
      edges.insert(std::minmax(source(h, m), target(h, m)));
      ++degree[source(h, m)];
      ++degree[target(h, m)];
    }
    for(const auto& vd : degree) points[vd.first] = m.point(vd.first);
  }

  // the same feature edges between the same vertices; the ends of feature curves and the vertices where
  // they branch are bit for bit where they were; the others lie on the input polylines. Returns the
  // number of vertices that moved.
  template <typename FeatureMap>
  std::size_t check(const Surface_mesh& m, FeatureMap feature) const
  {
    std::set<std::pair<sm_vertex, sm_vertex> > after;
    for(auto e : CGAL::edges(m))
      if(get(feature, e)) after.insert(std::minmax(source(halfedge(e, m), m), target(halfedge(e, m), m)));
    assert(after == edges);
    std::size_t moved = 0;
    for(const auto& vp : points)
    {
      const Point& p = m.point(vp.first);
      if(degree.at(vp.first) != 2) assert(p == vp.second);
      if(p == vp.second) continue;
      ++moved;
      double d = std::numeric_limits<double>::max();
      for(const auto& sg : segments) d = (std::min)(d, CGAL::squared_distance(p, K::Segment_3(sg.first, sg.second)));
      assert(d < 1e-20);
    }
    return moved;
  }
};

// smoothing slides feature vertices along their curves and keeps corners fixed
void test_feature_sliding(const std::string& fandisk)
{
  Surface_mesh m;
  if(!read_mesh(fandisk, m)) { std::cerr << "cannot read " << fandisk << std::endl; assert(false); }
  Q::preprocess_valences(m);
  auto feature = m.add_property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, bool>("e:feature", false).first;
  Features features;
  features.mark(m, feature);
  assert(!features.segments.empty());
  const std::size_t inverted = Q::compute_mesh_report(m).number_of_inverted_quads;
  const std::vector<sm_vertex> all(vertices(m).begin(), vertices(m).end());
  Q::smooth_quad_mesh(m, all, CGAL::parameters::edge_is_constrained_map(feature));
  const std::size_t moved = features.check(m, feature);
  std::cout << "smoothing fandisk: " << moved << " of " << features.points.size() << " feature vertices slid" << std::endl;
  assert(moved > 0);
  assert(Q::compute_mesh_report(m).number_of_inverted_quads <= inverted);
}

// protected faces keep their vertices and positions bit for bit; feature edges survive (same vertices),
// their vertices slide along the feature polylines, feature corners do not move
void test_protection_and_features(const std::string& fandisk)
{
  Surface_mesh m;
  if(!read_mesh(fandisk, m)) { std::cerr << "cannot read " << fandisk << std::endl; assert(false); }
  Q::preprocess_valences(m);
  typedef boost::graph_traits<Surface_mesh>::edge_descriptor edge_descriptor;
  typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
  auto feature = m.add_property_map<edge_descriptor, bool>("e:feature", false).first;
  Features features;
  features.mark(m, feature);
  assert(!features.segments.empty());
  // protect the faces whose first vertex is among the 15% largest x
  std::vector<double> xs;
  for(face_descriptor f : faces(m)) xs.push_back(m.point(target(halfedge(f, m), m)).x());
  std::sort(xs.begin(), xs.end());
  const double threshold = xs[xs.size() * 85 / 100];
  auto prot = m.add_property_map<face_descriptor, bool>("f:protected", false).first;
  std::vector<std::pair<face_descriptor, std::vector<std::pair<boost::graph_traits<Surface_mesh>::vertex_descriptor, Point> > > > saved;
  for(face_descriptor f : faces(m))
    if(m.point(target(halfedge(f, m), m)).x() > threshold)
    {
      prot[f] = true;
      std::vector<std::pair<boost::graph_traits<Surface_mesh>::vertex_descriptor, Point> > corners;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) corners.emplace_back(target(h, m), m.point(target(h, m)));
      saved.emplace_back(f, corners);
    }
  assert(!saved.empty());
  const long chi = euler_characteristic(m);
  const std::size_t before = Q::compute_mesh_report(m, CGAL::parameters::edge_is_constrained_map(feature)).total_absolute_defect;
  const auto s = Q::optimize_singularities(m, Q::parameters::face_is_constrained_map(prot,
                                                CGAL::parameters::edge_is_constrained_map(feature).random_seed(1)));
  std::cout << "fandisk with features and " << saved.size() << " protected faces: " << before << " -> "
            << s.number_of_singularities << " singularities, " << s.number_of_surgeries << " surgeries" << std::endl;
  assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4) && euler_characteristic(m) == chi);
  assert(s.number_of_singularities <= before);
  for(const auto& fs : saved)
  {
    assert(!m.is_removed(fs.first) && prot[fs.first]);
    std::size_t i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(fs.first, m), m))
    {
      assert(target(h, m) == fs.second[i].first);
      assert(m.point(target(h, m)) == fs.second[i].second); // bit for bit
      ++i;
    }
    assert(i == 4);
  }
  features.check(m, feature);
}

// The stop predicates on progress, and the end game (without its look-ahead, see test_look_ahead()): after
// a stop, every surgery it keeps was predicted to cancel singularities and did (each one lowers the count),
// and it leaves a valid mesh; without it (do_end_game(false)) the run ends with the batches.
void test_end_game()
{
  Q::Optimizer_statistics st;
  st.batch = 5;
  st.candidates_in_last_batch = 3;
  st.batches_without_improvement = 9;
  st.batches_without_progress = 2;
  assert(!Q::No_progress_stop_predicate(3)(st) && Q::No_improvement_stop_predicate(3)(st));
  assert(!Q::Default_stop_predicate(200, 3)(st) && Q::Default_stop_predicate(5, 3)(st));
  st.batches_without_progress = 3;
  assert(Q::No_progress_stop_predicate(3)(st));
  st.batches_without_progress = 0;
  st.candidates_in_last_batch = 0;
  assert(Q::No_progress_stop_predicate(3)(st));

  std::size_t with_end_game = 0;
  for(unsigned int seed = 0; seed < 4; ++seed)
  {
    Surface_mesh m;
    make_cc_sphere(m, 2);
    const long chi = euler_characteristic(m);
    struct Visitor : public Q::Default_optimizer_visitor<Surface_mesh>
    {
      std::size_t after_batches = 0, surgeries_in_batches = 0, batches = 0, predicted_in_end_game = 0;
      void on_batch_finished(const Q::Optimizer_statistics& s)
      {
        ++batches;
        after_batches = s.number_of_singularities;
        surgeries_in_batches = s.number_of_surgeries;
      }
      void on_surgery(const Q::Surgery_plan<Surface_mesh>&, double score, int predicted)
      {
        assert(score < 0);
        if(batches == 6) { assert(predicted < 0); ++predicted_in_end_game; } // after the last batch: the end game
      }
    } vis;
    const auto s = Q::optimize_singularities(m, Q::parameters::do_look_ahead(false,
                     Q::parameters::stop_predicate(Q::Batch_count_stop_predicate(6),
                                                   CGAL::parameters::random_seed(seed).visitor(std::ref(vis)))));
    check_result(m, chi, s);
    assert(s.batch == 6 && vis.batches == 6 && s.end_game_rounds > 0);
    const std::size_t kept = s.number_of_surgeries - vis.surgeries_in_batches;
    assert(kept == vis.predicted_in_end_game);
    assert(s.number_of_singularities + kept <= vis.after_batches);
    if(kept > 0) ++with_end_game;
    Surface_mesh without;
    make_cc_sphere(without, 2);
    const auto w = Q::optimize_singularities(without, Q::parameters::do_end_game(false,
                     Q::parameters::stop_predicate(Q::Batch_count_stop_predicate(6), CGAL::parameters::random_seed(seed))));
    assert(w.end_game_rounds == 0 && w.batch == 6 && w.number_of_singularities == vis.after_batches);
    std::cout << "end game (seed " << seed << "): " << vis.after_batches << " -> " << s.number_of_singularities
              << " singularities after 6 batches, " << kept << " surgeries in " << s.end_game_rounds << " rounds" << std::endl;
  }
  assert(with_end_game > 0);
}

// sparse singularities (a Catmull-Clark sphere of level 4: 32 singularities among 3842 vertices): a kept
// Q-zip is followed by more Q-zips of the same pair within the batch, so a batch keeps more surgeries than
// it chose candidates; every surgery is reported with a negative score; invariants hold; the same result
// on Surface_mesh and on Polyhedron_3.
void test_travel()
{
  struct Visitor : public Q::Default_optimizer_visitor<Surface_mesh>
  {
    std::size_t surgeries = 0, chosen = 0, batches_with_more = 0, surgeries_before = 0;
    void on_batch_scored(const Q::Optimizer_statistics&, std::size_t n) { chosen = n; }
    void on_surgery(const Q::Surgery_plan<Surface_mesh>&, double score, int) { assert(score < 0); ++surgeries; }
    void on_batch_finished(const Q::Optimizer_statistics&)
    {
      if(surgeries - surgeries_before > chosen) ++batches_with_more;
      surgeries_before = surgeries;
    }
  } vis;
  Surface_mesh sm;
  make_cc_sphere(sm, 4);
  const long chi = euler_characteristic(sm);
  const auto stop = Q::Batch_count_stop_predicate(10);
  const auto s = Q::optimize_singularities(sm, Q::parameters::do_end_game(false,
                   Q::parameters::stop_predicate(stop, CGAL::parameters::random_seed(0).visitor(std::ref(vis)))));
  std::cout << "travel (cc sphere, level 4): " << s.initial_number_of_singularities << " -> " << s.number_of_singularities
            << " singularities in " << s.batch << " batches, " << s.number_of_surgeries << " surgeries, "
            << vis.batches_with_more << " batches kept more surgeries than they chose" << std::endl;
  check_result(sm, chi, s);
  assert(vis.surgeries == s.number_of_surgeries);

  Polyhedron ph;
  make_cc_sphere(ph, 4);
  const auto sp = Q::optimize_singularities(ph, Q::parameters::do_end_game(false,
                    Q::parameters::stop_predicate(stop, CGAL::parameters::random_seed(0))));
  check_result(ph, chi, sp);
  assert(sp.number_of_surgeries == s.number_of_surgeries && sp.number_of_singularities == s.number_of_singularities);
  assert(are_isomorphic(sm, ph));
  assert(sorted_points(sm) == sorted_points(ph));
  assert(vis.batches_with_more > 0);
}

// Undone surgeries on two bundled meshes: the same result on Surface_mesh and on Polyhedron_3, run after
// other work in the process (plans replanned after undone surgeries included, see test_replanned_after_undos()). An undo re-creates vertices with new descriptors, recycled on Surface_mesh
// (reset properties) and maybe at the address of a removed vertex on Polyhedron_3 (its stamps, depending on
// the heap): each must get back the marks and scar stamps of the vertex it replaces, also inside a bend of
// the path, more than four edges from the region's shell (polylap_suzanne_half met such a vertex).
void test_same_result_after_undos(const std::string& data_dir)
{
  for(const char* name : { "polylap_suzanne_half.obj", "trimesh_target.obj" })
  {
    Surface_mesh sm;
    Polyhedron ph;
    if(!read_mesh(data_dir + name, sm) || !read_mesh(data_dir + name, ph))
    {
      std::cerr << "cannot read " << data_dir << name << std::endl;
      assert(false);
    }
    Q::preprocess_valences(sm);
    Q::preprocess_valences(ph);
    const Q::Optimizer_statistics s = Q::optimize_singularities(sm);
    const Q::Optimizer_statistics sp = Q::optimize_singularities(ph);
    std::cout << name << " on both mesh types: " << s.number_of_surgeries << " surgeries, "
              << s.number_of_undone_surgeries << " undone, " << s.number_of_replanned_surgeries << " replanned, "
              << s.number_of_singularities << " singularities left" << std::endl;
    assert(s.number_of_undone_surgeries > 0 && s.number_of_replanned_surgeries > 0);
    assert(sp.number_of_replanned_surgeries == s.number_of_replanned_surgeries);
    assert(sp.number_of_surgeries == s.number_of_surgeries && sp.number_of_singularities == s.number_of_singularities);
    assert(are_isomorphic(sm, ph));
    assert(sorted_points(sm) == sorted_points(ph));
  }
}

// A batch plans its candidates on the mesh of its start; a plan whose path meets only the regions of surgeries
// of the batch that were undone is found again by its positions and planned again instead of skipped (the mesh
// is the same there, with other descriptors). The first batches on a bundled mesh, with and without: the
// same candidates; with, some are replanned and executed (more surgeries tried, fewer skipped), and the
// invariants hold (no more inverted quads than the input's five).
void test_replanned_after_undos(const std::string& data_dir)
{
  struct Visitor : public Q::Default_optimizer_visitor<Surface_mesh>
  {
    std::size_t tried = 0;
    void on_surgery(const Q::Surgery_plan<Surface_mesh>&, double, int) { ++tried; }
    void on_undo(const Q::Surgery_plan<Surface_mesh>&) { ++tried; }
  };
  std::size_t tried[2] = { 0, 0 };
  Q::Optimizer_statistics stats[2];
  for(int replan = 0; replan < 2; ++replan)
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "quadriflow_gargoyle.obj", m)) { std::cerr << "cannot read the gargoyle" << std::endl; assert(false); }
    Q::preprocess_valences(m);
    const long chi = euler_characteristic(m);
    const std::size_t inverted = Q::compute_mesh_report(m).number_of_inverted_quads; // 5 in the input
    typedef CGAL::Static_boolean_property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, false> Ecm;
    typedef CGAL::Static_boolean_property_map<boost::graph_traits<Surface_mesh>::face_descriptor, false> Fcm;
    Q::internal::Optimizer_settings settings;
    settings.end_game = false;
    settings.replan_after_undos = replan == 1;
    settings.untangling_sweeps = 0; // undone at once: many more undos to replan after
    // few alternatives: with the default twelve, a source whose candidate is skipped for want of replanning
    // mostly executes another one instead, and the counts of tried and skipped surgeries no longer tell
    // the replanning apart
    settings.alternatives = 3;
    const Q::Default_scoring scoring;
    const Q::Batch_count_stop_predicate stop(8);
    Visitor vis;
    typedef CGAL::property_map_selector<Surface_mesh, CGAL::vertex_point_t>::type Vpm;
    Q::internal::Quad_smoother<Surface_mesh, Vpm, Ecm, Fcm, K> smoother(m, get(CGAL::vertex_point, m), Ecm(), Fcm(), true);
    Q::internal::Batch_optimizer<Surface_mesh, Vpm, Ecm, Fcm, K>
      optimizer(m, get(CGAL::vertex_point, m), Ecm(), Fcm(), smoother, scoring, stop, vis, settings);
    stats[replan] = optimizer.run();
    assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4) && euler_characteristic(m) == chi);
    const Q::Mesh_report r = Q::compute_mesh_report(m);
    assert(r.number_of_inverted_quads <= inverted && r.total_absolute_defect == stats[replan].number_of_singularities);
    tried[replan] = vis.tried;
  }
  std::cout << "replanned after undos (gargoyle, 8 batches): " << stats[1].number_of_replanned_surgeries << " replanned, "
            << tried[1] << " surgeries tried, " << stats[1].number_of_skipped_surgeries << " skipped (without: "
            << tried[0] << " tried, " << stats[0].number_of_skipped_surgeries << " skipped)" << std::endl;
  assert(stats[0].number_of_replanned_surgeries == 0 && stats[1].number_of_replanned_surgeries > 0);
  assert(tried[1] > tried[0] && stats[1].number_of_skipped_surgeries < stats[0].number_of_skipped_surgeries);
}

// The number of faces stays within `face_count_tolerance` of the initial one (on the mesh the optimizer
// receives), with tight tolerances on the bundled gargoyle (all quads), batches and end game, and singularities
// still cancel. (Surgeries are also judged on the faces their execution left, whose clean-up may collapse more
// quads than the plan says; that happened on libigl_horse_quad of the shared corpus, not here: without that
// check this test passes too.)
void test_face_count_tolerance(const std::string& data_dir)
{
  for(double tolerance : { 0.002, 0.01 })
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "quadriflow_gargoyle.obj", m)) { std::cerr << "cannot read the gargoyle" << std::endl; assert(false); }
    Q::preprocess_valences(m);
    const double f0 = double(faces(m).size());
    const Q::Optimizer_statistics s =
      Q::optimize_singularities(m, Q::parameters::face_count_tolerance(tolerance,
                                   Q::parameters::stop_predicate(Q::Batch_count_stop_predicate(40))));
    const double change = double(faces(m).size()) - f0;
    std::cout << "face count tolerance " << tolerance << ": " << f0 << " -> " << faces(m).size() << " faces, "
              << s.initial_number_of_singularities << " -> " << s.number_of_singularities << " singularities" << std::endl;
    assert(s.number_of_faces == faces(m).size());
    assert(std::abs(change) <= tolerance * f0);
    assert(s.number_of_singularities < s.initial_number_of_singularities);
  }
}

// quality_floor: when no quad of a pure quad input is below the floor, no quad of the result is (the surgeries,
// the chains of the end game and the smoothing are all guarded by it), on Surface_mesh and Polyhedron_3 alike;
// the default floor lets the same run go below it (so the floor decides); a floor outside (0, 1) is refused
// before any edit.
template <typename Mesh>
Q::Optimizer_statistics optimize_with_floor(Mesh& m, double floor)
{
  make_cc_sphere(m, 3);
  return Q::optimize_singularities(m, Q::parameters::quality_floor(floor, CGAL::parameters::random_seed(1)));
}

void test_quality_floor(const std::string& data_dir)
{
  Surface_mesh input;
  make_cc_sphere(input, 3);
  const long chi = euler_characteristic(input);
  const Q::Mesh_report in = Q::compute_mesh_report(input);
  const double floor = 0.5;
  Surface_mesh with_default, with_floor;
  const Q::Optimizer_statistics sd = optimize_with_floor(with_default, 0.1);
  const Q::Optimizer_statistics sf = optimize_with_floor(with_floor, floor);
  const Q::Mesh_report rd = Q::compute_mesh_report(with_default), rf = Q::compute_mesh_report(with_floor);
  std::cout << "quality floor: input min SJ " << in.min_scaled_jacobian << ", " << in.total_absolute_defect
            << " singularities; floor 0.1: min SJ " << rd.min_scaled_jacobian << ", " << sd.number_of_singularities
            << " singularities, " << sd.number_of_undone_surgeries << " undone; floor " << floor << ": min SJ "
            << rf.min_scaled_jacobian << ", " << sf.number_of_singularities << " singularities, "
            << sf.number_of_undone_surgeries << " undone" << std::endl;
  assert(in.number_of_inverted_quads == 0 && in.min_scaled_jacobian >= floor);
  check_result(with_default, chi, sd);
  check_result(with_floor, chi, sf);
  assert(rd.min_scaled_jacobian < floor);
  assert(rf.min_scaled_jacobian >= floor);
  assert(2 * sf.number_of_singularities <= in.total_absolute_defect);

  Polyhedron ph;
  const Q::Optimizer_statistics sp = optimize_with_floor(ph, floor);
  check_result(ph, chi, sp);
  assert(sp.number_of_surgeries == sf.number_of_surgeries && sp.number_of_singularities == sf.number_of_singularities);
  assert(are_isomorphic(with_floor, ph));
  assert(sorted_points(with_floor) == sorted_points(ph));

  // a real mesh (pure quads, none below 0.4), with a floor below its worst quad
  Surface_mesh fandisk;
  if(!read_mesh(data_dir + "pmp_fandisk_quads.off", fandisk)) { std::cerr << "cannot read the fandisk" << std::endl; assert(false); }
  const long fandisk_chi = euler_characteristic(fandisk);
  const Q::Mesh_report fandisk_in = Q::compute_mesh_report(fandisk);
  assert(all_faces_have_degree(fandisk, 4) && fandisk_in.min_scaled_jacobian >= 0.4);
  const Q::Optimizer_statistics sfan = Q::optimize_singularities(fandisk, Q::parameters::quality_floor(0.4));
  const Q::Mesh_report fandisk_out = Q::compute_mesh_report(fandisk);
  std::cout << "quality floor 0.4 on the fandisk: min SJ " << fandisk_in.min_scaled_jacobian << " -> "
            << fandisk_out.min_scaled_jacobian << ", " << fandisk_in.total_absolute_defect << " -> "
            << sfan.number_of_singularities << " singularities" << std::endl;
  check_result(fandisk, fandisk_chi, sfan);
  assert(fandisk_out.min_scaled_jacobian >= 0.4);
  assert(sfan.number_of_singularities < fandisk_in.total_absolute_defect);

  // smooth_quad_mesh() with a floor: with the optimizer's, the result stays above it; with a floor above the
  // worst quad, the worst quad gets no worse and the moves that would take a quad below the floor are refused
  // (fewer moves than with no floor, whose moves only keep the quads valid)
  std::size_t moves_without_floor = 0;
  for(double smoothing_floor : { 0., 0.4, 0.9 })
  {
    Surface_mesh smoothed = fandisk;
    std::vector<boost::graph_traits<Surface_mesh>::vertex_descriptor> all(vertices(smoothed).begin(), vertices(smoothed).end());
    const std::size_t moves = Q::smooth_quad_mesh(smoothed, all, Q::parameters::quality_floor(smoothing_floor,
                                                    CGAL::parameters::number_of_iterations(20)));
    const Q::Mesh_report rs = Q::compute_mesh_report(smoothed);
    std::cout << "smooth_quad_mesh, floor " << smoothing_floor << ": " << moves << " moves, min SJ "
              << fandisk_out.min_scaled_jacobian << " -> " << rs.min_scaled_jacobian << std::endl;
    assert(moves > 0 && rs.number_of_inverted_quads == 0);
    assert(rs.min_scaled_jacobian >= (std::min)(smoothing_floor, fandisk_out.min_scaled_jacobian));
    if(smoothing_floor == 0) moves_without_floor = moves;
    if(smoothing_floor == 0.9) assert(moves < moves_without_floor);
  }

  for(double bad : { 0., 1., -0.5, std::numeric_limits<double>::quiet_NaN() })
  {
    Surface_mesh m = input;
    bool refused = false;
    try { Q::optimize_singularities(m, Q::parameters::quality_floor(bad)); }
    catch(const CGAL::Precondition_exception&) { refused = true; }
    assert(refused);
    assert(are_isomorphic(m, input) && sorted_points(m) == sorted_points(input));
  }
}

// ten batches on the Catmull-Clark sphere of level 4 with the given Optimizer_settings::sparse_pairing_distance;
// checks that each batch executes all its candidates (or the best half, `all` false) and the invariants
// (`skip_chosen_targets`: see Optimizer_settings; `first_candidates`: the number of candidates of the first batch)
template <typename Mesh>
Q::Optimizer_statistics run_batches(Mesh& m, double sparse_pairing_distance, bool all, bool skip_chosen_targets = true,
                                    std::size_t* first_candidates = nullptr)
{
  struct Visitor : public Q::Default_optimizer_visitor<Mesh>
  {
    bool all = false;
    std::size_t batches = 0, first = 0;
    void on_batch_scored(const Q::Optimizer_statistics& s, std::size_t n)
    {
      assert(n == (all ? s.candidates_in_last_batch : (s.candidates_in_last_batch + 1) / 2));
      if(batches++ == 0) first = n;
    }
  } vis;
  vis.all = all;
  make_cc_sphere(m, 4);
  const long chi = euler_characteristic(m);
  typedef typename CGAL::property_map_selector<Mesh, CGAL::vertex_point_t>::type Vpm;
  typedef CGAL::Static_boolean_property_map<typename boost::graph_traits<Mesh>::edge_descriptor, false> Ecm;
  typedef CGAL::Static_boolean_property_map<typename boost::graph_traits<Mesh>::face_descriptor, false> Fcm;
  Q::internal::Optimizer_settings settings;
  settings.end_game = false;
  settings.sparse_pairing_distance = sparse_pairing_distance;
  settings.skip_chosen_targets = skip_chosen_targets;
  const Q::Default_scoring scoring;
  const Q::Batch_count_stop_predicate stop(10);
  Q::internal::Quad_smoother<Mesh, Vpm, Ecm, Fcm, K> smoother(m, get(CGAL::vertex_point, m), Ecm(), Fcm(), true);
  Q::internal::Batch_optimizer<Mesh, Vpm, Ecm, Fcm, K>
    optimizer(m, get(CGAL::vertex_point, m), Ecm(), Fcm(), smoother, scoring, stop, vis, settings);
  const Q::Optimizer_statistics s = optimizer.run();
  check_result(m, chi, s);
  assert(vis.batches == s.batch && s.batch == 10);
  if(first_candidates != nullptr) *first_candidates = vis.first;
  return s;
}

// sparse singularities: a batch executes all the candidates it chose when the singularities are on average
// at least `sparse_pairing_distance` edges from their partners, else the best half. Forced both ways
// (thresholds 0 and infinity) on the Catmull-Clark sphere of level 4 (32 singularities among 3842 vertices):
// invariants hold, the same result on Surface_mesh and on Polyhedron_3 (run after other work in the process,
// whose freed addresses Polyhedron_3 reuses), and executing all candidates keeps more surgeries in ten batches.
void test_all_candidates_when_sparse()
{
  Surface_mesh all_sm, half_sm;
  Polyhedron all_ph;
  const Q::Optimizer_statistics all = run_batches(all_sm, 0., true);
  const Q::Optimizer_statistics half = run_batches(half_sm, std::numeric_limits<double>::infinity(), false);
  const Q::Optimizer_statistics all_p = run_batches(all_ph, 0., true);
  std::cout << "all candidates when sparse (cc sphere, level 4, 10 batches): " << all.number_of_surgeries << " surgeries, "
            << all.number_of_singularities << " singularities left (the best half: " << half.number_of_surgeries << ", "
            << half.number_of_singularities << ")" << std::endl;
  assert(all_p.number_of_surgeries == all.number_of_surgeries && all_p.number_of_singularities == all.number_of_singularities);
  assert(are_isomorphic(all_sm, all_ph));
  assert(sorted_points(all_sm) == sorted_points(all_ph));
  assert(all.number_of_surgeries > half.number_of_surgeries);

  // A source that is the target of an earlier source's candidate is not scored in a sparse batch: on the sphere,
  // whose singularities come in pairs closest to each other, the first batch (the same mesh and the same random
  // sources either way) chooses fewer candidates than when every source is scored, and both runs keep the
  // invariants.
  Surface_mesh skipping_sm, scoring_all_sm;
  std::size_t skipping = 0, scoring_all = 0;
  run_batches(skipping_sm, 0., true, true, &skipping);
  run_batches(scoring_all_sm, 0., true, false, &scoring_all);
  std::cout << "  candidates of the first sparse batch: " << skipping << " (every source scored: " << scoring_all << ")"
            << std::endl;
  assert(skipping > 0 && skipping < scoring_all);
}

// the first n singularities other than x1 and x2 that the context gives at v (a vertex of a closed mesh),
// asked right after the scoring's own questions (so maybe answered by labels kept from earlier batches),
// are at the distances of the first ones a plain breadth-first search finds
template <typename PolygonMesh, typename Context>
void check_kept_nearest_singularities(const PolygonMesh& pm, const Context& ctx,
                                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor x1,
                                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor x2, std::size_t n)
{
  std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, int> dist;
  const std::vector<int> singular_distances = singular_distances_from(pm, v, x1, x2, dist);
  const auto part = ctx.nearest_singularities(v, x1, x2, n);
  assert(part.size == (std::min)(n, singular_distances.size()));
  for(std::size_t k = 0; k < part.size; ++k)
    assert(part.items[k].distance == singular_distances[k] && dist[part.items[k].vertex] == singular_distances[k]);
}

// the default scoring, whose context answers are checked after it asked them (see test_context_across_batches())
struct Checked_scoring
{
  std::size_t* calls;
  template <typename PolygonMesh, typename Context>
  double operator()(const Q::Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    typedef boost::graph_traits<PolygonMesh> GT;
    const double score = Q::Default_scoring()(c, ctx);
    ++*calls;
    if(c.source_landing == GT::null_vertex() || c.target_landing == GT::null_vertex()) return score;
    if(*calls % 4 == 0) check_kept_nearest_singularities(ctx.mesh(), ctx, c.source_landing, c.source, c.target, 3);
    if(*calls % 4 == 1) check_kept_nearest_singularities(ctx.mesh(), ctx, c.target_landing, c.source, c.target, 3);
    if(*calls % 4 == 2) check_opposite_singularity_distance(ctx, c.source_landing, c.source_defect, c.source, c.target);
    if(*calls % 4 == 3) check_nearest_singularities(ctx.mesh(), c.target, ctx);
    return score;
  }
};

// the closest singularities that the scoring context keeps from batch to batch (entirely while no surgery
// came within their search, their closest part otherwise) are those of the mesh of the batch, on
// Surface_mesh (whose removed descriptors are recycled) and on Polyhedron_3; the checks change no result.
template <typename Mesh>
void test_context_across_batches()
{
  Mesh checked, plain;
  make_cc_sphere(checked, 3);
  make_cc_sphere(plain, 3);
  std::size_t calls = 0;
  const auto stop = Q::Batch_count_stop_predicate(12);
  const auto sc = Q::optimize_singularities(checked, Q::parameters::scoring_functor(Checked_scoring{ &calls },
                    Q::parameters::do_end_game(false, Q::parameters::stop_predicate(stop, CGAL::parameters::random_seed(2)))));
  const auto sp = Q::optimize_singularities(plain, Q::parameters::do_end_game(false,
                    Q::parameters::stop_predicate(stop, CGAL::parameters::random_seed(2))));
  std::cout << "context across batches: " << sc.initial_number_of_singularities << " -> " << sc.number_of_singularities
            << " singularities in " << sc.batch << " batches, " << calls << " scored candidates checked" << std::endl;
  assert(calls > 0 && sc.batch == 12);
  assert(sc.number_of_surgeries == sp.number_of_surgeries && sorted_points(checked) == sorted_points(plain));
}

// the paper's genus-3 robustness test (Fig. 17): the closed surface of a 7 x 3 x 1 plate of voxels with
// three holes, triangulated and refined once by Catmull-Clark (as in benchmark_optimizer)
// the end game's smoother on a Surface_mesh without features or protected faces
typedef CGAL::Static_boolean_property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, false> ECM;
typedef CGAL::Static_boolean_property_map<boost::graph_traits<Surface_mesh>::face_descriptor, false> FCM;
typedef CGAL::property_map_selector<Surface_mesh, CGAL::vertex_point_t>::type VPM;
typedef Q::internal::Quad_smoother<Surface_mesh, VPM, ECM, FCM, K> Smoother;

void make_genus3_plate(Surface_mesh& m)
{
  make_genus3_voxel_plate(m);
  PMP::triangulate_faces(m);
  CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1));
  Q::preprocess_valences(m);
}

// the genus-3 plate where the batches and the plain end game stop above the optimum (a v3-v5 pair or more
// left), for the first such seed from 18 on, which it returns. With the isotropy and sizing terms divided by the
// square root of the number of operations (sessions 15-24), the batches reached the optimum on seeds 0 to 17
// (before, on 0 to 25): the search starts at 18 so as not to optimize the plate 18 more times on every run (with
// the means and the spacing factor of session 25 it still finds such a seed). Failed surgeries
// are undone at once, without untangling: with it (the default since session 21) the batches reach the
// optimum on every seed from 18 to 99.
unsigned int make_plate_where_batches_stop(Surface_mesh& m)
{
  unsigned int seed = 18;
  for(; seed < 100; ++seed)
  {
    make_genus3_plate(m);
    Q::optimize_singularities(m, Q::parameters::do_look_ahead(false, Q::parameters::number_of_untangling_sweeps(0,
                                 CGAL::parameters::random_seed(seed))));
    if(singularities(m) > 16) break;
  }
  assert(seed < 100);
  return seed;
}

// the positions of the vertices that can start a chain of the look-ahead `chains`, sorted (an order that
// does not depend on descriptors)
template <typename Chains>
std::vector<Point> endpoint_positions(const Surface_mesh& m, Chains& chains)
{
  std::vector<Point> sources;
  for(auto v : vertices(m)) if(chains.is_endpoint(v)) sources.push_back(m.point(v));
  std::sort(sources.begin(), sources.end());
  return sources;
}

// the vertex at `p` that can start a chain, or null_vertex() (a chain cancelled or moved it)
template <typename Chains>
boost::graph_traits<Surface_mesh>::vertex_descriptor endpoint_at(const Surface_mesh& m, Chains& chains, const Point& p)
{
  auto v = boost::graph_traits<Surface_mesh>::null_vertex();
  for(auto w : vertices(m)) if(m.point(w) == p && chains.is_endpoint(w)) v = w;
  return v;
}

// The end game's look-ahead. Directly, on the genus-3 plate where the batches and the plain end game stop
// (v3 a few edges from v5, no Q-zip predicted to cancel): every chain it keeps lowers the count by exactly
// two and leaves a valid quad mesh without inverted quads; every search that fails after executing Q-zips
// (here: searches without partners beyond the closest singularity, which cannot cancel) leaves the mesh as it
// was (connectivity and positions); a face budget that refuses every change executes nothing. In the
// optimizer, over seeds 0-4: fewer singularities in sum with the look-ahead than without, and the paper's
// optimum (exactly 16 v5, no v3) reached on every seed.
void test_look_ahead()
{
  typedef Q::internal::Look_ahead<Surface_mesh, VPM, ECM, FCM, Smoother> Chains;

  Surface_mesh m;
  make_genus3_plate(m);
  const long chi = euler_characteristic(m);
  assert(chi == -4);
  const unsigned int seed = make_plate_where_batches_stop(m);
  Smoother smoother(m, get(CGAL::vertex_point, m), ECM(), FCM(), true);
  smoother.quality_floor = 0.1;
  Chains::Settings settings;
  settings.max_distance = settings.max_depth = 6;
  Chains chains(m, get(CGAL::vertex_point, m), ECM(), FCM(), smoother, settings);
  Chains::Settings pair_settings = settings;
  pair_settings.budget = 1;
  const long f0 = long(faces(m).size());
  auto within_ten_percent = [&](long change) { return std::abs(double(long(faces(m).size()) + change - f0)) <= 0.1 * double(f0); };

  std::size_t kept = 0, failed_after_executions = 0;
  for(bool again = true; again; )
  {
    again = false;
    for(const Point& p : endpoint_positions(m, chains))
    {
      const auto v = endpoint_at(m, chains, p);
      if(v == boost::graph_traits<Surface_mesh>::null_vertex()) continue; // cancelled or moved by a chain
      Surface_mesh before;
      copy_mesh(m, before);
      const std::size_t count = singularities(m), executions = chains.number_of_executions();
      Chains::Chain chain;
      Chains none(m, get(CGAL::vertex_point, m), ECM(), FCM(), smoother, settings);
      assert(!none.cancel(v, [](long) { return false; }, chain) && none.number_of_executions() == 0);
      // on a copy, a search allowed one Q-zip, which cancels only a pair at most two edges apart; a search that
      // fails after executing it leaves the copy as it was
      {
        Surface_mesh trial;
        copy_mesh(m, trial);
        auto tv = boost::graph_traits<Surface_mesh>::null_vertex();
        for(auto w : vertices(trial)) if(trial.point(w) == p) tv = w;
        Smoother trial_smoother(trial, get(CGAL::vertex_point, trial), ECM(), FCM(), true);
        trial_smoother.quality_floor = 0.1;
        Chains pairs_only(trial, get(CGAL::vertex_point, trial), ECM(), FCM(), trial_smoother, pair_settings);
        Chains::Chain pair_chain;
        if(!pairs_only.cancel(tv, [](long) { return true; }, pair_chain))
        {
          if(pairs_only.number_of_executions() > 0) ++failed_after_executions;
          assert(are_isomorphic(trial, before) && sorted_points(trial) == sorted_points(before));
        }
      }
      if(chains.cancel(v, within_ten_percent, chain))
      {
        ++kept;
        again = true;
        assert(!chain.plans.empty() && chain.plans.size() == chain.predicted_cancellations.size());
        assert(singularities(m) + 2 == count);
        assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4) && euler_characteristic(m) == chi);
        assert(Q::compute_mesh_report(m).number_of_inverted_quads == 0);
        assert(std::abs(double(long(faces(m).size()) - f0)) <= 0.1 * double(f0) + 2);
        break; // the other sources may have moved
      }
      if(chains.number_of_executions() > executions) ++failed_after_executions;
      assert(are_isomorphic(m, before) && sorted_points(m) == sorted_points(before));
    }
  }
  std::cout << "look-ahead on the genus-3 plate (seed " << seed << "): " << kept << " chains kept, " << failed_after_executions
            << " searches undone, " << chains.number_of_executions() << " Q-zips executed, " << singularities(m)
            << " singularities left" << std::endl;
  assert(kept > 0 && failed_after_executions > 0);

  // in the optimizer, seeds 0-4: no more singularities in sum with the look-ahead than without, and the
  // paper's optimum (exactly 16 v5, no v3) reached with it on every seed (since the smoother puts vertices
  // back onto the surface, the batches alone reach it on these seeds too: the plate above, where they stop
  // short of it, is the look-ahead's test)
  std::size_t with_sum = 0, without_sum = 0, optimum_reached = 0;
  for(unsigned int seed = 0; seed < 5; ++seed)
  {
    Surface_mesh with, without;
    make_genus3_plate(with);
    make_genus3_plate(without);
    const auto s = Q::optimize_singularities(with, CGAL::parameters::random_seed(seed));
    const auto w = Q::optimize_singularities(without, Q::parameters::do_look_ahead(false, CGAL::parameters::random_seed(seed)));
    check_result(with, chi, s);
    const Q::Mesh_report r = Q::compute_mesh_report(with);
    std::cout << "genus-3 plate (seed " << seed << "): " << s.number_of_singularities << " singularities ("
              << r.number_of_interior_valence_3_like << " v3, " << r.number_of_interior_valence_5_like
              << " v5), without the look-ahead " << w.number_of_singularities << std::endl;
    with_sum += s.number_of_singularities;
    without_sum += w.number_of_singularities;
    if(r.number_of_interior_valence_5_like == 16 && r.number_of_interior_valence_3_like == 0) ++optimum_reached;
  }
  assert(with_sum <= without_sum && optimum_reached == 5);
}

// The look-ahead's quality guard judges the quads a chain created or moved against those it removed or moved,
// not against the whole region of its search: on the genus-3 plate where the batches stop (see
// test_look_ahead()), the interior vertex farthest from the singularities is pushed across a neighbour (an
// inverted quad, the worst of every search region). With and without smoothing, the chains kept leave no
// quad below the quality floor away from the pushed vertex (none was below it before) and no more inverted
// quads. (When the guard compared the whole region, the inverted quad made its reference negative: chains
// left quads below the floor.)
void test_look_ahead_quality_guard()
{
  typedef Q::internal::Look_ahead<Surface_mesh, VPM, ECM, FCM, Smoother> Chains;
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor Vertex;
  const double floor = 0.1;
  std::size_t kept = 0;
  double worst_kept = 1;
  for(bool smooth : { false, true })
  {
    Surface_mesh m;
    make_plate_where_batches_stop(m);
    // the interior vertex farthest from the singularities (breadth first from all of them)
    std::map<Vertex, int> distance;
    std::vector<Vertex> queue;
    for(Vertex v : vertices(m)) if(degree(v, m) != 4) { distance[v] = 0; queue.push_back(v); }
    for(std::size_t i = 0; i < queue.size(); ++i)
      for(Vertex w : vertices_around_target(queue[i], m))
        if(distance.emplace(w, distance[queue[i]] + 1).second) queue.push_back(w);
    const Vertex pushed = queue.back();
    const Vertex neighbour = *vertices_around_target(pushed, m).begin();
    // the inverted quads, the worst quad without a corner at `at`, and the corners of those with one
    auto quality_away = [&](const Point& at, std::vector<std::vector<Point> >* around_at = nullptr)
    {
      std::size_t inverted = 0;
      double worst = 1;
      for(auto f : faces(m))
      {
        const double j = Q::quad_scaled_jacobian(f, m);
        if(j <= 0) ++inverted;
        std::vector<Point> corners;
        for(Vertex v : vertices_around_face(halfedge(f, m), m)) corners.push_back(m.point(v));
        std::sort(corners.begin(), corners.end());
        if(!std::binary_search(corners.begin(), corners.end(), at)) worst = (std::min)(worst, j);
        else if(around_at != nullptr) around_at->push_back(corners);
      }
      if(around_at != nullptr) std::sort(around_at->begin(), around_at->end());
      return std::make_pair(inverted, worst);
    };
    assert(quality_away(m.point(pushed)).second >= floor && quality_away(m.point(pushed)).first == 0);
    m.point(pushed) = m.point(pushed) + 1.5 * (m.point(neighbour) - m.point(pushed));
    const Point at = m.point(pushed);
    std::vector<std::vector<Point> > pushed_quads;
    const std::size_t inverted = quality_away(at, &pushed_quads).first;
    assert(inverted > 0);

    Smoother smoother(m, get(CGAL::vertex_point, m), ECM(), FCM(), true);
    smoother.quality_floor = floor;
    Chains::Settings settings;
    settings.smooth = smooth;
    settings.quality_floor = floor;
    Chains chains(m, get(CGAL::vertex_point, m), ECM(), FCM(), smoother, settings);
    const long f0 = long(faces(m).size());
    auto within_ten_percent = [&](long change) { return std::abs(double(long(faces(m).size()) + change - f0)) <= 0.1 * double(f0); };
    for(bool again = true; again; )
    {
      again = false;
      for(const Point& p : endpoint_positions(m, chains))
      {
        const Vertex v = endpoint_at(m, chains, p);
        if(v == boost::graph_traits<Surface_mesh>::null_vertex()) continue;
        Chains::Chain chain;
        if(!chains.cancel(v, within_ten_percent, chain)) continue;
        // a chain that changed a quad around the pushed vertex is judged against the inverted quad: the
        // search stops there
        std::vector<std::vector<Point> > around_at;
        const std::pair<std::size_t, double> q = quality_away(at, &around_at);
        if(around_at != pushed_quads) break;
        ++kept;
        worst_kept = (std::min)(worst_kept, q.second);
        assert(q.first <= inverted && q.second >= floor);
        again = true;
        break;
      }
    }
  }
  std::cout << "look-ahead quality guard: " << kept << " chains kept beside an inverted quad, worst quad away from it "
            << worst_kept << std::endl;
  assert(kept > 0);
}

// The untangling step of the end game's quality guard (Quad_smoother::untangle()): on a flat 4 x 4 grid, two
// inner vertices pushed across their neighbours (inverted quads) are moved back until every quad is above the
// floor; the border does not move, nor does a vertex whose quads are all above the floor; the smallest scaled
// Jacobian never decreases.
void test_untangle()
{

  Surface_mesh m;
  make_quad_grid(m, 4, 4);
  Smoother smoother(m, get(CGAL::vertex_point, m), ECM(), FCM(), true);
  std::vector<Surface_mesh::Vertex_index> all(vertices(m).begin(), vertices(m).end());
  Surface_mesh::Vertex_index v11, v21, v33;
  for(auto v : all)
  {
    if(m.point(v) == Point(1, 1, 0)) v11 = v;
    if(m.point(v) == Point(2, 1, 0)) v21 = v;
    if(m.point(v) == Point(3, 3, 0)) v33 = v;
  }
  m.point(v11) = Point(2.6, 1.4, 0);
  m.point(v21) = Point(1.3, 1.8, 0);
  const std::vector<Point> before = sorted_points(m);
  const Q::Mesh_report tangled = Q::compute_mesh_report(m);
  assert(tangled.number_of_inverted_quads > 0);
  const Point p33 = m.point(v33);
  const std::size_t moves = smoother.untangle(all, 20, 0.5);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  std::cout << "untangle: " << tangled.number_of_inverted_quads << " inverted quads, min scaled Jacobian "
            << tangled.min_scaled_jacobian << " -> " << r.number_of_inverted_quads << ", " << r.min_scaled_jacobian
            << " (" << moves << " moves)" << std::endl;
  assert(moves > 0 && r.number_of_inverted_quads == 0 && r.min_scaled_jacobian >= 0.5);
  assert(r.min_scaled_jacobian >= tangled.min_scaled_jacobian);
  assert(m.point(v33) == p33);
  for(auto v : all)
    if(on_border(v, m)) assert(std::binary_search(before.begin(), before.end(), m.point(v)));
  for(auto v : all) assert(m.point(v).z() == 0);
}

// The smoother's reference surface (internal::Reference_surface) answers every closest-point query exactly as
// CGAL::AABB_tree::closest_point(p, start) does, whatever its hint: on a Catmull-Clark sphere with a flat
// side (its vertices at the bounding box), for points near the surface with the hint of the previous
// answer (as the smoother queries), points inside and outside the bounding box (beyond its sides, where the
// cells are clamped), far hints, and points that are their own `start` (on the surface: the start is the
// answer, the hint stays one of the surface's triangles). And internal::is_simple_edge_path() on short and
// long paths (compared pairwise, or sorted).
void test_reference_surface()
{
  typedef K::Triangle_3 Triangle;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator> > > Tree;
  Surface_mesh m;
  make_cc_sphere(m, 2);
  for(auto v : vertices(m)) // a flat side at x = -0.8
    if(m.point(v).x() < -0.8) m.point(v) = Point(-0.8, m.point(v).y(), m.point(v).z());
  Q::internal::Reference_surface<K> surface;
  std::vector<Triangle> triangles;
  std::vector<std::size_t> vertex_hint(num_vertices(m), 0);
  for(auto f : faces(m))
  {
    std::vector<Surface_mesh::Vertex_index> fv(vertices_around_face(halfedge(f, m), m).begin(),
                                              vertices_around_face(halfedge(f, m), m).end());
    for(std::size_t i = 1; i + 1 < fv.size(); ++i)
    {
      const std::size_t t = surface.add(m.point(fv[0]), m.point(fv[i]), m.point(fv[i + 1]));
      assert(t == triangles.size() + 1);
      triangles.emplace_back(m.point(fv[0]), m.point(fv[i]), m.point(fv[i + 1]));
      for(auto v : { fv[0], fv[i], fv[i + 1] }) vertex_hint[std::size_t(v)] = t;
    }
  }
  surface.build();
  Tree tree(triangles.begin(), triangles.end());
  CGAL::Random rng(7);
  const std::vector<Surface_mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  for(int i = 0; i < 40000; ++i)
  {
    const Surface_mesh::Vertex_index v = vs[std::size_t(rng.get_int(0, int(vs.size())))];
    const Point& on = m.point(v);
    std::size_t& hint = vertex_hint[std::size_t(v)];
    Point p = on;
    switch(i % 4)
    {
      case 0: // near the surface, the hint of the previous answer
        p = Point(on.x() + rng.get_double(-0.05, 0.05), on.y() + rng.get_double(-0.05, 0.05), on.z() + rng.get_double(-0.05, 0.05));
        break;
      case 1: // anywhere around, outside the bounding box too
        p = Point(rng.get_double(-1.6, 1.6), rng.get_double(-1.6, 1.6), rng.get_double(-1.6, 1.6));
        break;
      case 2: // on the surface
        break;
      default: // a far hint
        p = Point(on.x() + rng.get_double(-0.2, 0.2), on.y() + rng.get_double(-0.2, 0.2), on.z() + rng.get_double(-0.2, 0.2));
        hint = std::size_t(rng.get_int(1, int(triangles.size()) + 1));
    }
    const Point expected = tree.closest_point(p);
    const Point got = surface.closest_point(p, hint);
    assert(got == expected);
    assert(hint >= 1 && hint <= triangles.size());
  }
  std::cout << "reference surface: 40000 queries on " << triangles.size() << " triangles as the AABB tree answers them" << std::endl;

  // The smoother puts a vertex that lies off its reference surface back onto it, even when a move of the
  // vertex is shorter than its distance to the surface (with the vertex's position as the tree's starting
  // point, the closest point search answered with that position, and the vertex stayed off the surface)
  Smoother smoother(m, get(CGAL::vertex_point, m), ECM(), FCM(), true);
  smoother.step = 0.1;
  std::size_t off = 0;
  for(auto v : vertices(m))
  {
    if(std::size_t(v) % 7 != 0 || m.point(v).x() <= -0.8) continue;
    const Point on = m.point(v);
    m.point(v) = on + 0.1 * (on - CGAL::ORIGIN); // outwards, about half an edge
    assert(tree.squared_distance(m.point(v)) > 1e-4);
    ++off;
    smoother.smooth(std::vector<Surface_mesh::Vertex_index>(1, v), 1);
    assert(m.point(v) != on + 0.1 * (on - CGAL::ORIGIN) && tree.squared_distance(m.point(v)) < 1e-20);
  }
  std::cout << "smoothing: " << off << " vertices put off the reference surface are back on it after one sweep" << std::endl;
  assert(off > 10);

  Surface_mesh grid;
  make_quad_grid(grid, 40, 2);
  std::vector<Surface_mesh::Vertex_index> row; // the bottom row, 41 vertices, then back along the next row
  for(int k = 0; k <= 40; ++k)
    for(auto v : vertices(grid)) if(grid.point(v) == Point(k, 0, 0)) row.push_back(v);
  for(std::size_t n : { std::size_t(5), row.size() })
  {
    std::vector<Surface_mesh::Vertex_index> path(row.begin(), row.begin() + std::ptrdiff_t(n));
    assert(Q::internal::is_simple_edge_path(path, grid));
    path.push_back(path[path.size() - 2]); // back along the last edge
    assert(!Q::internal::is_simple_edge_path(path, grid));
    path.pop_back();
    path.erase(path.begin() + 1); // a gap
    assert(!Q::internal::is_simple_edge_path(path, grid));
  }
}

// Every vertex of an optimized mesh lies on the input surface: the vertices a Q-zip creates or merges at
// midpoints are put onto it before the smoothing, which projects every move, and those the pairing of
// triangles placed (hybrid meshes) are put onto the surface the mesh had before the pairing. (Before, with the
// defaults: on the bundled gargoyle, 26 vertices up to 0.86 mean edge lengths off the surface, left where the
// Q-zip had put them when their smoothing moves were all refused; on noisy_sphere_triquad 14 vertices up to
// 0.11, on trimesh_target one at 0.009, that the pairing had moved.)
void test_vertices_on_input_surface(const std::string& data_dir)
{
  // with the default untangling of failed surgeries, and without it (more surgeries undone: their positions
  // restored, on the surface too)
  for(const char* name : { "quadriflow_gargoyle.obj", "noisy_sphere_triquad.obj", "trimesh_target.obj" })
  for(int sweeps : { 20, 0 })
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + name, m)) { std::cerr << "cannot read " << name << std::endl; assert(false); }
    Q::preprocess_valences(m);
    const Input_surface<K> input(m);
    const std::size_t inverted_before = Q::compute_mesh_report(m).number_of_inverted_quads;
    const auto s = Q::optimize_singularities(m, Q::parameters::number_of_untangling_sweeps(sweeps));
    const double d = input.largest_distance(m);
    std::cout << name << " (untangling sweeps " << sweeps << "): " << s.initial_number_of_singularities << " -> "
              << s.number_of_singularities << " singularities, " << s.number_of_undone_surgeries << " undone, "
              << s.number_of_triangle_collisions << " triangle collisions, vertices at most "
              << d << " mean edge lengths from the input surface" << std::endl;
    // no inverted quad where the input has none; fewer than the input where it has some (the gargoyle: five)
    const std::size_t inverted_after = Q::compute_mesh_report(m).number_of_inverted_quads;
    assert(CGAL::is_valid_polygon_mesh(m) && (inverted_after == 0 || inverted_after < inverted_before));
    assert(s.number_of_singularities < s.initial_number_of_singularities);
    assert(sweeps != 0 || s.number_of_undone_surgeries > 0);
    assert((s.initial_number_of_triangles == 0) == (std::string(name) == "quadriflow_gargoyle.obj"));
    assert(s.initial_number_of_triangles == 0 || s.number_of_triangle_collisions > 0);
    assert(d < 1e-9);
  }
}

// the shared corpus, when present: invariants on a few small meshes, both mesh types on one of them
void test_corpus()
{
  const std::string dir = shared_corpus_dir("test_optimizer");
  if(dir.empty()) return;
  for(const char* name : { "polylap_amo_quad.off", "libigl_horse_quad.obj" })
  {
    Surface_mesh m;
    if(!read_mesh(dir + "/" + name, m)) { std::cerr << "cannot read " << name << std::endl; assert(false); }
    Q::preprocess_valences(m);
    const long chi = euler_characteristic(m);
    const bool valid_input = Q::compute_mesh_report(m).number_of_inverted_quads == 0;
    const Input_surface<K> input(m);
    const auto s = Q::optimize_singularities(m, CGAL::parameters::random_seed(1));
    assert(input.largest_distance(m) < 1e-9);
    std::cout << name << ": " << s.initial_number_of_singularities << " -> " << s.number_of_singularities
              << " singularities, " << s.initial_number_of_faces << " -> " << s.number_of_faces << " quads, "
              << s.elapsed_seconds << " s" << std::endl;
    assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4) && euler_characteristic(m) == chi);
    assert(s.number_of_singularities < s.initial_number_of_singularities);
    if(valid_input) assert(Q::compute_mesh_report(m).number_of_inverted_quads == 0);
    if(std::string(name) == "polylap_amo_quad.off")
    {
      Polyhedron p;
      read_mesh(dir + "/" + name, p);
      Q::preprocess_valences(p);
      const auto sp = Q::optimize_singularities(p, CGAL::parameters::random_seed(1));
      assert(sp.number_of_singularities == s.number_of_singularities && sp.number_of_surgeries == s.number_of_surgeries);
      assert(are_isomorphic(m, p));
    }
  }
  // features at 60 degrees marked before the preprocessing, as the example does. With seed 4 the smoother
  // met a vertex it had recorded as a feature vertex that a Q-zip had taken off the curve (the other copy
  // of a split got its constrained edges), and read its recorded feature neighbours, which it had none of
  Surface_mesh m;
  if(!read_mesh(dir + "/gen_instantmeshes_rocker_arm.obj", m)) { std::cerr << "cannot read the rocker arm" << std::endl; assert(false); }
  auto feature = m.add_property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, bool>("e:feature", false).first;
  Features::mark_sharp_edges(m, feature);
  Q::preprocess_valences(m, CGAL::parameters::edge_is_constrained_map(feature));
  Features features;
  features.record(m, feature);
  const Input_surface<K> input(m);
  const long chi = euler_characteristic(m);
  const auto s = Q::optimize_singularities(m, CGAL::parameters::edge_is_constrained_map(feature).random_seed(4));
  std::cout << "rocker arm with features: " << s.initial_number_of_singularities << " -> " << s.number_of_singularities
            << " singularities" << std::endl;
  assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4) && euler_characteristic(m) == chi);
  assert(s.number_of_singularities < s.initial_number_of_singularities);
  features.check(m, feature);
  const double d = input.largest_distance(m);
  std::cout << "rocker arm with features: vertices at most " << d << " mean edge lengths from the input surface" << std::endl;
  assert(d < 1e-9);
}

// the answers of the scoring context at a vertex asked several times in a batch, with other counts,
// exclusions and signs (a search that stopped early is then continued where it stopped, see
// Scoring_context::compute_nearest()), are read off the full list of closest singularities that a new
// context finds by a single search at the vertex. The questions go round after round over groups of
// vertices: of 64 vertices in a first batch, of all of them in a second one that starts from the closest
// singularities kept across batches.
void test_resumed_nearest_singularities(const std::string& data_dir)
{
  typedef Q::Scoring_context<Surface_mesh, VPM, ECM, FCM> Context;
  typedef Context::Nearby Nearby;
  const sm_vertex none = boost::graph_traits<Surface_mesh>::null_vertex();
  Surface_mesh m;
  if(!read_mesh(data_dir + "quadriflow_gargoyle.obj", m)) { std::cerr << "cannot read the gargoyle" << std::endl; assert(false); }
  const std::vector<sm_vertex> vs(vertices(m).begin(), vertices(m).end());
  Context fresh(m, get(CGAL::vertex_point, m), ECM(), FCM());
  fresh.begin_batch();
  std::vector<std::vector<Nearby> > full;
  std::vector<int> feature_distance;
  for(sm_vertex v : vs)
  {
    const auto nb = fresh.nearest_singularities(v);
    full.emplace_back(nb.begin(), nb.end());
    feature_distance.push_back(nb.feature_distance);
  }
  auto same = [](const Nearby& a, const Nearby& b) { return a.vertex == b.vertex && a.defect == b.defect && a.distance == b.distance; };
  // the k-th singularity of the full list of vertex j, or none
  auto at = [&](std::size_t j, std::size_t k) { return k < full[j].size() ? full[j][k].vertex : none; };
  Context ctx(m, get(CGAL::vertex_point, m), ECM(), FCM());
  std::size_t asked = 0;
  for(int batch = 0; batch < 2; ++batch)
  {
    if(batch == 0) ctx.begin_batch();
    else ctx.begin_batch(std::vector<sm_vertex>());
    const std::size_t group = batch == 0 ? 64 : vs.size();
    for(std::size_t first = 0; first < vs.size(); first += group)
      for(int round = 0; round < 7; ++round)
        for(std::size_t j = first; j < (std::min)(first + group, vs.size()); ++j)
        {
          ++asked;
          if(round == 3 || round == 4)
          {
            // the closest singularity of the sign opposite to `sign` other than the two closest ones
            const int sign = round == 3 ? 1 : -1;
            const sm_vertex x1 = at(j, 0), x2 = at(j, 1);
            Nearby expected{ none, 0, -1 };
            for(const Nearby& s : full[j])
              if(s.vertex != x1 && s.vertex != x2 && s.defect * sign < 0) { expected = s; break; }
            assert(same(ctx.closest_opposite_singularity(vs[j], sign, x1, x2), expected));
            continue;
          }
          // the first n singularities other than x1 and x2, with n and the exclusions growing round after
          // round (from none at all)
          const std::size_t n = round < 3 ? std::size_t(round) : round == 5 ? 4 : Context::max_nearest_singularities;
          const sm_vertex x1 = round == 2 ? at(j, 0) : round == 5 ? at(j, 1) : none;
          const sm_vertex x2 = round == 5 ? at(j, 2) : none;
          const auto nb = ctx.nearest_singularities(vs[j], x1, x2, n);
          assert(nb.feature_distance == feature_distance[j]);
          std::size_t k = 0;
          for(const Nearby& s : full[j])
          {
            if(s.vertex == x1 || s.vertex == x2) continue;
            if(k == n) break;
            assert(k < nb.size && same(nb.items[k], s));
            ++k;
          }
          assert(k == nb.size);
        }
  }
  std::cout << "resumed closest singularities: " << asked << " questions on " << vs.size() << " vertices" << std::endl;
}

// the answers of a scoring context refreshed after a batch (see Scoring_context::begin_batch(edited), which
// rebuilds the rows of the vertices the batch edited) are those of a new context on the same mesh: at every
// vertex, its neighbors in the same order, its defect, whether it is passable, its closest singularities,
// its distance to the features, its closest singularity of each sign and its distance to a separatrix
// (with and without its two closest singularities excluded)
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
void check_same_as_new_context(PolygonMesh& pm,
                               const Q::Scoring_context<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap>& ctx)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  Q::Scoring_context<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap>
    fresh(pm, ctx.vertex_point_map(), EdgeIsConstrainedMap(), FaceIsConstrainedMap());
  fresh.begin_batch();
  // the counts the default scoring's electric weight is scaled with (Default_scoring::electric_spacing)
  const std::size_t faces_now = faces(pm).size();
  std::size_t singular_now = 0;
  for(vertex_descriptor v : vertices(pm)) if(fresh.defect(v) != 0) ++singular_now;
  assert(ctx.number_of_faces() == faces_now && fresh.number_of_faces() == faces_now);
  assert(ctx.number_of_singularities() == singular_now && fresh.number_of_singularities() == singular_now);
  const vertex_descriptor none = GT::null_vertex();
  auto same = [](const Q::Nearby_singularity<PolygonMesh>& a, const Q::Nearby_singularity<PolygonMesh>& b)
  { return a.vertex == b.vertex && a.defect == b.defect && a.distance == b.distance; };
  for(vertex_descriptor v : vertices(pm))
  {
    const int i = ctx.index(v), j = fresh.index(v);
    assert((i < 0) == (j < 0));
    if(i < 0) continue;
    assert(ctx.defect(v) == fresh.defect(v) && ctx.is_passable_at(i) == fresh.is_passable_at(j));
    assert(ctx.valence_at(i) == fresh.valence_at(j));
    for(int k = 0; k < ctx.valence_at(i); ++k)
      assert(ctx.vertex(ctx.neighbors_begin(i)[k]) == fresh.vertex(fresh.neighbors_begin(j)[k]));
    const auto near = ctx.nearest_singularities(v), expected = fresh.nearest_singularities(v);
    assert(near.feature_distance == expected.feature_distance && near.size == expected.size);
    for(std::size_t k = 0; k < near.size; ++k) assert(same(near.items[k], expected.items[k]));
    for(int sign : { -1, 1 })
      assert(same(ctx.closest_opposite_singularity(v, sign, none, none), fresh.closest_opposite_singularity(v, sign, none, none)));
    const vertex_descriptor x1 = expected.size > 0 ? expected.items[0].vertex : none;
    const vertex_descriptor x2 = expected.size > 1 ? expected.items[1].vertex : none;
    assert(ctx.distance_to_separatrix(v, none, none, 3) == fresh.distance_to_separatrix(v, none, none, 3));
    assert(ctx.distance_to_separatrix(v, x1, x2, 3) == fresh.distance_to_separatrix(v, x1, x2, 3));
  }
}

// the default scoring, which compares the context with a new one (see check_same_as_new_context()) at its
// first call after the mesh was edited, on the mesh `pm`
template <typename PolygonMesh>
struct Fresh_context_scoring
{
  PolygonMesh* pm;
  bool* edited;
  std::size_t* checks;
  template <typename Context>
  double operator()(const Q::Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    if(*edited)
    {
      check_same_as_new_context(*pm, ctx);
      *edited = false;
      ++*checks;
    }
    return Q::Default_scoring()(c, ctx);
  }
};

// a kept or undone surgery edited the mesh (an undone one gives it back with new descriptors)
template <typename PolygonMesh>
struct Edit_visitor : Q::Default_optimizer_visitor<PolygonMesh>
{
  bool* edited;
  void on_surgery(const Q::Surgery_plan<PolygonMesh>&, double, int) { *edited = true; }
  void on_undo(const Q::Surgery_plan<PolygonMesh>&) { *edited = true; }
};

// The scoring context, refreshed after each batch (and each round of the end game) by rebuilding only the
// rows of the vertices edited, undone around or created and those of their neighbors, answers as a new
// context on the same mesh (see check_same_as_new_context()), on a mesh with a border where surgeries are
// undone, on Surface_mesh (which recycles the indices of removed vertices with reset properties) and on
// Polyhedron_3 (run after other work in the process, whose freed addresses it reuses, with their dynamic
// properties); the checks change no result.
template <typename Mesh>
void test_context_refreshed_as_new(const std::string& data_dir)
{
  Mesh checked, plain;
  const std::string name = data_dir + "polylap_suzanne_half.obj";
  if(!read_mesh(name, checked) || !read_mesh(name, plain)) { std::cerr << "cannot read " << name << std::endl; assert(false); }
  Q::preprocess_valences(checked);
  Q::preprocess_valences(plain);
  bool edited = false;
  std::size_t checks = 0;
  Edit_visitor<Mesh> vis;
  vis.edited = &edited;
  const auto sc = Q::optimize_singularities(checked, Q::parameters::scoring_functor(Fresh_context_scoring<Mesh>{ &checked, &edited, &checks },
                    CGAL::parameters::visitor(std::ref(vis))));
  const auto sp = Q::optimize_singularities(plain);
  std::cout << "context refreshed as new: " << sc.number_of_surgeries << " surgeries (" << sc.number_of_undone_surgeries
            << " undone), " << checks << " refreshed contexts checked" << std::endl;
  assert(sc.number_of_undone_surgeries > 0 && checks > 2);
  assert(sc.number_of_surgeries == sp.number_of_surgeries && sc.number_of_singularities == sp.number_of_singularities);
  assert(sorted_points(checked) == sorted_points(plain));
}

// The time limit (maximum_running_time) cuts the run of the same seed after a batch or an end-game step: a
// limit of 0 runs nothing, half the time of the full run gives a prefix of its batches (the same numbers of
// singularities and faces after each of them) with every batch started before the limit, a valid mesh and
// the flag set; a limit far beyond the run gives its result.
void test_time_limit(const std::string& data_dir)
{
  struct Batch { std::size_t singularities, faces; double elapsed; };
  struct Visitor : public Q::Default_optimizer_visitor<Surface_mesh>
  {
    std::vector<Batch> batches;
    void on_batch_finished(const Q::Optimizer_statistics& s)
    {
      batches.push_back(Batch{ s.number_of_singularities, s.number_of_faces, s.elapsed_seconds });
    }
  };
  const std::string name = data_dir + "quadriflow_gargoyle.obj";
  auto read_input = [&](Surface_mesh& m)
  {
    if(!read_mesh(name, m)) { std::cerr << "cannot read " << name << std::endl; assert(false); }
    Q::preprocess_valences(m);
  };
  auto run = [&](double limit, Surface_mesh& m, Visitor& vis)
  {
    read_input(m);
    return Q::optimize_singularities(m, CGAL::parameters::random_seed(0).visitor(std::ref(vis)).maximum_running_time(limit));
  };
  Surface_mesh input;
  read_input(input);
  const long chi = euler_characteristic(input);
  const std::size_t inverted_before = Q::compute_mesh_report(input).number_of_inverted_quads;
  Surface_mesh full, none, half, beyond;
  Visitor vfull, vnone, vhalf, vbeyond;
  const Q::Optimizer_result sfull = run(std::numeric_limits<double>::infinity(), full, vfull);
  assert(!sfull.reached_time_limit && sfull.batch > 4 && sfull.end_game_rounds > 0);
  assert(euler_characteristic(full) == chi);

  const Q::Optimizer_result snone = run(0., none, vnone);
  assert(snone.reached_time_limit && snone.batch == 0 && snone.end_game_rounds == 0 && snone.number_of_surgeries == 0);
  assert(vnone.batches.empty() && sorted_points(none) == sorted_points(input));
  assert(snone.number_of_singularities == snone.initial_number_of_singularities);

  const double limit = sfull.elapsed_seconds / 2;
  const Q::Optimizer_result shalf = run(limit, half, vhalf);
  std::cout << "time limit: full run " << sfull.batch << " batches in " << sfull.elapsed_seconds << " s, limit " << limit
            << " s: " << shalf.batch << " batches, " << shalf.end_game_rounds << " end-game rounds, "
            << shalf.number_of_singularities << " singularities (full: " << sfull.number_of_singularities << ")" << std::endl;
  assert(shalf.reached_time_limit && shalf.batch <= sfull.batch && !vhalf.batches.empty());
  assert(vhalf.batches.size() <= vfull.batches.size());
  for(std::size_t k = 0; k < vhalf.batches.size(); ++k)
  {
    assert(vhalf.batches[k].singularities == vfull.batches[k].singularities);
    assert(vhalf.batches[k].faces == vfull.batches[k].faces);
    if(k > 0) assert(vhalf.batches[k - 1].elapsed < limit); // batch k started before the limit
  }
  assert(CGAL::is_valid_polygon_mesh(half) && all_faces_have_degree(half, 4) && euler_characteristic(half) == chi);
  const Q::Mesh_report rhalf = Q::compute_mesh_report(half);
  assert(rhalf.total_absolute_defect == shalf.number_of_singularities && rhalf.number_of_faces == shalf.number_of_faces);
  assert(rhalf.number_of_inverted_quads <= inverted_before);
  assert(shalf.number_of_singularities >= sfull.number_of_singularities);

  const Q::Optimizer_result sbeyond = run(1e6, beyond, vbeyond);
  assert(!sbeyond.reached_time_limit && sbeyond.batch == sfull.batch && sbeyond.end_game_rounds == sfull.end_game_rounds);
  assert(sorted_points(beyond) == sorted_points(full));
}

// `test_optimizer --same-result-after-undos DATA_DIR` runs test_same_result_after_undos() alone (ctest runs it
// again under a perturbed heap, see CMakeLists.txt); `test_optimizer [FANDISK]` runs everything.
int main(int argc, char** argv)
{
  if(argc > 2 && std::string(argv[1]) == "--same-result-after-undos")
  {
    test_same_result_after_undos(argv[2]);
    std::cout << "done" << std::endl;
    return EXIT_SUCCESS;
  }
  const std::string fandisk = argc > 1 ? argv[1] : "data/pmp_fandisk_quads.off";
  test_subdivision_sphere();
  test_time_limit("data/");
  test_policies();
  test_end_game();
  test_look_ahead();
  test_look_ahead_quality_guard();
  test_untangle();
  test_reference_surface();
  test_vertices_on_input_surface("data/");
  test_feature_sliding(fandisk);
  test_protection_and_features(fandisk);
  test_travel();
  test_same_result_after_undos("data/");
  test_replanned_after_undos("data/");
  test_face_count_tolerance("data/");
  test_quality_floor("data/");
  test_all_candidates_when_sparse();
  test_context_across_batches<Surface_mesh>();
  test_context_across_batches<Polyhedron>();
  test_resumed_nearest_singularities("data/");
  test_context_refreshed_as_new<Surface_mesh>("data/");
  test_context_refreshed_as_new<Polyhedron>("data/");
  test_corpus();
  std::cout << "done" << std::endl;
  return EXIT_SUCCESS;
}
