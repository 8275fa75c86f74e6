// Tests of the singularity optimizer: batches of Q-zips, scoring, smoothing, features, protected regions.
#include "qzip_test_utils.h"

#include <CGAL/Qzip/optimize_singularities.h>
#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/preprocess.h>

#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

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

// protected faces keep their vertices and positions bit for bit; feature edges survive
void test_protection_and_features(const std::string& fandisk)
{
  Surface_mesh m;
  if(!read_mesh(fandisk, m)) { std::cerr << "cannot read " << fandisk << std::endl; assert(false); }
  Q::preprocess_valences(m);
  typedef boost::graph_traits<Surface_mesh>::edge_descriptor edge_descriptor;
  typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
  auto feature = m.add_property_map<edge_descriptor, bool>("e:feature", false).first;
  std::set<std::pair<Point, Point> > feature_segments;
  for(edge_descriptor e : edges(m))
  {
    const auto h = halfedge(e, m);
    if(is_border_edge(h, m)) continue;
    const auto n1 = PMP::compute_face_normal(face(h, m), m), n2 = PMP::compute_face_normal(face(opposite(h, m), m), m);
    if(n1 * n2 < std::cos(60. * CGAL_PI / 180.))
    {
      feature[e] = true;
      Point a = m.point(source(h, m)), b = m.point(target(h, m));
      if(b < a) std::swap(a, b);
      feature_segments.insert(std::make_pair(a, b));
    }
  }
  assert(!feature_segments.empty());
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
  std::set<std::pair<Point, Point> > after;
  for(edge_descriptor e : edges(m))
    if(feature[e])
    {
      Point a = m.point(source(halfedge(e, m), m)), b = m.point(target(halfedge(e, m), m));
      if(b < a) std::swap(a, b);
      after.insert(std::make_pair(a, b));
    }
  assert(after == feature_segments);
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
    const auto s = Q::optimize_singularities(m, CGAL::parameters::random_seed(1));
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
}

int main(int argc, char** argv)
{
  const std::string fandisk = argc > 1 ? argv[1] : "data/pmp_fandisk_quads.off";
  test_subdivision_sphere();
  test_policies();
  test_protection_and_features(fandisk);
  test_corpus();
  std::cout << "done" << std::endl;
  return EXIT_SUCCESS;
}
