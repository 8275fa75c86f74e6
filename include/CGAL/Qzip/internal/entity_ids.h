// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_ENTITY_IDS_H
#define CGAL_QZIP_INTERNAL_ENTITY_IDS_H

#include <CGAL/license/Qzip.h>

#include <boost/functional/hash.hpp>

#include <cstddef>
#include <unordered_map>

namespace CGAL {
namespace Qzip {
namespace internal {

// Stable names for mesh elements across removals and re-creations, for the journals that undo
// operations (Operation_log, Triangle_journal). Meshes recycle the descriptors of removed elements and an
// undo re-creates removed elements under new descriptors, so journals cannot name elements by
// descriptor. An id is bound to a descriptor when an element is first named, unbound when the element
// is removed, and bound to the new descriptor when an undo re-creates it: an id always denotes the same
// element, whatever descriptors it had over time.
template <typename Descriptor>
class Entity_ids
{
public:
  typedef std::size_t Id;

  Id name(Descriptor d)
  {
    auto it = id.find(d);
    if(it != id.end()) return it->second;
    id.emplace(d, next_id);
    descriptor.emplace(next_id, d);
    return next_id++;
  }
  Descriptor operator[](Id i) const { return descriptor.at(i); }
  void unbind(Descriptor d)
  {
    auto it = id.find(d);
    if(it == id.end()) return;
    descriptor.erase(it->second);
    id.erase(it);
  }
  void rebind(Id i, Descriptor d)
  {
    unbind(d);
    id[d] = i;
    descriptor[i] = d;
  }
  void clear() { id.clear(); descriptor.clear(); }

private:
  std::unordered_map<Descriptor, Id, boost::hash<Descriptor> > id;
  std::unordered_map<Id, Descriptor> descriptor;
  Id next_id = 0;
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_ENTITY_IDS_H
