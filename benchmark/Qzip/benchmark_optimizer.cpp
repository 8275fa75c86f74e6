// Benchmark of CGAL::Qzip::optimize_singularities(): the shared corpus, Catmull-Clark refinements of a
// corpus mesh (time against size, up to ~1M quads), and a genus-3 "robustness test" (paper, Fig. 17).
// Prints markdown tables on stdout (progress on stderr).
//
// usage: benchmark_optimizer [--corpus DIR] [--runs R] [--max-level L] [--skip-corpus] [--skip-large]
//                            [--skip-genus3] [--measure] [--mesh FILE]... [--trace]
//                            [--max-batches N] [--patience N] [--count-stop] [--seed S] [--min-level L]
//                            [--fingerprint] [--seeds N] [--first-seed S] [--time-limit S] [--quality-floor Q]
//   --runs R       runs per mesh below 100k quads, the median time is reported (default 3)
//   --max-level L  Catmull-Clark levels of the scaling series (default 4: ~1M quads)
//   --min-level L  run the scaling series from this level on (default 0; the lower levels are still built)
//   --fingerprint  print a hash of the sorted vertex positions of each result (to check that a change
//                  meant to be exact gives the same meshes)
//   --measure      recount the singularities after every surgery (slow) to measure how often the change
//                  predicted from the plan is the actual one (meshes below 20k quads)
//   --mesh FILE    only this mesh (repeatable): no corpus, scaling series nor genus-3 test
//   --trace        print every batch of the last run on stderr (singularities, faces, wall and CPU time)
//   --max-batches N, --patience N  the parameters of the Default_stop_predicate of the runs (200, 20)
//   --count-stop   stop on No_improvement_stop_predicate (fewer singularities) instead of on progress
//   --seed S       the random seed of the runs (default 0)
//   --time-limit S the maximum_running_time of the runs, in seconds (default: none)
//   --quality-floor Q  the quality_floor of the runs, a scaled Jacobian in (0, 1) (default 0.1)
//   --seeds N      one run for each of the seeds 0 to N-1 of every selected mesh (--mesh, else the corpus),
//                  and a table of the spread of the results (final count, its mean and standard error, faces,
//                  time to the plateau, time until the median final count over the seeds was first reached)
//   --first-seed S with --seeds N: the seeds S to S+N-1 (to split a spread over several processes)
// Meshes read from files are read again for every run (not copied), so a run optimizes the mesh the example
// optimizes; the Catmull-Clark and genus-3 meshes, built in memory, are copied.
// The summary line of each mesh on stderr also gives the median CPU time of the process (std::clock())
// during optimize_singularities(), less sensitive than wall time to other jobs on the machine, and the
// median CPU time until the number of singularities last changed (the plateau; the tables' "to plateau"
// column): a run goes on for a while after it, until its stop predicate gives up. The tables' "to the bound"
// column is the CPU time until the count first was within the target for closed pure-quad meshes
// (2·|4χ| plus 1% of the input's faces; "n/a" for the other meshes).

#include "qzip_test_utils.h"
#include "qzip_input_surface.h"

#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/optimize_singularities.h>
#include <CGAL/Qzip/preprocess.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

using namespace qzip_test;
namespace Q = CGAL::Qzip;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef Surface_mesh Mesh;

struct Measure_visitor : public Q::Default_optimizer_visitor<Mesh>
{
  const Mesh* mesh = nullptr;
  std::size_t count = 0, exact = 0, surgeries = 0;
  void on_started(const Q::Optimizer_statistics& s) { count = s.number_of_singularities; }
  void on_surgery(const Q::Surgery_plan<Mesh>&, double, int predicted)
  {
    ++surgeries;
    const std::size_t now = Q::compute_mesh_report(*mesh).total_absolute_defect;
    if(long(now) - long(count) == predicted) ++exact;
    count = now;
  }
  void on_batch_finished(const Q::Optimizer_statistics& s) { count = s.number_of_singularities; }
};

static bool trace = false;
static std::size_t max_batches = 200, patience = 20;
static double time_limit = std::numeric_limits<double>::infinity();
static double quality_floor = 0.1;
static unsigned int seed = 0;
static bool count_stop = false;
static bool fingerprint = false;

