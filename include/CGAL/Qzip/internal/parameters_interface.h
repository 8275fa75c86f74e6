// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// The named parameters Qzip adds to CGAL's list. No include guard: included with different
// definitions of CGAL_QZIP_add_named_parameter; moves verbatim into CGAL's parameters_interface.h.

CGAL_QZIP_add_named_parameter(edge_weight_t, edge_weight, edge_weight_map)
CGAL_QZIP_add_named_parameter(face_is_constrained_t, face_is_constrained, face_is_constrained_map)
CGAL_QZIP_add_named_parameter(scoring_functor_t, scoring_functor, scoring_functor)
CGAL_QZIP_add_named_parameter(stop_predicate_t, stop_predicate, stop_predicate)
CGAL_QZIP_add_named_parameter(smoothing_t, smoothing, do_smooth)
CGAL_QZIP_add_named_parameter(end_game_t, end_game, do_end_game)
CGAL_QZIP_add_named_parameter(look_ahead_t, look_ahead, do_look_ahead)
CGAL_QZIP_add_named_parameter(untangling_sweeps_t, untangling_sweeps, number_of_untangling_sweeps)
CGAL_QZIP_add_named_parameter(face_count_tolerance_t, face_count_tolerance, face_count_tolerance)
CGAL_QZIP_add_named_parameter(quality_floor_t, quality_floor, quality_floor)
CGAL_QZIP_add_named_parameter(chain_simulation_t, chain_simulation, simulate_chain)
