// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// Small helpers shared by the Qzip examples (not part of the library): checked mesh input,
// atomic mesh output, and a minimal command-line parser. Errors come back as a message;
// nothing here prints or exits.

#ifndef CGAL_QZIP_EXAMPLE_IO_H
#define CGAL_QZIP_EXAMPLE_IO_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>

#include <boost/graph/graph_traits.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <new>
#include <stdexcept>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace qzip_example {

/// Which face degrees `read_input_mesh()` accepts.
enum class Accepted_faces { QUADS_ONLY, TRIANGLES_AND_QUADS, ANY_POLYGON };

/// `true` if `a` and `b` both exist and are the same file (same device and inode; symbolic links followed).
inline bool same_file(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  if(::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0)
    return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/// The declarations of a PLY header that the data must follow: the elements, their counts and properties.
struct Ply_element
{
  std::string name;
  double count = 0;
  std::vector<std::pair<std::string, std::string> > properties; // (count type, item type); count type empty for a scalar
};

/// The size in bytes of a PLY scalar type, 0 for an unknown one.
inline std::size_t ply_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

/// Reads a PLY list count of type `type` from binary data (`big_endian` or little endian); -1 if it cannot.
inline double read_binary_ply_count(std::istream& in, const std::string& type, bool big_endian)
{
  const std::size_t size = ply_type_size(type);
  unsigned char bytes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  if(size == 0 || size > 4 || !in.read(reinterpret_cast<char*>(bytes), std::streamsize(size))) return -1;
  std::uint32_t u = 0;
  for(std::size_t i = 0; i < size; ++i) u |= std::uint32_t(bytes[big_endian ? size - 1 - i : i]) << (8 * i);
  const bool is_signed = type == "char" || type == "short" || type == "int" || type == "int8" || type == "int16" || type == "int32";
  if(is_signed && (u >> (8 * size - 1)) != 0) return -1; // negative
  return double(u);
}

/// Checks that the data of a PLY file (`in` positioned after its header) holds every element its header
/// declares, and that no list declares more items than the file can hold: CGAL 5.5's reader resizes a vector
/// to the declared count before reading the items (a list count of 4 billion in a file of a few hundred bytes
/// allocates 16 GB). A file whose data ends early is refused too: the reader would fail on it, and where its
/// reading of a garbled header differs from this one, the data it reads is not the data checked here.
inline bool ply_lists_fit(std::istream& in, const std::string& format, const std::vector<Ply_element>& elements,
                          std::uintmax_t file_size, const std::string& path, std::string& error)
{
  const bool ascii = format == "ascii", big_endian = format == "binary_big_endian";
  if(!ascii && !big_endian && format != "binary_little_endian") return true;
  auto refuse = [&](const std::string& why)
  {
    error = "cannot read '" + path + "': " + why;
    return false;
  };
  const std::string ends_early = "the PLY data ends before the elements its header declares";
  // An ASCII value is read as the reader reads it (an integer type as an integer, `>>` stopping where the
  // number does): after a value it cannot read, the reader's stream fails and it takes an uninitialized
  // count for the next list.
  auto read_ascii_value = [&](const std::string& type, double& value)
  {
    if(type.find("float") != std::string::npos || type == "double")
      return bool(in >> value);
    long long integer = 0;
    if(!(in >> integer)) return false;
    value = double(integer);
    return true;
  };
  const std::string unreadable = "the PLY data has a value that is not a number of its type";
  for(const Ply_element& element : elements)
    for(double row = 0; row < element.count; ++row)
      for(const std::pair<std::string, std::string>& property : element.properties)
      {
        double items = 1, value = 0;
        if(!property.first.empty())
        {
          if(ascii && !read_ascii_value(property.first, items)) return refuse(in.eof() ? ends_early : unreadable);
          if(!ascii) items = read_binary_ply_count(in, property.first, big_endian);
          if(!in) return refuse(ends_early);
          if(!(items >= 0) || items > double(file_size))
            return refuse("a list of element '" + element.name + "' declares more items than the file can hold");
        }
        if(ascii)
        {
          for(double k = 0; k < items; ++k)
            if(!read_ascii_value(property.second, value)) return refuse(in.eof() ? ends_early : unreadable);
          continue;
        }
        const std::streamoff at = in.tellg();
        const double bytes = items * double(ply_type_size(property.second));
        if(at < 0 || double(at) + bytes > double(file_size)) return refuse(ends_early);
        in.seekg(std::streamoff(bytes), std::ios::cur);
      }
  return true;
}

/// Reads the header of an OFF file as CGAL 5.5's `File_header_OFF` does (the keyword is the first run of letters
/// and digits after blanks and comments, and the character after it is consumed): returns whether it is a binary
/// OFF header (the word `BINARY`, the end of its line, then big-endian 32-bit counts, a dimension first for
/// `nOFF`); its vertex and face counts in `vertices` and `faces` (0 if the file ends before them: CGAL reports it).
inline bool read_off_binary_counts(std::ifstream& in, long long& vertices, long long& faces)
{
  in.clear();
  in.seekg(0);
  auto skip_blanks_and_comments = [&in]()
  {
    for(int c = in.peek(); c != EOF; c = in.peek())
    {
      if(c == '#') { std::string comment; std::getline(in, comment); }
      else if(std::isspace(c)) in.get();
      else break;
    }
  };
  // appends to `word` the run of letters and digits that follows, and consumes the character after it (`after`)
  auto read_word = [&in](std::string& word, char& after)
  {
    after = '\0';
    char c;
    while(in.get(c))
    {
      if(!std::isalnum(static_cast<unsigned char>(c))) { after = c; return; }
      word += c;
    }
  };
  std::string keyword, word;
  char after = '\0', first = '\0';
  skip_blanks_and_comments();
  read_word(keyword, after);
  if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return false;
  skip_blanks_and_comments();
  if(!in.get(first) || std::isdigit(static_cast<unsigned char>(first))) return false;
  word += first;
  read_word(word, after);
  if(word != "BINARY") return false;
  if(after != '\n') { std::string end_of_line; std::getline(in, end_of_line); }
  long long count[2] = { 0, 0 };
  for(int k = keyword.find('n') != std::string::npos ? -1 : 0; k < 2; ++k)
  {
    unsigned char b[4];
    if(!in.read(reinterpret_cast<char*>(b), 4)) return true;
    const long long x = std::int32_t(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 |
                                     std::uint32_t(b[2]) << 8 | std::uint32_t(b[3]));
    if(k >= 0) count[k] = x;
  }
  vertices = count[0];
  faces = count[1];
  return true;
}

/// Checks the header of an OFF or PLY file before CGAL's readers see it: the element counts it declares must
/// fit in the file (every element takes at least one byte); in a PLY header every `property` line must
/// follow an `element` line, element counts must be non-negative integers, vertex coordinates and normals
/// must be `float` or `double` (not lists), the header must end with `end_header`, and the data must hold
/// the declared elements with no list longer than the file (see `ply_lists_fit()`). CGAL 5.5's readers
/// reserve memory for the declared counts before reading, which
/// fails (`std::bad_alloc`, or an abort under AddressSanitizer) on absurd counts, and its PLY reader
/// dereferences the last element of an empty list on a property without element, and a null pointer on
/// integer or list coordinates (segmentation faults in Release; assertions otherwise).
/// A binary OFF header (see `read_off_binary_counts()`) must declare non-negative counts that fit in the file too
/// (CGAL turns a negative count into a huge one, and computes an `int` from their sum: undefined behaviour when it
/// overflows). Other formats are not checked.
inline bool check_file_header(const std::string& path, std::uintmax_t file_size, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  std::string line, token;
  auto too_many = [&](double declared)
  {
    if(declared <= double(file_size)) return false;
    error = "cannot read '" + path + "': its header declares more elements than the file can hold";
    return true;
  };
  if(!std::getline(in, line)) return true;
  std::istringstream first(line);
  if(!(first >> token)) return true;
  if(token == "ply")
  {
    double total = 0;
    bool element_seen = false, header_ended = false;
    int line_number = 0; // after the first
    std::string element, type, format;
    std::vector<Ply_element> elements;
    while(std::getline(in, line))
    {
      std::istringstream is(line);
      std::string keyword, name;
      double count = 0;
      if(!(is >> keyword)) continue;
      if(keyword == "end_header") { header_ended = true; break; }
      if(++line_number == 1) is >> format; // CGAL's reader takes the format from the second line, whatever its keyword
      if(keyword == "element")
      {
        element_seen = true;
        element.clear();
        elements.emplace_back();
        if(is >> element >> count)
        {
          elements.back().name = element;
          elements.back().count = count;
          // CGAL 5.5's reader turns a negative count into a huge unsigned one and loops over it
          if(count < 0 || count != std::floor(count))
          {
            error = "cannot read '" + path + "': malformed PLY header (element '" + element
                    + "' has a count that is not a non-negative integer)";
            return false;
          }
          total += count;
        }
      }
      else if(keyword == "property" && !element_seen)
      {
        error = "cannot read '" + path + "': malformed PLY header (a property before any element)";
        return false;
      }
      else if(keyword == "property" && (is >> type))
      {
        // `property <type> <name>` or `property list <count type> <item type> <name>`
        const bool list = type == "list";
        std::string count_type;
        if(list) is >> count_type >> type;
        is >> name;
        // the reader skips properties of unknown types (and lists with a floating-point count)
        if(ply_type_size(type) != 0 && (!list || (ply_type_size(count_type) != 0 && ply_type_size(count_type) <= 4 &&
                                                  count_type.find("float") == std::string::npos)))
          elements.back().properties.emplace_back(count_type, type);
        if(element != "vertex") continue;
        if((name == "x" || name == "y" || name == "z" || name == "nx" || name == "ny" || name == "nz") &&
           (list || (type != "float" && type != "float32" && type != "double" && type != "float64")))
        {
          error = "cannot read '" + path + "': vertex property '" + name + "' is of type '" + (list ? "list of " : "")
                  + type + "' (float or double expected)";
          return false;
        }
      }
    }
    if(!header_ended)
    {
      error = "cannot read '" + path + "': malformed PLY header (no end_header line)";
      return false;
    }
    return !too_many(total) && ply_lists_fit(in, format, elements, file_size, path, error);
  }
  long long vertices = 0, faces = 0;
  if(read_off_binary_counts(in, vertices, faces))
  {
    if(vertices >= 0 && faces >= 0) return !too_many(double(vertices + faces));
    error = "cannot read '" + path + "': malformed binary OFF header (a negative element count)";
    return false;
  }
  if(token.size() < 3 || token.compare(token.size() - 3, 3, "OFF") != 0) return true;
  in.clear();
  in.seekg(0);
  std::getline(in, line); // the first line, read into `first` above
  std::string rest;
  std::getline(first, rest);
  // the counts follow the keyword, on its line or on the next line that is not a comment
  auto is_blank_or_comment = [](const std::string& l)
  {
    const std::size_t i = l.find_first_not_of(" \t\r");
    return i == std::string::npos || l[i] == '#';
  };
  std::istringstream counts(rest);
  double v = 0, f = 0;
  while(!(counts >> v >> f))
  {
    if(!std::getline(in, line)) return true;
    if(is_blank_or_comment(line)) continue;
    counts.clear();
    counts.str(line);
  }
  return !too_many((v > 0 ? v : 0) + (f > 0 ? f : 0));
}

/// Checks that every face index of the file refers to an existing vertex. CGAL 5.5's OBJ and PLY readers
/// do not check the indices (OBJ even turns index 0 and `n + 1` into `n`) and then read past the end of
/// their vertex array while building the mesh; this check reads the file as a polygon soup first, which
/// only stores the indices. Returns `true` when the file cannot be read as a soup: then
/// `CGAL::IO::read_polygon_mesh()` fails on it as well and the caller reports that.
inline bool face_indices_in_range(const std::string& path, std::string& error)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  try
  {
    if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
      return true;
  }
  catch(const std::exception&)
  {
    return true; // e.g. std::bad_alloc on absurd element counts, reported by the caller's read as well
  }
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
      {
        error = "cannot read '" + path + "': a face refers to a vertex that does not exist (the file has "
                + std::to_string(points.size()) + " vertices)";
        return false;
      }
  return true;
}