// a hash of the sorted vertex positions of m (independent of the vertex order)
static std::size_t position_fingerprint(const Mesh& m)
{
  std::vector<std::array<double, 3> > ps;
  for(auto v : vertices(m)) ps.push_back({{ m.point(v).x(), m.point(v).y(), m.point(v).z() }});
  std::sort(ps.begin(), ps.end());
  std::size_t h = ps.size();
  for(const auto& p : ps)
    for(double x : p) h = h * 1000003u ^ std::hash<double>()(x);
  return h;
}

// the stop predicate of the runs: the default one with the parameters given on the command line, or
// (--count-stop) the same with No_improvement_stop_predicate (progress = fewer singularities only)
struct Bench_stop
{
  bool operator()(const Q::Optimizer_statistics& s) const
  {
    if(count_stop) return s.batch >= max_batches || Q::No_improvement_stop_predicate(patience)(s);
    return Q::Default_stop_predicate(max_batches, patience)(s);
  }
};

// records when the number of singularities changed and when it first reached the target (CPU time of
// the process since `start`, set by the caller to the call of optimize_singularities()), and prints every batch
// with --trace
struct Trace_visitor : public Q::Default_optimizer_visitor<Mesh>
{
  bool print = false;
  std::clock_t start = 0;
  // the CPU seconds at which the count last took its current value
  double count_since = 0;
  std::size_t count = 0;
  // the target count (see target_count(), negative: none) and the CPU seconds at which the count first was at
  // most that (negative: not yet)
  double target = -1;
  double target_since = -1;
  // first_at_most[n]: the CPU seconds at which the count first was at most n (negative: not yet)
  std::vector<double> first_at_most;
  std::size_t lowest = 0; // the lowest count so far
  double cpu_seconds() const { return double(std::clock() - start) / CLOCKS_PER_SEC; }
  void record_target(std::size_t n)
  {
    if(target >= 0 && target_since < 0 && double(n) <= target) target_since = cpu_seconds();
    for(; lowest > n; --lowest) first_at_most[lowest - 1] = cpu_seconds();
  }
  void record(const Q::Optimizer_statistics& s)
  {
    record_target(s.number_of_singularities);
    if(s.number_of_singularities == count) return;
    count = s.number_of_singularities;
    count_since = cpu_seconds();
  }
  void on_started(const Q::Optimizer_statistics& s)
  {
    count = s.number_of_singularities;
    count_since = cpu_seconds();
    first_at_most.assign(count + 1, -1.);
    first_at_most[count] = cpu_seconds();
    lowest = count;
    record_target(count);
  }
  void on_batch_finished(const Q::Optimizer_statistics& s)
  {
    record(s);
    if(!print) return;
    std::cerr << "    batch " << s.batch << ": " << s.number_of_singularities << " singularities, " << s.number_of_faces
              << " faces, pairing distance " << s.pairing_distance << ", " << s.candidates_in_last_batch << " candidates, " << s.surgeries_in_last_batch << " surgeries (so far " << s.number_of_skipped_surgeries << " skipped, " << s.number_of_replanned_surgeries << " replanned, " << s.number_of_undone_surgeries << " undone, " << s.number_of_failed_surgeries << " failed), " << s.elapsed_seconds << " s (scoring "
              << s.scoring_seconds << ", execution " << s.execution_seconds << "), CPU "
              << cpu_seconds() << " s" << std::endl;
  }
  void on_finished(const Q::Optimizer_statistics& s) { record(s); }
};

struct Row
{
  std::string name;
  Q::Mesh_report before, after;
  Q::Optimizer_statistics stats;
  double seconds = 0;
  double plateau_seconds = 0; // CPU seconds until the final number of singularities was reached (median)
  double cpu_seconds = 0;     // CPU seconds of optimize_singularities() (median)
  // CPU seconds until the number of singularities first was at most the target (see target_count()): the
  // median over the runs, negative if a run never reached it or the mesh has no target
  double target_seconds = -1;
  std::vector<double> first_at_most; // of the last run, see Trace_visitor
  std::array<double, 3> off_surface = {{ 0, 0, 0 }}; // see off_surface()
  std::string exact;
  std::size_t fingerprint = 0;
};

