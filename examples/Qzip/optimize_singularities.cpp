// Reduces the singularities of a quad mesh by batches of Q-zips (Feng, Tong, Desbrun 2021, Sec. 4.1).
// A quad-dominant input may have triangles: the optimizer pairs them (moves them towards each other and
// collides them into quads, Sec. 3.2) and the summary says how many are left. Faces with five or more
// sides are not supported: such an input is refused with one "error:" line.
//
// usage: optimize_singularities [IN [OUT]] [--batches N] [--time-limit SECONDS] [--seed S]
//                               [--feature-angle DEG] [--protect FACES.txt] [--no-smooth] [--weights E,I,S,X,P]
//                               [--quality-floor Q] [--json REPORT]
//
// Reads IN (default: the bundled Spot, CGAL::data_file_path("meshes/spot_quadrangulated.obj")),
// removes interior valence-2 vertices and splits valence-6+ ones (preprocess_valences()), optimizes,
// and writes OUT atomically (through a temporary file renamed over OUT). Without OUT nothing is written:
// only the before/after summary is printed. Progress goes to stderr.
//   --batches N         at most N batches (default: until the plateau, at most 200)
//   --time-limit S      start no batch (nor end-game step) once S seconds have passed since the start of the
//                       optimization (preprocessing excluded); the one under way finishes
//   --seed S            seed of the random choices (default 0); the result depends only on it
//   --feature-angle DEG edges whose dihedral angle exceeds DEG degrees are features: never crossed
//   --protect FILE      0-based indices of faces of IN, one per line: no edit reaches them
//   --no-smooth         no smoothing (surgeries that would invert a quad are undone)
//   --weights E,I,S,X,P the weights of Default_scoring's electric, isotropy, sizing, separatrix and pairing
//                       terms (default 1,0.02,0.02,0.02,0.3; their effect: benchmark/Qzip/RESULTS.md, session 25)
//   --quality-floor Q   no edit takes a quad below the scaled Jacobian Q, in (0, 1), unless the worst quad
//                       around it was already lower (default 0.1; higher keeps better quads, fewer surgeries pass)
//   --json REPORT       also write the before/after reports as JSON to REPORT

#include "qzip_example_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/optimize_singularities.h>
#include <CGAL/Qzip/preprocess.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::edge_descriptor          edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor          face_descriptor;

namespace Q = CGAL::Qzip;
namespace PMP = CGAL::Polygon_mesh_processing;

static const char* usage =
  "usage: optimize_singularities [IN [OUT]] [--batches N] [--time-limit SECONDS] [--seed S] "
  "[--feature-angle DEG] [--protect FACES.txt] [--no-smooth] [--weights E,I,S,X,P] [--quality-floor Q] [--json REPORT]";

// prints progress on stderr
struct Progress_visitor : public Q::Default_optimizer_visitor<Mesh>
{
  void on_batch_finished(const Q::Optimizer_statistics& s)
  {
    std::cerr << "  batch " << std::setw(3) << s.batch << ": " << s.number_of_singularities << " singularities, "
              << s.number_of_faces << " faces, " << s.surgeries_in_last_batch << " surgeries, "
              << std::fixed << std::setprecision(3) << s.elapsed_seconds << " s" << std::defaultfloat << std::endl;
  }
};

static bool parse_unsigned(const std::string& s, unsigned long& out)
{
  if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stoul(s);
  return true;
}

// reads the whole of s as a number (what std::istream reads as a double, nothing after it)
static bool parse_number(const std::string& s, double& out)
{
  std::istringstream is(s);
  return bool(is >> out) && is.eof();
}

// reads "E,I,S,X,P" (five finite non-negative numbers) into the weights of `scoring`
static bool parse_weights(const std::string& s, Q::Default_scoring& scoring)
{
  double* const weights[] = { &scoring.electric_weight, &scoring.isotropy_weight, &scoring.sizing_weight,
                              &scoring.separatrix_weight, &scoring.pairing_weight };
  double values[5];
  std::size_t begin = 0;
  for(int i = 0; i < 5; ++i)
  {
    const std::size_t end = i < 4 ? s.find(',', begin) : s.size();
    if(end == std::string::npos) return false;
    if(!parse_number(s.substr(begin, end - begin), values[i]) || !(values[i] >= 0 && values[i] < 1e9)) return false;
    begin = end + 1;
  }
  for(int i = 0; i < 5; ++i) *weights[i] = values[i];
  return true;
}

