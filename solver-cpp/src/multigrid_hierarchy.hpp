// Geometric multigrid hierarchy for M = D^T D + W (method S2.3), W = diag(w), w_p = omega^2 on
// constrained points, 0 elsewhere, plus a base penalty beta^2 >= 0 at every point when the field
// has a prior (setBasePenalty: w_p = beta^2 + omega^2 [p in C]).
//
// Level 0 (fine) is matrix-free: vectors are n x 3 row-major on a box padded with one ghost
// layer (ghost rows are always zero), so the 6-neighbour loops need no boundary tests; D and D^T
// use a precomputed 1/|N(q)| per point (0 on ghosts). Gauss-Seidel keeps L = D x up to date, so
// one point update reads and writes only 7 rows of L instead of the 25-point row of D^T D.
// Smoothing is Gauss-Seidel in plane-multicolour order on every level: z planes k and k + C are
// independent when the operator couples planes at most C - 1 apart (C >= 3 on the fine level and
// the Galerkin levels; MultigridOptions::colours, 5), so colour c = the planes k = c mod C, swept
// colour after colour, the planes of a colour in parallel (parallel.hpp), each plane
// lexicographically. Every loop of a
// V-cycle runs in parallel over planes or rows, each value computed as in a serial loop, so a
// V-cycle gives the same bits with any thread count.
// Levels l >= 1 are Galerkin operators A_{l+1} = P_l^T A_l P_l (A_1 = (D P_0)^T (D P_0) + P_0^T W
// P_0) in CSR; the coarsest (at most `coarsestMaxPoints` points) is factored (LL^T, dense
// storage, every loop kept inside the operator's band: lower bandwidth w, m w^2 / 2 flops).
// A penalty change at fine point p by delta changes every coarse operator by delta * v v^T, v the
// composite interpolation row of p (at most 8 entries): setPenalty updates those 64 entries per
// level in place, so an edit costs O(#changed points * levels) plus, at the coarsest level,
// rank-1 updates/downdates of its factor (one per changed point, O(m w) each) or a
// refactorisation (O(m w^2)) when that is cheaper, or a downdate fails. build() and
// resetPenalties() always refactor, so the factor then depends on the penalties alone.
// vcycle() applies one symmetric V-cycle B (pre- and post-smoothing adjoint to each other, exact
// coarsest solve), so B is symmetric positive definite and usable as a CG preconditioner.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "field_system.hpp"
#include "grid.hpp"
#include "multigrid_sparse.hpp"
#include "multigrid_transfer.hpp"
#include "status.hpp"

namespace hairsketch {

struct MultigridOptions {
  // Coarsen until a level has at most this many points; that level is factored exactly. A
  // large exact coarsest level matters on this operator (the constrained points, weighted by
  // omega^2, act almost as fixed values, which coarse levels cannot represent): on the app's
  // 250K grid it more than halves CG's iterations. Past ~1000 points the factor's work
  // outgrows the iterations it saves (scripts/bench-mg-app.ts measures both).
  int coarsestMaxPoints = 1000;
  int sweeps = 1;  // smoothing steps before and after the coarse correction
  // true: each step is a symmetric Gauss-Seidel sweep (forward then backward) on both sides;
  // false: pre-smoothing forward, post-smoothing backward (also symmetric overall, cheaper).
  // On the fine level false is faster: half the sweeps for a few more iterations, on every
  // grid of the app (scripts/bench-mg-app.ts).
  bool symmetricSweeps = false;
  // The same choice for the coarse (CSR) levels, where a sweep costs more per point.
  bool coarseSymmetricSweeps = true;
  // Smoothing steps on the coarse (CSR) levels (0: the same as `sweeps`).
  int coarseSweeps = 0;
  // Coarse corrections per visit of a coarse level l >= 1 (1: V-cycle, 2: W-cycle). The fine
  // level is always corrected once; the coarsest is solved exactly, once.
  int coarseCycles = 1;
  // Plane colours of the Gauss-Seidel sweeps on every level (at least the 3 that decouple the
  // planes of a colour). More colours sweep more like the lexicographic order: with 3, CG may
  // need one iteration more than with the lexicographic sweep; with 5 it needs the same counts
  // on every benchmark (mg_bench, bench-mg-app.ts), and 5 still leaves 12-15 planes per colour
  // at 250K for the threads.
  int colours = 5;
  // Cold start (MgPcgSolver after setGrid or forgetWarmStart): full multigrid (nested
  // iteration, fullMultigrid()) instead of a zero field (false: CG starts from zero). The
  // right-hand side is restricted to every level, the coarsest level solved exactly, and on the
  // way up each level starts from the interpolated coarser solution and runs `fmgCycles`
  // V-cycles, the fine level `fmgFineCycles` (before CG's first iteration).
  bool fmgStart = true;
  int fmgCycles = 1;
  int fmgFineCycles = 0;
};

class MultigridHierarchy {
 public:
  // Builds levels, transfers and Galerkin operators for W = 0. InvalidInput on a bad grid.
  Status build(const Grid& grid, const MultigridOptions& options = {});