static std::string fmt(double x, int p = 3)
{
  std::ostringstream os;
  os << std::fixed << std::setprecision(p) << x;
  return os.str();
}

static std::size_t singular(const Q::Mesh_report& r)
{
  return r.number_of_interior_valence_3_like + r.number_of_interior_valence_5_like +
         r.number_of_boundary_negative_defects + r.number_of_boundary_positive_defects;
}

// the target for a closed pure-quad mesh, 2·|4χ| plus 1% of its faces (negative when the report has no
// lower bound: a border, or triangles)
static double target_count(const Q::Mesh_report& r)
{
  if(!r.has_singularity_lower_bound) return -1;
  return 2. * double(r.singularity_lower_bound) + 0.01 * double(r.number_of_faces);
}

// how far the vertices of `result` lie from the surface of `input` (see qzip_test::Input_surface), in mean edge
// lengths of `input`: the largest distance, the mean one, and the number of vertices farther than a tenth of an edge
static std::array<double, 3> off_surface(const Mesh& input, const Mesh& result)
{
  const qzip_test::Input_surface<K> surface(input);
  std::array<double, 3> out = {{ 0, 0, 0 }};
  for(auto v : vertices(result))
  {
    const double d = surface.distance(result.point(v));
    out[0] = (std::max)(out[0], d);
    out[1] += d;
    if(d > 0.1) ++out[2];
  }
  out[1] /= double(num_vertices(result));
  return out;
}

// gives a fresh copy of the input of a row, preprocessed (preprocess_valences()): read again from its file, as
// the example optimizes it (the halfedge order of a copy differs, and so does the trajectory of a run), or
// copied from a mesh built in memory
typedef std::function<void(Mesh&)> Input;

static Input from_file(const std::string& path)
{
  return [path](Mesh& m)
  {
    if(!read_mesh(path, m)) throw std::runtime_error("cannot read " + path + " again");
    Q::preprocess_valences(m);
  };
}

static Input from_memory(const Mesh& built)
{
  auto copy = std::make_shared<Mesh>(built);
  return [copy](Mesh& m)
  {
    copy_mesh(*copy, m);
    Q::preprocess_valences(m);
  };
}

// optimizes the input `runs` times; the median time is kept
static Row run(const std::string& name, const Input& input, int runs, bool measure)
{
  Row row;
  row.name = name;
  Mesh pre;
  input(pre);
  row.before = Q::compute_mesh_report(pre);
  std::vector<double> times, cpu, plateau, to_target;
  for(int i = 0; i < runs; ++i)
  {
    Mesh m;
    input(m);
    CGAL::Real_timer t;
    const std::clock_t c0 = std::clock();
    t.start();
    Trace_visitor tracer;
    tracer.print = trace && i + 1 == runs;
    tracer.start = c0;
    tracer.target = target_count(row.before);
    row.stats = Q::optimize_singularities(m, Q::parameters::stop_predicate(Bench_stop(), Q::parameters::quality_floor(quality_floor,
                                                 CGAL::parameters::random_seed(seed).visitor(std::ref(tracer)).maximum_running_time(time_limit))));
    t.stop();
    times.push_back(t.time());
    cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
    plateau.push_back(tracer.count_since);
    to_target.push_back(tracer.target_since);
    if(i + 1 == runs)
    {
      row.first_at_most = tracer.first_at_most;
      row.after = Q::compute_mesh_report(m);
      row.fingerprint = position_fingerprint(m);
      row.off_surface = off_surface(pre, m);
      if(measure && row.before.number_of_faces < 20000)
      {
        Mesh mm;
        input(mm);
        Measure_visitor vis;
        vis.mesh = &mm;
        Q::optimize_singularities(mm, Q::parameters::quality_floor(quality_floor, CGAL::parameters::random_seed(seed).visitor(std::ref(vis))));
        row.exact = std::to_string(vis.exact) + "/" + std::to_string(vis.surgeries);
      }
    }
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu.begin(), cpu.end());
  std::sort(plateau.begin(), plateau.end());
  row.seconds = times[times.size() / 2];
  row.plateau_seconds = plateau[plateau.size() / 2];
  row.cpu_seconds = cpu[cpu.size() / 2];
  std::sort(to_target.begin(), to_target.end());
  if(to_target.front() >= 0) row.target_seconds = to_target[to_target.size() / 2];
  std::cerr << "  " << name << ": " << singular(row.before) << " -> " << singular(row.after) << " singularities, "
            << row.before.number_of_faces << " -> " << row.after.number_of_faces << " faces, " << row.stats.batch << " batches + " << row.stats.end_game_rounds << " end-game rounds, "
            << fmt(row.seconds) << " s (CPU " << fmt(cpu[cpu.size() / 2]) << " s, final count after "
            << fmt(row.plateau_seconds) << " s)";
  if(fingerprint) std::cerr << ", fingerprint " << std::hex << row.fingerprint << std::dec;
  std::cerr << std::endl;
  return row;
}