/// Reads `path` into `mesh` (cleared first) and checks it. Returns `false` with a one-line message in `error`
/// if the file is missing or unreadable, is not a valid polygon mesh (`CGAL::IO::read_polygon_mesh` fails,
/// e.g. on an edge shared by three faces, or `CGAL::is_valid_polygon_mesh` fails), has a pinched
/// (non-manifold) vertex, has no face, has a non-finite coordinate, or has a face whose degree `accepted`
/// does not allow.
template <typename Mesh>
bool read_input_mesh(const std::string& path, Mesh& mesh, std::string& error,
                     Accepted_faces accepted = Accepted_faces::QUADS_ONLY)
{
  error.clear();
  CGAL::clear(mesh);
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
  {
    error = "cannot open input '" + path + "': no such file";
    return false;
  }
  if(!S_ISREG(st.st_mode))
  {
    error = "cannot open input '" + path + "': not a regular file";
    return false;
  }
  if(!std::ifstream(path).good())
  {
    error = "cannot open input '" + path + "': permission denied or unreadable";
    return false;
  }
  if(!check_file_header(path, std::uintmax_t(st.st_size), error) || !face_indices_in_range(path, error))
    return false;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(path, mesh);
  }
  catch(const std::bad_alloc&)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "': it declares more elements than can be allocated";
    return false;
  }
  catch(const std::exception& e)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "': " + e.what();
    return false;
  }
  if(!read)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "' as a polygon mesh (unsupported extension, malformed file, "
            "or a non-manifold / non-orientable surface)";
    return false;
  }
  if(!CGAL::is_valid_polygon_mesh(mesh))
  {
    CGAL::clear(mesh);
    error = "'" + path + "' is not a valid polygon mesh";
    return false;
  }
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  if(!pinched.empty())
  {
    CGAL::clear(mesh);
    error = "'" + path + "' is not manifold: it has " + std::to_string(pinched.size())
            + " pinched (non-manifold) vertex fan(s)";
    return false;
  }
  if(faces(mesh).empty())
  {
    error = "'" + path + "' contains no face";
    return false;
  }
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y()))
       || !std::isfinite(CGAL::to_double(p.z())))
    {
      error = "'" + path + "' has a vertex with a NaN or infinite coordinate";
      return false;
    }
  }
  if(accepted != Accepted_faces::ANY_POLYGON)
  {
    for(auto f : faces(mesh))
    {
      std::size_t d = 0;
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      {
        (void)h;
        ++d;
      }
      const bool ok = (d == 4) || (d == 3 && accepted == Accepted_faces::TRIANGLES_AND_QUADS);
      if(!ok)
      {
        error = "'" + path + "' has a face of degree " + std::to_string(d) + "; only "
                + (accepted == Accepted_faces::QUADS_ONLY ? "quads are" : "triangles and quads are")
                + " accepted";
        return false;
      }
    }
  }
  return true;
}

