// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_STRIP_OPERATION_H
#define CGAL_QZIP_STRIP_OPERATION_H

#include <CGAL/license/Qzip.h>

#include <CGAL/assertions.h>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipPrimitive
The four strip operations of the compass, in counterclockwise order (a left turn of the path takes
the next one, a right turn the previous one), and the no-operation used at adjusted path ends.
*/
enum class Strip_operation
{
  LEFT_SPLIT = 0,      ///< LS: a strip of quads is inserted on the left of the path
  RIGHT_COLLAPSE = 1,  ///< RC: the quads on the left of the path collapse towards the right
  LEFT_COLLAPSE = 2,   ///< LC: the quads on the right of the path collapse towards the left
  RIGHT_SPLIT = 3,     ///< RS: a strip of quads is inserted on the right of the path
  NO_OPERATION = 4     ///< nothing happens at this vertex (guide-only vertex of an adjusted end)
};

/// \ingroup PkgQzipPrimitive
/// rotates a compass tag by `quarter_turns` counterclockwise (a negative value turns clockwise).
inline Strip_operation rotate(Strip_operation op, int quarter_turns)
{
  CGAL_precondition(op != Strip_operation::NO_OPERATION);
  return Strip_operation(((int(op) + quarter_turns) % 4 + 4) % 4);
}

/// \ingroup PkgQzipPrimitive
/// `true` for `LEFT_SPLIT` and `RIGHT_SPLIT`.
inline bool is_split(Strip_operation op)
{ return op == Strip_operation::LEFT_SPLIT || op == Strip_operation::RIGHT_SPLIT; }

/// \ingroup PkgQzipPrimitive
/// `true` for `LEFT_COLLAPSE` and `RIGHT_COLLAPSE`.
inline bool is_collapse(Strip_operation op)
{ return op == Strip_operation::LEFT_COLLAPSE || op == Strip_operation::RIGHT_COLLAPSE; }

/// \ingroup PkgQzipPrimitive
/// the short name of a strip operation: "LS", "RC", "LC", "RS" or "NOOP".
inline const char* short_name(Strip_operation op)
{
  static const char* names[] = { "LS", "RC", "LC", "RS", "NOOP" };
  return names[int(op)];
}

/// \ingroup PkgQzipPrimitive
/// Why a plan cannot be carried out.
enum class Plan_status
{
  REALIZABLE,            ///< the plan can be executed
  INVALID_PATH,          ///< the path is not a simple edge path of at least one edge
  UNSUPPORTED_ENDPOINT,  ///< an end of the path is not an interior vertex of valence 3 or 5 (nor, for the terminal one, a supported border defect, or a feature defect, not at the end of its curve, whose other sectors are regular; see `plan_qzip()`)
  ENDPOINT_ADJUSTMENT,   ///< an end-point adjustment needs a vertex on the border
  NOT_SIMPLE_AFTER_ADJUSTMENT, ///< the adjusted path is not simple
  NOTHING_TO_DO,         ///< the adjusted plan has no collapse and no split (e.g. two adjacent v3 and a split motion)
  PATH_WOULD_COLLAPSE,   ///< a collapse of the chain would merge away a vertex the path has still to visit
  BORDER_OR_CONSTRAINED, ///< an operation would touch a constrained edge or a protected face, collapse a non-quad face, or merge a border vertex away other than where the path leaves the border
  BORDER_FACE_COLLAPSE,  ///< at a path vertex on the border, the compass asks for a collapse on the side of the border, where there is no quad
  SPLIT_WITHOUT_GUIDE,   ///< the adjusted path starts with a split: no earlier operation gives the guide edge that delimits its fan
  VALENCE_6_LEFT,        ///< an interior v5 at an end of the path, delimiting the first or the last split, would become a valence-6 vertex that the clean-up cannot split (no two opposite neighbours of valence 4)
  EXECUTION_WOULD_FAIL,  ///< the execution, simulated on a copy of the neighbourhood of the path, fails: `execute_qzip()` would roll it back (`Surgery_plan::predicted_failure` says why)
  EXECUTION_FAILED       ///< the chain could not be completed (a quad would degenerate, a link condition fails) or left a new singularity; the mesh was restored
};

/// \ingroup PkgQzipPrimitive
/// Why the execution of a realizable plan was rolled back (`Plan_status::EXECUTION_FAILED`), or why its
/// simulation by `plan_qzip()` failed (`Plan_status::EXECUTION_WOULD_FAIL`).
enum class Execution_failure
{
  NONE,                 ///< not rolled back
  PATH_EDGE_MISSING,    ///< an edge of the path disappeared on the way
  COLLAPSE_REFUSED,     ///< a collapse would break the mesh (link condition, border, protected face, not a quad) or a feature curve (remove a constrained edge, merge two feature or border vertices)
  SPLIT_REFUSED,        ///< a split would touch a protected face, or separate the constrained edges of a feature vertex
  NO_GUIDE_FOR_SPLIT,   ///< a split has no guide edge distinct from the next path edge
  CLEANUP_IMPOSSIBLE,   ///< a valence-2 or valence-6 vertex left by the chain could not be cleaned up
  SINGULARITY_CREATED   ///< the chain completed but created a singularity or changed the border
};

/// \ingroup PkgQzipPrimitive
/// a human-readable description of an `Execution_failure`.
inline const char* describe(Execution_failure f)
{
  switch(f)
  {
    case Execution_failure::NONE: return "none";
    case Execution_failure::PATH_EDGE_MISSING: return "an edge of the path disappeared";
    case Execution_failure::COLLAPSE_REFUSED: return "a collapse was refused";
    case Execution_failure::SPLIT_REFUSED: return "a split was refused";
    case Execution_failure::NO_GUIDE_FOR_SPLIT: return "a split had no guide edge";
    case Execution_failure::CLEANUP_IMPOSSIBLE: return "the valence-2/6 clean-up was impossible";
    case Execution_failure::SINGULARITY_CREATED: return "the chain would have created a singularity";
  }
  return "";
}

/// \ingroup PkgQzipPrimitive
/// a human-readable description of a `Plan_status`.
inline const char* describe(Plan_status s)
{
  switch(s)
  {
    case Plan_status::REALIZABLE: return "realizable";
    case Plan_status::INVALID_PATH: return "invalid path";
    case Plan_status::UNSUPPORTED_ENDPOINT: return "an end is not an interior valence-3 or valence-5 vertex";
    case Plan_status::ENDPOINT_ADJUSTMENT: return "the end-point adjustment needs a border vertex";
    case Plan_status::NOT_SIMPLE_AFTER_ADJUSTMENT: return "the adjusted path is not simple";
    case Plan_status::PATH_WOULD_COLLAPSE: return "a collapse would merge away a vertex the path has still to visit";
    case Plan_status::NOTHING_TO_DO: return "the plan has no operation: this motion leaves the pair where it is";
    case Plan_status::BORDER_OR_CONSTRAINED: return "an operation would touch a feature or a protected face, collapse a non-quad face, or merge a border vertex away";
    case Plan_status::BORDER_FACE_COLLAPSE: return "at a path vertex on the border, the compass asks for a collapse on the side of the border";
    case Plan_status::SPLIT_WITHOUT_GUIDE: return "the adjusted path starts with a split, which has no guide edge";
    case Plan_status::VALENCE_6_LEFT: return "a v5 at an end of the path would become a valence-6 vertex that the clean-up cannot split";
    case Plan_status::EXECUTION_WOULD_FAIL: return "the simulated execution fails";
    case Plan_status::EXECUTION_FAILED: return "the chain of operations could not be completed";
  }
  return "";
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_STRIP_OPERATION_H