static void print_header(bool measure)
{
  std::cout << "| mesh | faces before → after (Δ%) | singularities before → after | v3 / v5 after (interior) | bound 2·|4χ| + 1% F | "
               "min / mean SJ before | min / mean SJ after | inverted after | off surface: max / mean (edges), vertices > 0.1 | batches | time (s) | to plateau (CPU s) | to the bound (CPU s) |"
            << (measure ? " exact predictions |" : "") << "\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|" << (measure ? "---|" : "") << "\n";
}

static void print_row(const Row& r, bool measure)
{
  const double df = 100. * (double(r.after.number_of_faces) - double(r.before.number_of_faces)) / double(r.before.number_of_faces);
  std::cout << "| " << r.name << " | " << r.before.number_of_faces << " → " << r.after.number_of_faces << " ("
            << (df >= 0 ? "+" : "") << fmt(df, 1) << ") | " << singular(r.before) << " → " << singular(r.after) << " | "
            << r.after.number_of_interior_valence_3_like << " / " << r.after.number_of_interior_valence_5_like << " | ";
  if(r.before.has_singularity_lower_bound)
  {
    const double target = target_count(r.before);
    std::cout << r.before.singularity_lower_bound << ": " << fmt(target, 0) << (double(singular(r.after)) <= target ? " ✓" : " ✗");
  }
  else std::cout << "n/a";
  std::cout << " | " << fmt(r.before.min_scaled_jacobian) << " / " << fmt(r.before.mean_scaled_jacobian) << " | "
            << fmt(r.after.min_scaled_jacobian) << " / " << fmt(r.after.mean_scaled_jacobian) << " | "
            << r.after.number_of_inverted_quads << (r.before.number_of_inverted_quads > 0 ? " (input: " + std::to_string(r.before.number_of_inverted_quads) + ")" : std::string())
            << " | " << fmt(r.off_surface[0], 2) << " / " << fmt(r.off_surface[1], 4) << ", " << r.off_surface[2]
            << " | " << r.stats.batch << " | " << fmt(r.seconds) << " | " << fmt(r.plateau_seconds) << " | "
            << (r.target_seconds >= 0 ? fmt(r.target_seconds) : r.before.has_singularity_lower_bound ? "not reached" : "n/a")
            << " |" << (measure ? " " + r.exact + " |" : "") << "\n";
}

// --seeds N: one run for each of the seeds 0 to N-1, and the spread of the results (the trajectory of a run,
// and with it its time, depends on the seed)
static void print_spread_header()
{
  std::cout << "| mesh | singularities before | after: min / median / max | after: mean ± s.e. | faces Δ%: min / max | "
               "inverted after: max | off surface (edges): max / largest mean | to plateau (CPU s): min / median / max | "
               "CPU s: min / median / max | to the median count (CPU s): median | to the bound (CPU s): min / median / max |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|\n";
}

