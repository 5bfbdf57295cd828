// Multiple-rank update/downdate of a supernodal LDL^T factor on the diagonal (method S3.2,
// paper §4.2). Clean-room from Gill, Golub, Murray & Saunders (1974), method C1, and Davis &
// Hager (1999, 2001): a term alpha * e_p e_p^T changes only the columns on the elimination-tree
// path from p to the root, and the pattern of L never changes.
//
// Terms are applied as one multiple-rank pass over the union of their paths: supernodes are
// visited in postorder; at each, the vectors that reach it (its own terms plus the vectors coming
// up from its children) form a dense |R_s| x k block W. Two kernels do the same arithmetic:
//  - Blocked (default): a panel of columns is eliminated at once. With Y = L_pp^-1 W_p (the C1
//    multipliers of the panel) and a k x k weight matrix Lambda (the alphas, then full: it is
//    the Schur complement of the weights), every column gets g_j = Lambda_j y_j / d'_j and the
//    rows below the panel are updated by two GEMMs with inner dimension k:
//    L_below += (W_below G - L_below UT(Y G)), W_below -= L_below Y. Vectors travel in chunks of
//    at most `chunk` columns; each chunk's residual rows and Lambda go to the parent.
//  - Rank1: C1 column by column with all vectors of a supernode, rows swept in strips (the
//    reference the blocked kernel is tested against).
// Sequential rank-1 application in term order is the mathematical meaning: callers put updates
// before downdates so that every intermediate matrix stays positive definite.
#pragma once

#include <vector>

#include "status.hpp"
#include "supernodal_factor.hpp"

namespace hairsketch {

struct DiagonalTerm {
  int position = 0;    // elimination position (symbolic().iperm[grid point])
  double alpha = 0.0;  // M <- M + alpha e e^T (omega^2 to add a constraint, -omega^2 to remove)
};

enum class UpdateKernel {
  Blocked,  // panels of columns eliminated at once; the sweeps below are GEMMs (default)
  Rank1,    // plain C1 rank-1 sweeps (reference; same arithmetic, regrouped)
};

struct UpdateOptions {
  UpdateKernel kernel = UpdateKernel::Blocked;
  int chunk = 256;  // blocked: at most this many vectors per pass through a supernode
  // A pivot d -> d' is accepted when d' is finite and d' > pivotTolerance * d.
  double pivotTolerance = 1e-12;
  int panel = 48;  // columns per panel
};

struct UpdateStats {
  double flops = 0;
  int supernodes = 0;  // supernodes visited (the merged paths)
  int maxRank = 0;     // largest number of vectors through one supernode
};

// Modifies F in place. On NotPositiveDefinite the factor is damaged and marked invalid: the
// caller must refactor from the matrix.
Status modifyDiagonal(SupernodalFactor& F, const std::vector<DiagonalTerm>& terms,
                      const UpdateOptions& options = {}, UpdateStats* stats = nullptr);

// Flops modifyDiagonal would spend on these positions (the cost model's path cost).
double estimateModifyFlops(const SupernodalSymbolic& S, const std::vector<int>& positions);

}  // namespace hairsketch
