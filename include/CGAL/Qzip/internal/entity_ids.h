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

#include <CGAL/Qzip/internal/descriptor_hash_map.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// Stable names for mesh elements across removals and re-creations, for the journals that undo
// operations (Operation_log, Triangle_journal). Meshes recycle the descriptors of removed elements and an
// undo re-creates removed elements under new descriptors, so journals cannot name elements by
// descriptor. An id is bound to a descriptor when an element is first named, unbound when the element
// is removed, and bound to the new descriptor when an undo re-creates it: an id always denotes the same
// element, whatever descriptors it had over time.
//
// Ids are numbered from 0, so an id's binding is an array entry. The map from descriptors to ids is never
// erased from: an entry d -> i holds only while i is bound to d, so that unbinding touches the array alone
// and a recycled descriptor is named anew by overwriting its entry. `clear()` keeps both buffers, so that
// a journal cleared and filled again allocates nothing.
template <typename Descriptor>
class Entity_ids
{
public:
  typedef std::size_t Id;

  Id name(Descriptor d)
  {
    const auto it = id.insert(d, bindings.size());
    if(!it.second && holds(*it.first, d)) return *it.first;
    *it.first = bindings.size();
    bindings.push_back(Binding{ d, true });
    return *it.first;
  }
  Descriptor operator[](Id i) const
  {
    CGAL_precondition(i < bindings.size() && bindings[i].bound);
    return bindings[i].descriptor;
  }
  void unbind(Descriptor d)
  {
    if(const Id* i = id.find(d); i != nullptr && holds(*i, d)) bindings[*i].bound = false;
  }
  void rebind(Id i, Descriptor d)
  {
    CGAL_precondition(i < bindings.size());
    unbind(d);
    *id.insert(d, i).first = i;
    bindings[i] = Binding{ d, true };
  }
  void clear() { id.clear(); bindings.clear(); }

private:
  struct Binding { Descriptor descriptor; bool bound; };

  bool holds(Id i, Descriptor d) const { return bindings[i].bound && bindings[i].descriptor == d; }

  Descriptor_hash_map<Descriptor, Id> id;
  std::vector<Binding> bindings; // by id
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_ENTITY_IDS_H