static void print_spread(const std::string& name, const Input& input, unsigned int first_seed, unsigned int seeds)
{
  std::vector<double> after, faces_change, plateau, cpu, to_target;
  std::vector<std::vector<double> > first_at_most;
  std::size_t before = 0, inverted = 0;
  bool has_target = false;
  double off_max = 0, off_mean = 0;
  for(unsigned int s = first_seed; s < first_seed + seeds; ++s)
  {
    seed = s;
    const Row r = run(name + " seed " + std::to_string(s), input, 1, false);
    before = singular(r.before);
    after.push_back(double(singular(r.after)));
    faces_change.push_back(100. * (double(r.after.number_of_faces) - double(r.before.number_of_faces)) /
                           double(r.before.number_of_faces));
    inverted = (std::max)(inverted, r.after.number_of_inverted_quads);
    plateau.push_back(r.plateau_seconds);
    cpu.push_back(r.cpu_seconds);
    has_target = r.before.has_singularity_lower_bound;
    if(r.target_seconds >= 0) to_target.push_back(r.target_seconds);
    first_at_most.push_back(r.first_at_most);
    off_max = (std::max)(off_max, r.off_surface[0]);
    off_mean = (std::max)(off_mean, r.off_surface[1]);
  }
  auto spread = [](std::vector<double> x, int precision)
  {
    std::sort(x.begin(), x.end());
    return fmt(x.front(), precision) + " / " + fmt(x[x.size() / 2], precision) + " / " + fmt(x.back(), precision);
  };
  // the mean final count and its standard error; the CPU time until each run first reached the median final
  // count (a run that never did counts as infinitely slow: at least half of them did)
  double mean = 0, variance = 0;
  for(double a : after) mean += a;
  mean /= double(after.size());
  for(double a : after) variance += (a - mean) * (a - mean);
  const double standard_error = after.size() > 1 ? std::sqrt(variance / double(after.size() - 1) / double(after.size())) : 0.;
  std::vector<double> sorted_after = after;
  std::sort(sorted_after.begin(), sorted_after.end());
  const std::size_t median_count = std::size_t(sorted_after[sorted_after.size() / 2]);
  std::vector<double> to_median;
  for(const std::vector<double>& f : first_at_most)
    to_median.push_back(median_count < f.size() && f[median_count] >= 0 ? f[median_count]
                                                                        : std::numeric_limits<double>::infinity());
  std::sort(to_median.begin(), to_median.end());
  std::sort(faces_change.begin(), faces_change.end());
  std::cout << "| " << name << " | " << before << " | " << spread(after, 0) << " | " << fmt(mean, 2) << " ± "
            << fmt(standard_error, 2) << " | " << fmt(faces_change.front(), 1)
            << " / " << fmt(faces_change.back(), 1) << " | " << inverted << " | " << fmt(off_max, 2) << " / "
            << fmt(off_mean, 4) << " | " << spread(plateau, 2) << " | "
            << spread(cpu, 2) << " | " << fmt(to_median[to_median.size() / 2], 2) << " (≤ " << median_count << ") | ";
  if(!has_target) std::cout << "n/a";
  else if(to_target.size() == seeds) std::cout << spread(to_target, 2);
  else std::cout << "reached on " << to_target.size() << " of " << seeds << " seeds";
  std::cout << " |" << std::endl;
}

