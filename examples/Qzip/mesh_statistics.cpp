// Prints statistics of a polygon mesh: element counts, topology, valences, singularities (defects) and
// quad quality. Usage: mesh_statistics [IN] [--json]
// Any valid polygon mesh is described (triangles and other polygons included).

#include "qzip_example_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Qzip/mesh_report.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

int main(int argc, char** argv)
{
  const std::string bad = qzip_example::unknown_option(argc, argv, {"--json", "--help", "-h"});
  const std::vector<std::string> inputs = qzip_example::positional_arguments(argc, argv);
  if(qzip_example::has_flag(argc, argv, "--help") || qzip_example::has_flag(argc, argv, "-h"))
  {
    std::cout << "usage: " << argv[0] << " [IN] [--json]\n";
    return EXIT_SUCCESS;
  }
  if(!bad.empty())
  {
    std::cerr << "error: unknown option '" << bad << "' (usage: mesh_statistics [IN] [--json])" << std::endl;
    return EXIT_FAILURE;
  }
  if(inputs.size() > 1)
  {
    std::cerr << "error: expected at most one input file (usage: mesh_statistics [IN] [--json])" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string filename = inputs.empty() ? CGAL::data_file_path("meshes/spot_quadrangulated.obj") : inputs[0];

  Mesh mesh;
  std::string error;
  if(!qzip_example::read_input_mesh(filename, mesh, error, qzip_example::Accepted_faces::ANY_POLYGON))
  {
    std::cerr << "error: " << error << std::endl;
    return EXIT_FAILURE;
  }

  const CGAL::Qzip::Mesh_report report = CGAL::Qzip::compute_mesh_report(mesh);
  if(qzip_example::has_flag(argc, argv, "--json"))
    CGAL::Qzip::write_json(std::cout, report);
  else
    std::cout << filename << "\n" << report;
  return EXIT_SUCCESS;
}