  int levels() const { return int(levels_.size()); }
  // Box size of level l (0 = fine).
  void levelDims(int l, int& nx, int& ny, int& nz) const;

  // Fine vectors: paddedRows() rows of 3 doubles; grid point p lives at row paddedRow(p).
  int64_t paddedRows() const { return fine_.rows; }
  int64_t paddedRow(int p) const;
  void toPadded(const Field& f, double* x) const;  // ghost rows set to zero
  void fromPadded(const double* x, Field& f) const;

  double penalty(int p) const { return fine_.w[paddedRow(p)]; }
  // Sets w_p (fine) and updates all coarse operators locally. Call prepare() before vcycle().
  Status setPenalty(int p, double w);
  // Rebuilds every coarse operator from its W = 0 values, plus the base penalty's
  // beta^2 P_l^T P_l, plus the current fine penalties' excess over the base added in ascending
  // point order: the same arithmetic, in the same order, as a fresh hierarchy given the base
  // penalty (setBasePenalty) and then these penalties (setPenalty, ascending), so the operators
  // no longer carry the rounding of earlier edits (the preconditioner, and with a zero start the
  // whole solve, then depend on the penalties alone). Call prepare() after it.
  Status resetPenalties();
  // A penalty beta2 >= 0 at every fine point (a prior's beta^2 I): every fine w_p becomes beta2
  // (other penalties are dropped: the caller sets them again with setPenalty, in ascending
  // order), every coarse operator its W = 0 values plus beta2 P_l^T P_l, with P_l the composite
  // interpolation from the fine level to level l (a tensor product of 1D interpolations, so
  // P_l^T P_l is the product of three banded 1D Gram matrices: O(nnz) per level, not 64
  // updates per fine point), and the coarsest factor is invalid until prepare(). beta2 = 0
  // gives back the operators of build(), bit for bit.
  Status setBasePenalty(double beta2);
  double basePenalty() const { return basePenalty_; }
  // Brings the coarsest factor up to date with the penalty changes since the last call: rank-1
  // updates of the factor, or a refactorisation (after build/resetPenalties, when cheaper, or
  // when an update fails its pivot check).
  Status prepare();
  // How the last prepare() that had work brought the factor up to date (tests, benchmarks).
  bool lastPrepareRefactored() const { return lastRefactored_; }
  // Whether the coarsest factor is that of some earlier state of the coarsest operator (which is
  // symmetric positive definite at every state): vcycle() may then run before prepare(), solving
  // the coarsest level with that factor, and stays symmetric positive definite. False after
  // build() and resetPenalties() until prepare().
  bool hasFactor() const { return factorValid_; }

  // y = M x on padded fine vectors (x, y must not alias).
  void applyFine(const double* x, double* y);
  // z = B r, one V-cycle from a zero initial guess (r, z padded, must not alias).
  void vcycle(const double* r, double* z);
  // x ~ M^-1 b by full multigrid up to level 1 and interpolation to the fine level (b, x padded,
  // must not alias; ghost rows of x are zero): b restricted down the levels (P^T), the coarsest
  // level solved exactly, then on each level l >= 1 from the coarsest up: x_l = P x_{l+1} and
  // `cycles` V-cycles on A_l x_l = b_l from there; x = P_0 x_1. cycles = 0: interpolated only.
  // A function of b and the operators alone, the same bits with any thread count.
  void fullMultigrid(const double* b, double* x, int cycles);

  // Galerkin operator of level l >= 1 (for the single-level case, level 0's assembled matrix).
  const Csr& levelMatrix(int l) const { return levels_[l].A; }
  // Transfer between level l (fine side) and l + 1 (coarse side).
  const Transfer3D& transfer(int l) const { return transfers_[l]; }

  size_t memoryBytes() const;