int main(int argc, char** argv)
{
  std::string corpus = QZIP_SHARED_DATA_DIR;
  int runs = 3, max_level = 4, min_level = 0;
  unsigned int seeds = 0, first_seed = 0;
  bool skip_corpus = false, skip_large = false, skip_genus3 = false, measure = false;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--corpus" && i + 1 < argc) corpus = argv[++i];
    else if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--max-level" && i + 1 < argc) max_level = std::atoi(argv[++i]);
    else if(a == "--min-level" && i + 1 < argc) min_level = std::atoi(argv[++i]);
    else if(a == "--fingerprint") fingerprint = true;
    else if(a == "--skip-corpus") skip_corpus = true;
    else if(a == "--skip-large") skip_large = true;
    else if(a == "--skip-genus3") skip_genus3 = true;
    else if(a == "--measure") measure = true;
    else if(a == "--trace") trace = true;
    else if(a == "--max-batches" && i + 1 < argc) max_batches = std::size_t(std::atoi(argv[++i]));
    else if(a == "--patience" && i + 1 < argc) patience = std::size_t(std::atoi(argv[++i]));
    else if(a == "--time-limit" && i + 1 < argc) time_limit = std::atof(argv[++i]);
    else if(a == "--quality-floor" && i + 1 < argc)
    {
      quality_floor = std::atof(argv[++i]);
      if(!(quality_floor > 0 && quality_floor < 1))
      { std::cerr << "error: --quality-floor expects a number in (0, 1), got '" << argv[i] << "'" << std::endl; return EXIT_FAILURE; }
    }
    else if(a == "--count-stop") count_stop = true;
    else if(a == "--seed" && i + 1 < argc) seed = unsigned(std::atoi(argv[++i]));
    else if(a == "--seeds" && i + 1 < argc) seeds = unsigned(std::max(1, std::atoi(argv[++i])));
    else if(a == "--first-seed" && i + 1 < argc) first_seed = unsigned(std::max(0, std::atoi(argv[++i])));
    else if(a == "--mesh" && i + 1 < argc) meshes.push_back(argv[++i]);
    else { std::cerr << "error: unknown argument '" << a << "'" << std::endl; return EXIT_FAILURE; }
  }

  if(seeds > 0)
  {
    if(meshes.empty() && file_exists(corpus + "/SOURCES.md"))
      for(const std::string& f : shared_corpus_files()) meshes.push_back(corpus + "/" + f);
    if(meshes.empty()) { std::cout << "corpus not found at " << corpus << " and no --mesh: nothing to run\n"; return EXIT_SUCCESS; }
    std::cout << "\n### Spread over seeds " << first_seed << "-" << first_seed + seeds - 1
              << " (default parameters, one run per seed)\n\n";
    print_spread_header();
    for(const std::string& f : meshes)
    {
      Mesh m;
      if(!read_mesh(f, m)) { std::cout << "| " << f << " | unreadable |\n"; continue; }
      print_spread(f.substr(f.find_last_of('/') + 1), from_file(f), first_seed, seeds);
    }
    return EXIT_SUCCESS;
  }

  if(!meshes.empty())
  {
    std::cout << "\n### Selected meshes (default parameters, seed " << seed << ", median of " << runs << " runs)\n\n";
    print_header(measure);
    for(const std::string& f : meshes)
    {
      Mesh m;
      if(!read_mesh(f, m)) { std::cout << "| " << f << " | unreadable |\n"; continue; }
      print_row(run(f, from_file(f), runs, measure), measure);
    }
    return EXIT_SUCCESS;
  }

  if(!skip_corpus)
  {
    if(!file_exists(corpus + "/SOURCES.md"))
      std::cout << "corpus not found at " << corpus << ": skipped\n";
    else
    {
      std::cout << "\n### Shared corpus (default parameters, seed " << seed << ", median of " << runs << " runs)\n\n";
      print_header(measure);
      for(const std::string& f : shared_corpus_files())
      {
        Mesh m;
        if(!read_mesh(corpus + "/" + f, m)) { std::cout << "| " << f << " | unreadable |\n"; continue; }
        print_row(run(f, from_file(corpus + "/" + f), faces(m).size() < 100000 ? runs : 1, measure), measure);
      }
    }
  }

  if(!skip_large)
  {
    const std::string base = corpus + "/quadriflow_gargoyle.obj";
    Mesh m;
    if(!read_mesh(base, m)) read_mesh(CGAL::data_file_path("meshes/spot_quadrangulated.obj"), m);
    std::cout << "\n### Catmull-Clark refinements of quadriflow_gargoyle.obj (time against size)\n\n";
    print_header(false);
    for(int level = 0; level <= max_level; ++level)
    {
      if(level > 0) CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1));
      const std::size_t n = faces(m).size();
      if(level < min_level) continue;
      print_row(run("gargoyle CC" + std::to_string(level) + " (" + std::to_string(n) + " quads)", from_memory(m), n < 100000 ? runs : 1, false), false);
    }
  }

  if(!skip_genus3)
  {
    std::cout << "\n### Genus-3 robustness test (voxel plate with 3 holes, triangulated, Catmull-Clark; expected optimum: 16 v5)\n\n";
    print_header(false);
    for(int levels = 1; levels <= 2; ++levels)
    {
      Mesh m;
      make_genus3_voxel_plate(m);
      PMP::triangulate_faces(m);
      CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(levels));
      print_row(run("genus-3 plate, triangulated, CC" + std::to_string(levels), from_memory(m), runs, false), false);
    }
  }
  return EXIT_SUCCESS;
}