static void summary(std::ostream& os, const char* title, const Q::Mesh_report& r)
{
  os << title << ": " << r.number_of_quads << " quads, " << r.number_of_triangles << " triangles ("
     << r.number_of_canonical_triangles << " canonical); singularities: "
     << r.number_of_interior_valence_3_like << " v3-like + " << r.number_of_interior_valence_5_like
     << " v5-like interior, " << r.number_of_boundary_negative_defects << " negative + "
     << r.number_of_boundary_positive_defects << " positive boundary/feature = "
     << (r.number_of_interior_valence_3_like + r.number_of_interior_valence_5_like +
         r.number_of_boundary_negative_defects + r.number_of_boundary_positive_defects)
     << " (" << r.number_of_singularities_by_sector << " counting feature vertices by sector; lower bound ";
  if(r.has_singularity_lower_bound) os << r.singularity_lower_bound; else os << "n/a";
  os << "); scaled Jacobian min " << std::setprecision(4) << r.min_scaled_jacobian << " mean "
     << r.mean_scaled_jacobian << ", " << r.number_of_inverted_quads << " inverted\n";
}

int main(int argc, char** argv)
{
  const std::set<std::string> flags = { "--no-smooth", "--help", "-h" };
  const std::set<std::string> with_value = { "--batches", "--time-limit", "--seed", "--feature-angle", "--protect",
                                              "--weights", "--quality-floor", "--json" };
  if(qzip_example::has_flag(argc, argv, "--help") || qzip_example::has_flag(argc, argv, "-h"))
  {
    std::cout << usage << std::endl;
    return EXIT_SUCCESS;
  }
  const std::string bad = qzip_example::unknown_option(argc, argv, flags, with_value);
  if(!bad.empty())
  {
    std::cerr << "error: unknown option '" << bad << "' (" << usage << ")" << std::endl;
    return EXIT_FAILURE;
  }
  for(int i = 1; i < argc; ++i)
    if(with_value.count(argv[i]) && i + 1 >= argc)
    {
      std::cerr << "error: option '" << argv[i] << "' needs a value (" << usage << ")" << std::endl;
      return EXIT_FAILURE;
    }
  const std::vector<std::string> pos = qzip_example::positional_arguments(argc, argv, with_value);
  if(pos.size() > 2)
  {
    std::cerr << "error: expected at most an input and an output file (" << usage << ")" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string in = pos.empty() ? CGAL::data_file_path("meshes/spot_quadrangulated.obj") : pos[0];
  const std::string out = pos.size() > 1 ? pos[1] : std::string();

  unsigned long batches = 0, seed = 0;
  const std::string batches_s = qzip_example::option_value(argc, argv, "--batches");
  const std::string seed_s = qzip_example::option_value(argc, argv, "--seed");
  if(!batches_s.empty() && (!parse_unsigned(batches_s, batches) || batches == 0))
  { std::cerr << "error: --batches expects a positive integer, got '" << batches_s << "'" << std::endl; return EXIT_FAILURE; }
  if(!seed_s.empty() && !parse_unsigned(seed_s, seed))
  { std::cerr << "error: --seed expects a non-negative integer, got '" << seed_s << "'" << std::endl; return EXIT_FAILURE; }
  double time_limit = std::numeric_limits<double>::infinity();
  const std::string limit_s = qzip_example::option_value(argc, argv, "--time-limit");
  if(!limit_s.empty() && (!parse_number(limit_s, time_limit) || !(time_limit > 0 && time_limit < 1e9)))
  { std::cerr << "error: --time-limit expects a positive number of seconds, got '" << limit_s << "'" << std::endl; return EXIT_FAILURE; }
  double feature_angle = -1;
  const std::string angle_s = qzip_example::option_value(argc, argv, "--feature-angle");
  if(!angle_s.empty() && (!parse_number(angle_s, feature_angle) || !(feature_angle >= 0 && feature_angle <= 180)))
  { std::cerr << "error: --feature-angle expects an angle in degrees in [0, 180], got '" << angle_s << "'" << std::endl; return EXIT_FAILURE; }
  double quality_floor = 0.1;
  const std::string floor_s = qzip_example::option_value(argc, argv, "--quality-floor");
  if(!floor_s.empty() && (!parse_number(floor_s, quality_floor) || !(quality_floor > 0 && quality_floor < 1)))
  { std::cerr << "error: --quality-floor expects a scaled Jacobian in (0, 1), got '" << floor_s << "'" << std::endl; return EXIT_FAILURE; }
  Q::Default_scoring scoring;
  const std::string weights_s = qzip_example::option_value(argc, argv, "--weights");
  if(!weights_s.empty() && !parse_weights(weights_s, scoring))
  { std::cerr << "error: --weights expects five non-negative numbers E,I,S,X,P, got '" << weights_s << "'" << std::endl; return EXIT_FAILURE; }

  Mesh mesh;
  std::string error;
  if(!qzip_example::read_input_mesh(in, mesh, error, qzip_example::Accepted_faces::TRIANGLES_AND_QUADS))
  {
    std::cerr << "error: " << error << std::endl;
    return EXIT_FAILURE;
  }
  if(!out.empty() && qzip_example::same_file(in, out))
  {
    std::cerr << "error: output '" << out << "' is the input file; refusing to overwrite it" << std::endl;
    return EXIT_FAILURE;
  }

  // protected faces: indices of the faces of IN (Surface_mesh keeps the file order)
  Mesh::Property_map<face_descriptor, bool> fprot = mesh.add_property_map<face_descriptor, bool>("f:qzip_protected", false).first;
  std::size_t number_protected = 0;
  const std::string protect_file = qzip_example::option_value(argc, argv, "--protect");
  if(!protect_file.empty())
  {
    std::ifstream pf(protect_file);
    if(!pf) { std::cerr << "error: cannot open '" << protect_file << "'" << std::endl; return EXIT_FAILURE; }
    std::vector<face_descriptor> fs(faces(mesh).begin(), faces(mesh).end());
    std::string line;
    std::size_t line_number = 0;
    while(std::getline(pf, line))
    {
      ++line_number;
      if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
      std::istringstream is(line);
      long idx;
      std::string rest;
      if(!(is >> idx) || (is >> rest) || idx < 0 || std::size_t(idx) >= fs.size())
      {
        std::cerr << "error: " << protect_file << ":" << line_number << ": expected a face index in [0, "
                  << fs.size() << "), got '" << line << "'" << std::endl;
        return EXIT_FAILURE;
      }
      if(!fprot[fs[std::size_t(idx)]]) { fprot[fs[std::size_t(idx)]] = true; ++number_protected; }
    }
  }

  // features: dihedral angle above the threshold
  Mesh::Property_map<edge_descriptor, bool> efeat = mesh.add_property_map<edge_descriptor, bool>("e:qzip_feature", false).first;
  std::size_t number_features = 0;
  if(feature_angle >= 0)
  {
    const double cos_threshold = std::cos(feature_angle * CGAL_PI / 180.);
    for(edge_descriptor e : edges(mesh))
    {
      const auto h = halfedge(e, mesh);
      if(is_border_edge(h, mesh)) continue;
      const K::Vector_3 n1 = PMP::compute_face_normal(face(h, mesh), mesh);
      const K::Vector_3 n2 = PMP::compute_face_normal(face(opposite(h, mesh), mesh), mesh);
      if(n1 * n2 < cos_threshold) { efeat[e] = true; ++number_features; }
    }
  }

  std::cout << "input:  " << in << " (" << number_features << " feature edges, " << number_protected
            << " protected faces)\n";
  const Q::Mesh_report before = Q::compute_mesh_report(mesh, CGAL::parameters::edge_is_constrained_map(efeat));
  summary(std::cout, "before", before);

  CGAL::Real_timer timer;
  timer.start();
  // preprocessing must not reach protected faces either: their edges count as constrained there
  Mesh::Property_map<edge_descriptor, bool> efrozen = mesh.add_property_map<edge_descriptor, bool>("e:qzip_frozen", false).first;
  for(edge_descriptor e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    efrozen[e] = efeat[e] || (!is_border(h, mesh) && fprot[face(h, mesh)]) ||
                 (!is_border(opposite(h, mesh), mesh) && fprot[face(opposite(h, mesh), mesh)]);
  }
  const Q::Preprocess_result pre = Q::preprocess_valences(mesh, CGAL::parameters::edge_is_constrained_map(efrozen));
  mesh.remove_property_map(efrozen);
  std::cout << "scoring weights: electric " << scoring.electric_weight << ", isotropy " << scoring.isotropy_weight
            << ", sizing " << scoring.sizing_weight << ", separatrix " << scoring.separatrix_weight << ", pairing "
            << scoring.pairing_weight << "; quality floor " << quality_floor << "\n";
  std::cerr << "preprocessing: " << pre.removed_valence_2 << " valence-2 vertices removed, " << pre.vertex_splits
            << " vertex splits" << std::endl;

  Progress_visitor progress;
  Q::Optimizer_result stats;
  const bool smooth = !qzip_example::has_flag(argc, argv, "--no-smooth");
  const auto common = Q::parameters::scoring_functor(scoring, Q::parameters::quality_floor(quality_floor,
                        Q::parameters::face_is_constrained_map(fprot,
                          CGAL::parameters::edge_is_constrained_map(efeat).random_seed(unsigned(seed)).visitor(std::ref(progress))
                            .maximum_running_time(time_limit))));
  if(batches > 0)
    stats = Q::optimize_singularities(mesh, Q::parameters::combine(common, Q::parameters::do_smooth(smooth),
              Q::parameters::stop_predicate(Q::stop_when_either(Q::Batch_count_stop_predicate(batches),
                                                                Q::No_progress_stop_predicate()))));
  else
    stats = Q::optimize_singularities(mesh, Q::parameters::combine(common, Q::parameters::do_smooth(smooth)));
  timer.stop();

  const Q::Mesh_report after = Q::compute_mesh_report(mesh, CGAL::parameters::edge_is_constrained_map(efeat));
  summary(std::cout, "after ", after);
  if(stats.initial_number_of_triangles > 0)
    std::cout << "triangles: " << stats.initial_number_of_triangles << " -> " << stats.number_of_triangles << " ("
              << stats.number_of_triangle_collisions << " collisions kept, " << stats.number_of_undone_triangle_paths
              << " attempts undone)\n";
  std::cout << "optimizer: " << stats.batch << " batches, " << stats.number_of_surgeries << " surgeries kept, "
            << stats.number_of_undone_surgeries << " undone, " << stats.number_of_failed_surgeries
            << " rolled back by the primitive; time " << std::setprecision(3) << timer.time()
            << " s (preprocessing included; scoring " << stats.scoring_seconds << " s, execution and smoothing "
            << stats.execution_seconds << " s)\n";
  if(stats.reached_time_limit)
    std::cout << "stopped at the time limit (" << time_limit << " s): more batches would have run\n";

  mesh.remove_property_map(fprot);
  mesh.remove_property_map(efeat);
  if(!out.empty())
  {
    mesh.collect_garbage();
    if(!qzip_example::write_output_mesh_atomically(out, mesh, error, in))
    {
      std::cerr << "error: " << error << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << out << "\n";
  }
  else
    std::cout << "no output file given: nothing written\n";

  const std::string json = qzip_example::option_value(argc, argv, "--json");
  if(!json.empty())
  {
    std::ofstream js(json);
    if(!js) { std::cerr << "error: cannot write '" << json << "'" << std::endl; return EXIT_FAILURE; }
    js << "{\n\"input\": \"" << in << "\",\n\"before\": ";
    Q::write_json(js, before);
    js << ",\n\"after\": ";
    Q::write_json(js, after);
    js << ",\n\"optimizer\": {\"batches\": " << stats.batch << ", \"surgeries\": " << stats.number_of_surgeries
       << ", \"triangles_before\": " << stats.initial_number_of_triangles << ", \"triangles_after\": "
       << stats.number_of_triangles << ", \"triangle_collisions\": " << stats.number_of_triangle_collisions
       << ", \"undone\": " << stats.number_of_undone_surgeries << ", \"failed\": " << stats.number_of_failed_surgeries
       << ", \"seed\": " << seed << ", \"smoothing\": " << (smooth ? "true" : "false")
       << ", \"seconds\": " << timer.time() << ", \"reached_time_limit\": " << (stats.reached_time_limit ? "true" : "false")
       << "}\n}\n";
    if(!js) { std::cerr << "error: cannot write '" << json << "'" << std::endl; return EXIT_FAILURE; }
  }
  return EXIT_SUCCESS;
}