/// Writes `mesh` to `path` through a temporary file in the same directory, renamed over `path` once
/// complete, so that `path` is never left half-written. Refuses (returns `false` with a message) when
/// `path` is the same file as `input_path` (if given), or when the format (from the extension) is not
/// supported or the file cannot be written.
template <typename Mesh>
bool write_output_mesh_atomically(const std::string& path, const Mesh& mesh, std::string& error,
                                  const std::string& input_path = std::string())
{
  error.clear();
  if(!input_path.empty() && same_file(path, input_path))
  {
    error = "output '" + path + "' is the input file; refusing to overwrite it";
    return false;
  }
  const std::string::size_type slash = path.find_last_of('/');
  const std::string dir = (slash == std::string::npos) ? std::string() : path.substr(0, slash + 1);
  const std::string name = (slash == std::string::npos) ? path : path.substr(slash + 1);
  const std::string::size_type dot = name.find_last_of('.');
  if(name.empty() || dot == std::string::npos || dot == 0)
  {
    error = "output '" + path + "' has no file extension (use .off, .obj, .ply, ...)";
    return false;
  }
  // keep the extension: CGAL::IO::write_polygon_mesh chooses the format from it
  const std::string tmp = dir + "." + name.substr(0, dot) + ".tmp" + std::to_string(::getpid()) + name.substr(dot);
  if(!std::ofstream(tmp).good()) // checked here so that CGAL's writer does not print its own message
  {
    error = "cannot create a file in the directory of '" + path + "'";
    return false;
  }
  if(!CGAL::IO::write_polygon_mesh(tmp, mesh, CGAL::parameters::stream_precision(17)))
  {
    std::remove(tmp.c_str());
    error = "cannot write '" + path + "' (unsupported file extension?)";
    return false;
  }
  if(std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    error = "cannot rename the temporary file to '" + path + "'";
    return false;
  }
  return true;
}

