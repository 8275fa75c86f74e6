// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPTIMIZER_ERASED_POLICIES_H
#define CGAL_QZIP_INTERNAL_OPTIMIZER_ERASED_POLICIES_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/stop_predicates.h>
#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

#include <cstddef>
#include <functional>
#include <memory>

namespace CGAL {
namespace Qzip {

template <typename PolygonMesh> struct Surgery_plan;

namespace internal {

// The scoring functor, the stop predicate and the visitor of optimize_singularities() behind fixed types:
// Batch_optimizer is compiled once per mesh type and property maps, not once more for every scoring
// functor, stop predicate and visitor a program passes (a test program passes a dozen). They are called
// once per candidate, once per batch and once per surgery: an indirect call costs nothing next to them.

// a scoring functor called with the optimizer's context type
template <typename PolygonMesh, typename Context>
using Erased_scoring = std::function<double(const Qzip_candidate<PolygonMesh>&, Context&)>;

typedef std::function<bool(const Optimizer_statistics&)> Erased_stop_predicate;

// a reference to a visitor of optimize_singularities() (its callbacks are those of Default_optimizer_visitor)
template <typename PolygonMesh>
class Erased_optimizer_visitor
{
  typedef Surgery_plan<PolygonMesh> Plan;

  struct Callbacks
  {
    virtual ~Callbacks() {}
    virtual void on_started(const Optimizer_statistics& s) = 0;
    virtual void on_batch_scored(const Optimizer_statistics& s, std::size_t chosen) = 0;
    virtual void on_surgery(const Plan& plan, double score, int predicted_change) = 0;
    virtual void on_undo(const Plan& plan) = 0;
    virtual void on_batch_finished(const Optimizer_statistics& s) = 0;
    virtual void on_finished(const Optimizer_statistics& s) = 0;
  };

  template <typename Visitor>
  struct Forward : Callbacks
  {
    Visitor& visitor;
    explicit Forward(Visitor& visitor) : visitor(visitor) {}
    void on_started(const Optimizer_statistics& s) override { visitor.on_started(s); }
    void on_batch_scored(const Optimizer_statistics& s, std::size_t chosen) override { visitor.on_batch_scored(s, chosen); }
    void on_surgery(const Plan& plan, double score, int predicted_change) override
    { visitor.on_surgery(plan, score, predicted_change); }
    void on_undo(const Plan& plan) override { visitor.on_undo(plan); }
    void on_batch_finished(const Optimizer_statistics& s) override { visitor.on_batch_finished(s); }
    void on_finished(const Optimizer_statistics& s) override { visitor.on_finished(s); }
  };

  std::unique_ptr<Callbacks> callbacks;

public:
  template <typename Visitor>
  explicit Erased_optimizer_visitor(Visitor& visitor) : callbacks(new Forward<Visitor>(visitor)) {}

  void on_started(const Optimizer_statistics& s) { callbacks->on_started(s); }
  void on_batch_scored(const Optimizer_statistics& s, std::size_t chosen) { callbacks->on_batch_scored(s, chosen); }
  void on_surgery(const Plan& plan, double score, int predicted_change) { callbacks->on_surgery(plan, score, predicted_change); }
  void on_undo(const Plan& plan) { callbacks->on_undo(plan); }
  void on_batch_finished(const Optimizer_statistics& s) { callbacks->on_batch_finished(s); }
  void on_finished(const Optimizer_statistics& s) { callbacks->on_finished(s); }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPTIMIZER_ERASED_POLICIES_H