 private:
  // One colour pass of a Gauss-Seidel sweep: the planes of `colour`, rows forward or backward.
  struct ColourPass {
    int colour = 0;
    bool forward = true;
  };
  struct Level {
    int nx = 0, ny = 0, nz = 0;
    Csr A;                                      // l >= 1, or l = 0 when it is the only level
    std::vector<double> base;                   // A.val with W = 0 (resetPenalties)
    std::vector<int64_t> diagPos;               // position of A(i, i) in A.val
    std::vector<double> invDiag;                // 1 / A(i, i)
    std::vector<double> x, b, res;              // n x 3 work vectors (l >= 1)
    int colours = 1;                            // planes k and k + colours never couple in A
    std::vector<ColourPass> prePlan, postPlan;  // smoothing (levels between fine and coarsest)
  };
  struct Fine {
    int px = 0, py = 0, pz = 0;
    int64_t rows = 0;
    BoxLayout layout;
    std::vector<double> inv;      // 1/|N(q)| on real points, 0 on ghosts
    std::vector<double> diagK;    // (D^T D)_pp = 1 + sum_q inv_q^2
    std::vector<double> w;        // penalty
    std::vector<double> invDiag;  // 1 / (diagK + w)
    std::vector<double> L, res;   // padded x 3 work vectors
  };
  // Composite 1D interpolation from the fine axis to level l: at most 2 (index, weight) pairs.
  struct Comp1 {
    int count = 0;
    int idx[2] = {0, 0};
    double w[2] = {0, 0};
  };

  // Colours of the fine level: its 25-point operator couples planes at most 2 apart.
  static constexpr int kFineColours = 3;
  static void appendSweep(std::vector<ColourPass>& plan, int colours, bool forward);
  // Pre-smoothing (pre) or its adjoint, the post-smoothing, as colour passes.
  static std::vector<ColourPass> smoothingPlan(int colours, int sweeps, bool symmetric, bool pre);

  void computeL(const double* x, double* L) const;
  Status addPenaltyToLevels(int p, double delta);
  // A.val += basePenalty_ * P_l^T P_l on every coarse level (and the diagonal's inverse).
  void addBaseToLevels();
  // The 1D Gram matrices of the composite interpolation per level and axis (gramX_ ...).
  Status buildGrams();
  void fineSweepPlane(int k, bool forward, double* x, const double* b);
  void fineColourPass(int colour, bool forward, double* x, const double* b);
  void fineResidual(const double* x, const double* b, double* res) const;
  void coarseColourPass(int l, int colour, bool forward);
  void coarseResidual(int l);
  // One V-cycle on level l for levels_[l].b, from levels_[l].x (zeroStart: from zero).
  void cycle(int l, bool zeroStart = true);
  void solveCoarsest();
  Status refactorCoarsest();
  bool updateCoarsest();
  static void finishLevel(Level& lv, int minColours);
  // A penalty change at the coarsest level: delta * v v^T on at most 8 entries.
  struct CoarseTerm {
    int count = 0;
    int idx[8];
    double v[8];
    double delta = 0;
  };

  Grid grid_;
  MultigridOptions opt_;
  Fine fine_;
  int fineColours_ = kFineColours;
  std::vector<ColourPass> finePre_, finePost_;
  std::vector<Level> levels_;
  std::vector<Transfer3D> transfers_;
  std::vector<std::vector<Comp1>> compX_, compY_, compZ_;  // per level
  // Per level and axis, G = C^T C of the composite 1D interpolation C (fine axis -> level l),
  // banded: G(a, a + d) at [kGramWidth * a + d + kGramReach], |d| <= kGramReach. Built on the
  // first setBasePenalty with beta2 > 0.
  static constexpr int kGramReach = 2, kGramWidth = 2 * kGramReach + 1;
  std::vector<std::vector<double>> gramX_, gramY_, gramZ_;
  double basePenalty_ = 0;
  TransferWork work_;
  Eigen::MatrixXd coarsestL_;        // lower Cholesky factor of the coarsest operator
  std::vector<double> coarseWork_;   // the coarsest solve's right-hand sides, column by column
  std::vector<CoarseTerm> pending_;  // changes not yet in coarsestL_
  bool factorValid_ = false;         // coarsestL_ + pending_ describe the coarsest operator
  int coarsestBand_ = 0;             // lower bandwidth of the coarsest operator (and factor)
  bool coarsestDirty_ = true;
  bool lastRefactored_ = true;
};

}  // namespace hairsketch
