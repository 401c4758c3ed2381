/* hpgen's C runtime: the fixed code of every generated module (the exported API of
   hpgen.abi: hpgen_dims, hpgen_step, the runs hpgen_run_* and hpgen_advance*, hpgen_record,
   hpgen_observe, hpgen_linearize, the batches and the lanes). kernels.c includes it last,
   after the model's kernels (see hpgen_runtime.h); its parts, in dependency order:

     hpgen_linalg.c     the Newton matrix: dense LU / cofactors, J^{-1}, norms
     hpgen_newton_sparse.c  a sparse Newton matrix's stop tests and chord iteration
     hpgen_newton.c     Newton on the step's residual, one step (hpgen_step)
     hpgen_runs.c       a run: predictor, run step (its guard), composed step
     hpgen_advance.c    the runs: states, sections, record rows, observables
     hpgen_batch.c      batches of runs
     hpgen_linearize.c  the step's linearization along recorded steps
     hpgen_lanes.c      lane-wise ensembles (models with lane kernels only)
*/
#include "hpgen_runtime.h"

HPGEN_EXPORT const char* hpgen_hash(void) { return HPGEN_HASH; }

/* out[0..3] = ABI version, n, d, nz */
HPGEN_EXPORT void hpgen_dims(long long* out) {
    out[0] = HPGEN_ABI; out[1] = HPGEN_N; out[2] = HPGEN_D; out[3] = HPGEN_NZ;
}

#include "hpgen_linalg.c"
#include "hpgen_newton_sparse.c"
#include "hpgen_newton.c"
#include "hpgen_runs.c"
#include "hpgen_advance.c"
#include "hpgen_batch.c"
#include "hpgen_linearize.c"
#include "hpgen_lanes.c"
