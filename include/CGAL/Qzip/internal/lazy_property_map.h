// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_LAZY_PROPERTY_MAP_H
#define CGAL_QZIP_INTERNAL_LAZY_PROPERTY_MAP_H

#include <CGAL/license/Qzip.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>

#include <memory>
#include <unordered_map>

namespace CGAL {
namespace Qzip {
namespace internal {

// A read-write property map that stores only the keys written to it and answers a default value
// for the others: graph searches that stop early then cost only what they visit. Copies share storage.
template <typename Key, typename Value>
class Lazy_property_map
{
  std::shared_ptr<std::unordered_map<Key, Value, boost::hash<Key> > > values;
  Value default_value;
public:
  typedef Key key_type;
  typedef Value value_type;
  typedef Value reference;
  typedef boost::read_write_property_map_tag category;

  explicit Lazy_property_map(const Value& d)
    : values(std::make_shared<std::unordered_map<Key, Value, boost::hash<Key> > >()), default_value(d) {}

  friend Value get(const Lazy_property_map& m, const Key& k)
  {
    auto it = m.values->find(k);
    return it == m.values->end() ? m.default_value : it->second;
  }
  friend void put(const Lazy_property_map& m, const Key& k, const Value& v) { (*m.values)[k] = v; }
};

// A color map for Boost graph searches that answers black (already finished) for the keys a
// predicate rejects, so that the search never enters them, and white for the other unvisited keys.
template <typename Key, typename Passable>
class Blocking_color_map
{
  std::shared_ptr<std::unordered_map<Key, boost::default_color_type, boost::hash<Key> > > colors;
  Passable passable;
public:
  typedef Key key_type;
  typedef boost::default_color_type value_type;
  typedef boost::default_color_type reference;
  typedef boost::read_write_property_map_tag category;

  explicit Blocking_color_map(const Passable& p)
    : colors(std::make_shared<std::unordered_map<Key, boost::default_color_type, boost::hash<Key> > >()),
      passable(p) {}

  friend boost::default_color_type get(const Blocking_color_map& m, const Key& k)
  {
    auto it = m.colors->find(k);
    if(it != m.colors->end()) return it->second;
    return m.passable(k) ? boost::white_color : boost::black_color;
  }
  friend void put(const Blocking_color_map& m, const Key& k, boost::default_color_type c) { (*m.colors)[k] = c; }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_LAZY_PROPERTY_MAP_H
