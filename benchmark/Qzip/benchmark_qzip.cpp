// Times the Q-zip primitive on real meshes: path search, planning, execution and undo, by path length,
// with a plain breadth-first search between the same two vertices as the floor. Each Q-zip is planned
// twice (in alternating order): with the simulation of its execution (the default) and without
// (`simulate_chain(false)`), to measure what the simulation costs; and executed twice (in alternating
// order, undone in between): by `execute_qzip()`, which records the reverse Q-zip, and by the bare executor
// (internal::Chain_executor_of), to measure what the recording costs.
//
// usage: benchmark_qzip [N per mesh = 2000] [mesh files...]   (default: bundled meshes + shared corpus)

#include "qzip_test_utils.h"

#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/qzip.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <deque>

using namespace qzip_test;
namespace Q = CGAL::Qzip;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;
// The times are the CPU time of this thread, in microseconds: the benchmark runs on machines shared with
// other processes, whose time a wall clock would count. Reading the clock costs about 0.14 us, which every
// figure includes.
struct Clock
{
  typedef double time_point;
  static time_point now()
  {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e6 + double(t.tv_nsec) * 1e-3;
  }
};

static double micro(Clock::time_point a, Clock::time_point b) { return b - a; }

struct Sample { std::size_t length; double path, plan, plan_unsimulated, exec, exec_bare, undo, bfs; };

// the floor: a plain BFS from s until t, with a visited stamp array (no allocation per search)
struct Plain_bfs
{
  std::vector<unsigned> stamp;
  unsigned current = 0;
  std::vector<vertex_descriptor> queue;
  std::size_t run(const Surface_mesh& m, vertex_descriptor s, vertex_descriptor t)
  {
    if(stamp.size() < num_vertices(m)) stamp.assign(num_vertices(m), 0);
    ++current;
    queue.clear();
    queue.push_back(s);
    stamp[s] = current;
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      const vertex_descriptor v = queue[i];
      if(v == t) return i;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      {
        const vertex_descriptor u = source(h, m);
        if(stamp[u] != current) { stamp[u] = current; queue.push_back(u); }
      }
    }
    return queue.size();
  }
};

static double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
static double percentile(std::vector<double> v, double p)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

static bool singular(vertex_descriptor v, const Surface_mesh& m)
{
  return !on_border(v, m) && valence(v, m) != 4;
}

void run(const std::string& file, std::size_t count, std::vector<Sample>& all)
{
  Surface_mesh m;
  if(!read_mesh(file, m)) { std::printf("cannot read %s\n", file.c_str()); return; }
  Q::preprocess_valences(m);
  m.collect_garbage();
  CGAL::Random rng(42);
  Plain_bfs bfs;
  Q::Qzip_history<Surface_mesh> history(m);
  std::vector<Sample> samples;
  std::size_t refused = 0, attempts = 0, unpaired = 0, simulation_refused = 0;
  typedef Q::internal::Chain_executor_of<Surface_mesh, boost::property_map<Surface_mesh, CGAL::vertex_point_t>::type,
                                         CGAL::parameters::Default_named_parameters> Bare_executor;
  while(samples.size() < count && attempts < 20 * count)
  {
    ++attempts;
    std::vector<vertex_descriptor> sing;
    for(auto v : vertices(m)) if(singular(v, m)) sing.push_back(v);
    if(sing.size() < 2) break;
    const vertex_descriptor s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
    // a singularity at a random distance up to 32 edges
    const int reach = rng.get_int(1, 33);
    const std::vector<vertex_descriptor> candidates = singularities_within(m, s, reach / 2, reach);
    if(candidates.empty()) continue;
    const vertex_descriptor t = candidates[std::size_t(rng.get_int(0, int(candidates.size())))];

    Sample x;
    auto t0 = Clock::now();
    const auto path = Q::shortest_surgery_path(m, s, t);
    auto t1 = Clock::now();
    if(path.empty()) continue;
    const Q::Strip_operation motion = Q::Strip_operation(rng.get_int(0, 4));
    // planned with and without the simulation, alternately first
    auto plan_timed = [&](bool simulate)
    {
      const auto p0 = Clock::now();
      auto p = Q::plan_qzip(m, path, motion, Q::parameters::simulate_chain(simulate));
      return std::make_pair(p, micro(p0, Clock::now()));
    };
    const bool simulated_first = attempts % 2 == 0;
    std::pair<Q::Surgery_plan<Surface_mesh>, double> unsimulated;
    if(!simulated_first) unsimulated = plan_timed(false);
    const auto simulated = plan_timed(true);
    if(simulated_first) unsimulated = plan_timed(false);
    const auto& plan = simulated.first;
    x.plan = simulated.second;
    x.plan_unsimulated = unsimulated.second;
    if(!plan.is_realizable())
    {
      ++refused;
      if(plan.status == Q::Plan_status::EXECUTION_WOULD_FAIL) ++simulation_refused;
      continue;
    }
    // the bare executor, before or after the recording one (alternately): the undo gives back the same
    // descriptors on Surface_mesh (its free lists are last in, first out), checked by the counts
    auto bare = [&]()
    {
      const auto b0 = Clock::now();
      Bare_executor exec(m, history.operation_log(), CGAL::parameters::default_values());
      const auto rb = exec.run(plan);
      const auto b1 = Clock::now();
      if(rb.is_done()) history.undo_last();
      return std::make_pair(rb, micro(b0, b1));
    };
    const bool bare_first = samples.size() % 2 == 1;
    std::pair<Q::Qzip_result<Surface_mesh>, double> rb;
    if(bare_first) rb = bare();
    const auto e0 = Clock::now();
    const auto r = Q::execute_qzip(m, plan, history);
    const auto e1 = Clock::now();
    if(!r.is_done()) { ++refused; continue; }
    history.undo_last();
    const auto e2 = Clock::now();
    if(!bare_first) rb = bare();
    x.exec_bare = rb.second;
    if(!rb.first.is_done() || rb.first.number_of_collapses != r.number_of_collapses ||
       rb.first.number_of_splits != r.number_of_splits)
    { ++unpaired; x.exec_bare = -1; }
    const auto f0 = Clock::now();
    bfs.run(m, s, t);
    const auto f1 = Clock::now();
    x.length = path.size() - 1;
    x.path = micro(t0, t1); x.exec = micro(e0, e1); x.undo = micro(e1, e2); x.bfs = micro(f0, f1);
    samples.push_back(x);
  }
  std::vector<double> exec, path;
  for(const Sample& x : samples) { exec.push_back(x.exec); path.push_back(x.path); }
  std::printf("| %s | %zu | %zu | %zu | %zu | %.1f | %.1f |\n", file.substr(file.find_last_of('/') + 1).c_str(),
              std::size_t(faces(m).size()), samples.size(), refused, simulation_refused, median(exec), median(path));
  if(unpaired != 0) std::fprintf(stderr, "%s: %zu Q-zips whose bare execution differed (not compared)\n", file.c_str(), unpaired);
  all.insert(all.end(), samples.begin(), samples.end());
}