/// `true` if `flag` (e.g. `--json`) is among the arguments.
inline bool has_flag(int argc, char** argv, const std::string& flag)
{
  for(int i = 1; i < argc; ++i)
    if(flag == argv[i])
      return true;
  return false;
}

/// The value following option `name` (e.g. `--output out.off`), or `default_value` if absent.
inline std::string option_value(int argc, char** argv, const std::string& name,
                                const std::string& default_value = std::string())
{
  for(int i = 1; i + 1 < argc; ++i)
    if(name == argv[i])
      return argv[i + 1];
  return default_value;
}

/// The arguments that are neither options (starting with `-`) nor values of `options_with_value`.
inline std::vector<std::string> positional_arguments(int argc, char** argv,
                                                     const std::set<std::string>& options_with_value = {})
{
  std::vector<std::string> out;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options_with_value.count(a) > 0) { ++i; continue; }
    if(!a.empty() && a[0] == '-') continue;
    out.push_back(a);
  }
  return out;
}

/// The first argument starting with `-` that is neither in `flags` nor in `options_with_value`, or "" if none.
inline std::string unknown_option(int argc, char** argv, const std::set<std::string>& flags,
                                  const std::set<std::string>& options_with_value = {})
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options_with_value.count(a) > 0) { ++i; continue; }
    if(!a.empty() && a[0] == '-' && flags.count(a) == 0)
      return a;
  }
  return std::string();
}

} // namespace qzip_example

#endif // CGAL_QZIP_EXAMPLE_IO_H
