/* hpgen's C runtime, part 4: batches of independent runs, one after the other (callers split
   a batch across threads). Included by hpgen_runtime.c after hpgen_runs.c. */

/* Advance B independent runs (runs[0..B-1]) by `steps` steps each, one after the other,
   exactly as B calls of hpgen_advance: records of run b start at g_rec + b * per_run * NN
   (p_rec + b * per_run * D), statuses in st[b]. Callers split a batch across threads. */
HPGEN_EXPORT long long hpgen_advance_batch(hpgen_run* runs, long long B, double h,
                                           long long steps, long long every,
                                           const hpgen_options* o, long long per_run,
                                           double* g_rec, double* p_rec, hpgen_status* st) {
    long long b, failed = 0;
    for (b = 0; b < B; ++b) {
        hpgen_advance(runs + b, h, steps, every, o, g_rec + b * per_run * HPGEN_NN,
                      p_rec + b * per_run * HPGEN_D, st + b);
        if (st[b].code != HPGEN_OK) ++failed;
    }
    return failed;
}


/* Advance B independent runs like B calls of hpgen_advance_record: rows of run b start at
   rows + b * per_run * W, its row count in n_rec[b], its status in st[b]. Returns the number
   of failed runs. Callers split a batch across threads. */
HPGEN_EXPORT long long hpgen_advance_record_batch(hpgen_run* runs, long long B, double h,
                                                  long long steps, long long every,
                                                  const hpgen_options* o, long long per_run,
                                                  double* rows, long long* n_rec,
                                                  hpgen_status* st) {
    long long b, failed = 0;
    for (b = 0; b < B; ++b) {
        hpgen_advance_record(runs + b, h, steps, every, o, rows + b * per_run * HPGEN_W,
                             n_rec + b, st + b);
        if (st[b].code != HPGEN_OK) ++failed;
    }
    return failed;
}


/* Start B runs (runs[0..B-1]) as B calls of hpgen_run_init and, when cs > 0, of
   hpgen_run_set_compose with the same gammas: run b from g0 + b * g_stride (g_stride 0: one
   g0 shared by the runs; flat column-major), p0 + b * HPGEN_D and z0 + b * HPGEN_NZ.
   Returns -1 (no run touched) when cs is outside 0..HPGEN_CS_MAX, else 0. Callers split a
   batch across threads. */
HPGEN_EXPORT int hpgen_run_init_batch(hpgen_run* runs, long long B, const double* g0,
                                      long long g_stride, const double* p0, const double* z0,
                                      long long cs, const double* gammas) {
    long long b;
    if (cs < 0 || cs > HPGEN_CS_MAX) return -1;
    for (b = 0; b < B; ++b) {
        hpgen_run_init(runs + b, g0 + b * g_stride, p0 + b * HPGEN_D, z0 + b * HPGEN_NZ);
        if (cs > 0) hpgen_run_set_compose(runs + b, cs, gammas);
    }
    return 0;
}
