// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_QZIP_NAMED_FUNCTION_PARAMETERS_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <type_traits>

namespace CGAL {
namespace Qzip {

namespace internal_np {
#define CGAL_QZIP_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Qzip/internal/parameters_interface.h>
#undef CGAL_QZIP_add_named_parameter
} // namespace internal_np

namespace internal {

// rebuilds the entries of np2 (oldest first) on top of np1
template <typename T> const T& np_value(const T& v, std::true_type) { return v; }
template <typename T> const T& np_value(const std::reference_wrapper<const T>& v, std::false_type) { return v.get(); }

template <typename NP1, typename T, typename Tag>
CGAL::Named_function_parameters<T, Tag, NP1>
append_np(const NP1& np1, const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np2)
{
  return CGAL::Named_function_parameters<T, Tag, NP1>(np_value<T>(np2.v, std::is_copy_constructible<T>()), np1);
}

template <typename NP1, typename T, typename Tag, typename Base>
auto append_np(const NP1& np1, const CGAL::Named_function_parameters<T, Tag, Base>& np2)
{
  auto head = append_np(np1, static_cast<const Base&>(np2));
  return CGAL::Named_function_parameters<T, Tag, decltype(head)>(np_value<T>(np2.v, std::is_copy_constructible<T>()), head);
}

} // namespace internal

/// \ingroup PkgQzipNamedParameters
/// The named parameters of Qzip: CGAL's own (`CGAL::parameters::vertex_point_map()`, ...) and
/// `edge_weight_map()`, `face_is_constrained_map()`, `scoring_functor()`, `stop_predicate()`,
/// `do_smooth()`, `do_end_game()`, `do_look_ahead()`, `number_of_untangling_sweeps()`, `face_count_tolerance()`,
/// `quality_floor()`, `simulate_chain()`. A Qzip parameter starts a pack or is prepended to one
/// (`face_is_constrained_map(fcm, CGAL::parameters::vertex_point_map(vpm))`); `combine()` joins packs.
namespace parameters {

using namespace CGAL::parameters;

#define CGAL_QZIP_add_named_parameter(X, Y, Z)                                                      \
  template <typename K>                                                                             \
  CGAL::Named_function_parameters<K, Qzip::internal_np::X> Z(const K& k)                           \
  { return CGAL::Named_function_parameters<K, Qzip::internal_np::X>(k); }                          \
  template <typename K, typename T, typename Tag, typename Base>                                    \
  CGAL::Named_function_parameters<K, Qzip::internal_np::X, CGAL::Named_function_parameters<T, Tag, Base> > \
  Z(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)                            \
  { return CGAL::Named_function_parameters<K, Qzip::internal_np::X,                                 \
                                           CGAL::Named_function_parameters<T, Tag, Base> >(k, np); }
#include <CGAL/Qzip/internal/parameters_interface.h>
#undef CGAL_QZIP_add_named_parameter

/// joins named-parameter packs; when a tag appears twice the last one wins.
template <typename NP1> const NP1& combine(const NP1& np1) { return np1; }

template <typename NP1, typename NP2, typename... NPS>
auto combine(const NP1& np1, const NP2& np2, const NPS&... nps)
{
  return combine(Qzip::internal::append_np(np1, np2), nps...);
}

} // namespace parameters
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_NAMED_FUNCTION_PARAMETERS_H
