// The common interface of the estimators (one per row of the table of methods, method_table.def).
#pragma once

#include <memory>
#include <vector>

#include "convergence.hpp"
#include "features.hpp"
#include "image_view.hpp"
#include "inner_point.hpp"
#include "method.hpp"
#include "params.hpp"
#include "rays.hpp"
#include "trace.hpp"

namespace projtrack {

class ScratchMask;  // scratch_mask.hpp (internal: the fills' own masks)

// An estimator keeps scratch buffers between calls (so steady-state calls do not allocate): use
// one instance per stream, from one thread at a time.
class Estimator {
 public:
  virtual ~Estimator() = default;

  // Estimates the projection features of the object around `inner_point` from `edges` (non-zero
  // = edge), then updates the inner point for the next frame. Never throws on bad input: the
  // status says what was wrong (see status.hpp). Fills `trace` when one is given. `options`: what
  // the caller (a tracker) sets for this call alone. With a budget (options.budget) the estimate
  // spends its work from it, and stops when it runs out (OverBudget) or its stop flag is set
  // (Interrupted): a stopped estimate has no features.
  Features estimate(const ImageView& edges, Point2i inner_point, const Params& params,
                    Trace* trace = nullptr) {
    return estimate(edges, inner_point, params, EstimateOptions{}, trace);
  }
  Features estimate(const ImageView& edges, Point2i inner_point, const Params& params,
                    const EstimateOptions& options, Trace* trace = nullptr);
  // Whether the last estimate's fill took in pixel `p` (of the edges it was given), so that an
  // estimate from `p` on the same edges would find the same region and the same verdict: true
  // only for pixel filling, whose region is the 4-connected free pixels around its start (when
  // cut short by the area limit, from `p` it would be cut short too). The methods whose answer
  // depends on where they start say false.
  virtual bool took_in(Point2i) const { return false; }
  // Sets in `into` (of the edges' size) the pixels the last estimate's fill took in, when
  // took_in() answers for them; widens `box` to hold them. Returns the work it did (units).
  virtual std::uint64_t add_fill_to(ScratchMask&, Rect&) const { return 0; }

 protected:
  struct Context {
    const ImageView& edges;          // valid, non-empty
    const Params& params;            // validated
    const EstimateOptions& options;  // validated
    const RayFan& fan;               // params.rays directions
    Trace* trace;                    // may be null
  };
  // The method proper, called with `out.seed` a free pixel and `out.inner_point` == `out.seed`.
  // Sets centroid, area, bbox and iterations, and leaves `out.inner_point` where the method's own
  // iterations moved it; the common inner-point update runs afterwards.
  virtual void run(const Context& ctx, Features& out, Work& work) = 0;

  // The loop of the iterative methods. estimate(p, i) casts from p in iteration i and returns the
  // centroid (setting out.area when it has one per iteration); the inner point then walks toward
  // the centroid and, when `recentre`, is recentred on the mean of n ray hits (the paper does so
  // inside the loop for the n^y variants). Stops by the convergence rule or at max_iterations.
  template <class Estimate>
  void iterate(const Context& ctx, Features& out, Work& work, bool recentre, Estimate&& estimate);

 private:
  // `f` as an estimate that a checkpoint stopped (work.stopped): Interrupted or OverBudget,
  // without features, with the work it did.
  static Features stopped(Features& f, const WorkBudget& budget, const Work& work);

  RayFan fan_;
  std::vector<RayHit> update_hits_;
};

template <class Estimate>
void Estimator::iterate(const Context& ctx, Features& out, Work& work, bool recentre,
                        Estimate&& estimate) {
  Point2i p = out.seed;
  Point2d c_prev = to_double(p);
  for (int it = 1; it <= ctx.params.max_iterations; ++it) {
    const Point2d c = estimate(p, it);
    if (work.stopped) break;  // c is meaningless: the estimate is void
    out.centroid = c;
    out.iterations = it;
    if (ctx.trace) ctx.trace->iterations.push_back({p, c, out.area});
    const Point2i next =
        recentre ? update_inner_point(ctx.edges, p, c, ctx.fan, update_hits_, work, ctx.trace, 0)
                 : move_toward(ctx.edges, p, round_to_pixel(c), work);
    const bool done = converged(p, next, c_prev, c, ctx.params.convergence);
    p = next;
    c_prev = c;
    if (done || work.must_stop()) break;
  }
  out.inner_point = p;
}

// A new estimator of method `m` (null for an integer that is no Method value): the factory of its
// row in the table of methods.
std::unique_ptr<Estimator> make_estimator(Method m);

// The least work (WorkBudget units) one estimate of method `m` costs with `params`, however short
// its rays: a ray method's casts of one iteration (rays + ... + rays^recursion for a method that
// reads recursion) and the inner-point update every method makes. A budget smaller than this can
// never hold a whole estimate.
std::uint64_t least_estimate_cost(Method m, const Params& params);

// The status of an estimate covering `bbox` in a width × height frame: Ok, ReachedBorder (it
// touches the border) or CoversFrame (it touches all four).
EstimateStatus border_status(const Rect& bbox, int width, int height);
// Moves an estimate made in a region of the frame into frame coordinates.
void translate(Features& f, int dx, int dy);

}  // namespace projtrack