int main(int argc, char** argv)
{
  const std::size_t count = argc > 1 ? std::size_t(std::atoi(argv[1])) : 2000;
  std::vector<std::string> files;
  for(int i = 2; i < argc; ++i) files.push_back(argv[i]);
  if(files.empty())
  {
    const std::string dir = shared_corpus_dir("benchmark on the shared corpus");
    if(!dir.empty())
    {
      for(const std::string& f : shared_corpus_files())
        if(f != "trimesh_quadknot.obj") files.push_back(dir + "/" + f);
    }
    else
      files = { CGAL::data_file_path("meshes/spot_quadrangulated.obj"), CGAL::data_file_path("meshes/blub_quadrangulated.obj") };
  }
  std::printf("| mesh | quads | Q-zips timed | refused or rolled back | of which refused by the simulation | median execute (us) | median path search (us) |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  std::vector<Sample> all;
  for(const std::string& f : files) run(f, count, all);

  std::printf("\n| path length | Q-zips | execute median (us) | execute p90 (us) | plan median (us) | path search median (us) | path + plan + execute median (us) | undo median (us) | plain BFS s->t median (us) | execute / BFS | path search / BFS |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> recorder_rows, simulation_rows;
  const std::size_t buckets[][2] = { {1, 2}, {3, 5}, {6, 8}, {9, 16}, {17, 32}, {33, 1000} };
  for(const auto& b : buckets)
  {
    std::vector<double> exec, plan, path, total, undo, bfs, r1, r2, paired, bare, ratio, unsimulated, plan_ratio;
    for(const Sample& x : all)
      if(x.length >= b[0] && x.length <= b[1])
      {
        if(x.exec_bare > 0)
        { paired.push_back(x.exec); bare.push_back(x.exec_bare); ratio.push_back(x.exec / x.exec_bare); }
        exec.push_back(x.exec); plan.push_back(x.plan); path.push_back(x.path); undo.push_back(x.undo);
        unsimulated.push_back(x.plan_unsimulated); plan_ratio.push_back(x.plan / std::max(x.plan_unsimulated, 1e-3));
        total.push_back(x.path + x.plan + x.exec); bfs.push_back(x.bfs);
        r1.push_back(x.exec / std::max(x.bfs, 1e-3)); r2.push_back(x.path / std::max(x.bfs, 1e-3));
      }
    if(exec.empty()) continue;
    std::printf("| %zu-%zu | %zu | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", b[0], b[1], exec.size(),
                median(exec), percentile(exec, 0.9), median(plan), median(path), median(total), median(undo), median(bfs),
                median(r1), median(r2));
    char row[256];
    std::snprintf(row, sizeof(row), "| %zu-%zu | %zu | %.1f | %.1f | %.2f |\n", b[0], b[1], paired.size(),
                  median(paired), median(bare), median(ratio));
    recorder_rows.push_back(row);
    std::snprintf(row, sizeof(row), "| %zu-%zu | %zu | %.1f | %.1f | %.2f |\n", b[0], b[1], plan.size(),
                  median(plan), median(unsimulated), median(plan_ratio));
    simulation_rows.push_back(row);
  }
  std::printf("\n| path length | Q-zips compared | execute_qzip() median (us) | bare executor median (us) | median ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  for(const std::string& row : recorder_rows) std::printf("%s", row.c_str());
  std::printf("\n| path length | Q-zips | plan median, simulated (us) | plan median, simulate_chain(false) (us) | median ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  for(const std::string& row : simulation_rows) std::printf("%s", row.c_str());
  return EXIT_SUCCESS;
}
