// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// The examples' check of a PLY file before CGAL 5.5's reader sees it (not part of the library).
// CGAL's reader trusts the file: it resizes a vector to every list count it reads, takes uninitialized
// values once its stream has failed, and dereferences null or dangling pointers on some headers. This
// check reads the header line by line as `CGAL::IO::internal::PLY_reader::init()` does, then the data
// as the reader would, and refuses every file on which the reader would go astray. Where a value is
// ambiguous the check refuses rather than guess: it may refuse a file CGAL reads, never the other way.

#ifndef CGAL_QZIP_EXAMPLE_PLY_CHECK_H
#define CGAL_QZIP_EXAMPLE_PLY_CHECK_H

#include <cstdint>
#include <istream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace qzip_example {

/// One `element` of a PLY header: its name, count, and the properties CGAL's reader keeps.
struct Ply_element
{
  std::string name;
  std::uintmax_t count = 0;
  std::vector<std::pair<std::string, std::string> > properties; // (count type, item type); count type empty for a scalar
};

/// The size in bytes of a PLY scalar type, 0 for a type CGAL's reader does not know.
inline std::size_t ply_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

inline bool ply_is_floating_point(const std::string& type)
{
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

inline bool ply_is_signed(const std::string& type)
{
  return type == "char" || type == "short" || type == "int" || type == "int8" || type == "int16" || type == "int32";
}

/// Reads a PLY header (`in` at the start of the file) as CGAL 5.5's reader does: the first line starts with
/// `ply`; the second line, whatever its first word, gives the format as its second word and has a third;
/// every later line starts with a word: `element <name> <count>`, `property <type> <name>`,
/// `property list <count type> <item type> <name>`, `end_header`, or any other word, which is ignored.
/// A property of a type the reader does not know is skipped, as the reader skips it. Returns `false` with
/// the reason in `why` for a header the reader would reject (an empty line, a missing word or count), one
/// it would mis-read (a negative count, which it turns into a huge one; a property before any element,
/// where it takes the last element of an empty list; vertex coordinates that are not `float` or `double`,
/// where it dereferences a null pointer), and one without `end_header` (it reads on from the end of file).
inline bool read_ply_header(std::istream& in, std::string& format, std::vector<Ply_element>& elements,
                            std::string& why)
{
  std::string line;
  elements.clear();
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number)
  {
    std::istringstream is(line);
    std::string keyword;
    if(line_number == 1)
    {
      if(!(is >> keyword) || keyword != "ply") { why = "not a PLY file"; return false; }
      continue;
    }
    if(line_number == 2)
    {
      std::string version;
      if(!(is >> keyword >> format >> version) ||
         (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian"))
      {
        why = "malformed PLY header (line 2 is not 'format <ascii|binary_little_endian|binary_big_endian> <version>')";
        return false;
      }
      continue;
    }
    const std::string at_line = " (line " + std::to_string(line_number) + ")";
    if(!(is >> keyword)) { why = "malformed PLY header (an empty line" + at_line + ")"; return false; }
    if(keyword == "end_header") return true;
    if(keyword == "element")
    {
      Ply_element element;
      if(!(is >> element.name >> std::ws) || is.peek() == '-' || !(is >> element.count))
      {
        why = "malformed PLY header (an element without a non-negative count" + at_line + ")";
        return false;
      }
      elements.push_back(element);
    }
    else if(keyword == "property")
    {
      std::string type, name, count_type;
      bool read = bool(is >> type >> name);
      const bool list = read && type == "list";
      if(list)
      {
        count_type = name;
        read = bool(is >> type >> name);
      }
      if(!read) { why = "malformed PLY header (a property without a type and a name" + at_line + ")"; return false; }
      if(elements.empty()) { why = "malformed PLY header (a property before any element" + at_line + ")"; return false; }
      const bool kept = ply_type_size(type) != 0 &&
                        (!list || (ply_type_size(count_type) != 0 && !ply_is_floating_point(count_type)));
      if(kept) elements.back().properties.emplace_back(count_type, type);
      const bool vertex = elements.back().name == "vertex" || elements.back().name == "vertices";
      const bool coordinate = name == "x" || name == "y" || name == "z" || name == "nx" || name == "ny" || name == "nz";
      if(vertex && coordinate && (list || !ply_is_floating_point(type)))
      {
        why = "vertex property '" + name + "' is of type '" + (list ? "list of " : "") + type
              + "' (float or double expected)";
        return false;
      }
    }
  }
  why = "malformed PLY header (no end_header line)";
  return false;
}

/// Reads one value of PLY type `type` from ASCII data as CGAL 5.5's reader does, with `operator>>` on a value
/// of that type: a `float` is read as a `float` (`1e39` fails, as a `double` it would not). An integer must lie
/// in the range of its type: CGAL's reader would fail on it (its stream then stays failed and it takes
/// uninitialized counts) or wrap it around (then its reading of the data is not this one).
inline bool read_ply_ascii_value(std::istream& in, const std::string& type, double& value)
{
  if(type == "float" || type == "float32")
  {
    float f = 0;
    if(!(in >> f)) return false;
    value = double(f);
    return true;
  }
  if(ply_is_floating_point(type)) return bool(in >> value);
  long long integer = 0;
  if(!(in >> integer)) return false;
  const int bits = int(8 * ply_type_size(type));
  const long long low = ply_is_signed(type) ? -(1LL << (bits - 1)) : 0;
  const long long high = ply_is_signed(type) ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
  if(integer < low || integer > high)
  {
    in.setstate(std::ios::failbit);
    return false;
  }
  value = double(integer);
  return true;
}

/// Reads a binary PLY list count of type `type` (at most 4 bytes, as the header check ensures); -1 if the
/// data ends or the count is negative (CGAL's reader turns it into a huge size).
inline double read_ply_binary_count(std::istream& in, const std::string& type, bool big_endian)
{
  const std::size_t size = ply_type_size(type);
  unsigned char bytes[4] = {0, 0, 0, 0};
  if(size == 0 || size > 4 || !in.read(reinterpret_cast<char*>(bytes), std::streamsize(size))) return -1;
  std::uint32_t u = 0;
  for(std::size_t i = 0; i < size; ++i) u |= std::uint32_t(bytes[big_endian ? size - 1 - i : i]) << (8 * i);
  if(ply_is_signed(type) && (u >> (8 * size - 1)) != 0) return -1;
  return double(u);
}

/// Reads the data of a PLY file (`in` just after its header) as CGAL 5.5's reader does, element by element,
/// item by item, property by property: returns `false` with the reason in `why` if the data ends before the
/// declared elements (the reader would then take uninitialized values), holds a value that is not a number
/// of its type, or a list count larger than the file (the reader resizes a vector to it before reading).
inline bool ply_data_fits(std::istream& in, const std::string& format, const std::vector<Ply_element>& elements,
                          std::uintmax_t file_size, std::string& why)
{
  const bool ascii = format == "ascii", big_endian = format == "binary_big_endian";
  const std::string ends_early = "the PLY data ends before the elements its header declares";
  const std::string unreadable = "the PLY data has a value that is not a number of its type";
  for(const Ply_element& element : elements)
    for(std::uintmax_t row = 0; row < element.count; ++row)
      for(const std::pair<std::string, std::string>& property : element.properties)
      {
        double items = 1, value = 0;
        if(!property.first.empty())
        {
          if(ascii && !read_ply_ascii_value(in, property.first, items)) { why = in.eof() ? ends_early : unreadable; return false; }
          if(!ascii && (items = read_ply_binary_count(in, property.first, big_endian)) < 0)
          {
            why = in ? "a list of element '" + element.name + "' has a negative count" : ends_early;
            return false;
          }
          if(items > double(file_size))
          {
            why = "a list of element '" + element.name + "' declares more items than the file can hold";
            return false;
          }
        }
        if(ascii)
        {
          for(double k = 0; k < items; ++k)
            if(!read_ply_ascii_value(in, property.second, value)) { why = in.eof() ? ends_early : unreadable; return false; }
          continue;
        }
        const std::streamoff at = in.tellg();
        const double bytes = items * double(ply_type_size(property.second));
        if(at < 0 || double(at) + bytes > double(file_size)) { why = ends_early; return false; }
        in.seekg(std::streamoff(bytes), std::ios::cur);
      }
  return true;
}

/// Checks a PLY file (`in` at its start, `file_size` bytes) before CGAL 5.5's reader sees it: its header
/// (`read_ply_header()`), its element counts (each element takes at least one byte) and its data
/// (`ply_data_fits()`). Returns `false` with the reason in `why`.
inline bool check_ply_file(std::istream& in, std::uintmax_t file_size, std::string& why)
{
  std::string format;
  std::vector<Ply_element> elements;
  if(!read_ply_header(in, format, elements, why)) return false;
  double total = 0;
  for(const Ply_element& element : elements) total += double(element.count);
  if(total > double(file_size))
  {
    why = "its header declares more elements than the file can hold";
    return false;
  }
  return ply_data_fits(in, format, elements, file_size, why);
}

} // namespace qzip_example

#endif // CGAL_QZIP_EXAMPLE_PLY_CHECK_H
