/* hpgen's C runtime, part 6b: the state of L runs in lanes (hpgen_lane_set) and what the
   lanes loops of hpgen_lanes.c share: gather / scatter a lane, start, the tail of a step
   (the scalar redo of the lanes that did not step, records), the finite test and the commit
   of the lanes that stepped, the final scatter. Included by hpgen_lanes.c. */

/* L runs in lanes: the state hpgen_run_cstep reads and writes (an explicit step keeps no
   predictor offsets), and the lanes' bookkeeping: records written, alive (not stopped by a
   failure), how many are */
typedef struct hpgen_lane_set {
    double g[HPGEN_NN * HPGEN_L], p[HPGEN_D * HPGEN_L], z[HPGEN_NZ * HPGEN_L];
#if !HPGEN_EXPLICIT
    double dz[HPGEN_PH][HPGEN_NZ * HPGEN_L];
    double cdz[HPGEN_CS_MAX][HPGEN_CH][HPGEN_NZ * HPGEN_L];
    long long hp[HPGEN_L], ch[HPGEN_L];
    double lu[HPGEN_L][HPGEN_LU_SIZE];             /* each lane's kept J^{-1} */
    int piv[HPGEN_L][HPGEN_NZ];
    long long valid[HPGEN_L];
#endif
    long long k[HPGEN_L], rec[HPGEN_L], alive[HPGEN_L], nalive;
} hpgen_lane_set;

/* lane l <-> run r */
static void hpgen_lane_gather(hpgen_lane_set* s, const hpgen_run* r, int l) {
    int i;
    for (i = 0; i < HPGEN_NN; ++i) s->g[i * HPGEN_L + l] = r->g[i];
    for (i = 0; i < HPGEN_D; ++i) s->p[i * HPGEN_L + l] = r->p[i];
    for (i = 0; i < HPGEN_NZ; ++i) s->z[i * HPGEN_L + l] = r->z[i];
#if !HPGEN_EXPLICIT
    {
        long long c;
        int j;
        for (j = 0; j < HPGEN_PH; ++j)
            for (i = 0; i < HPGEN_NZ; ++i) s->dz[j][i * HPGEN_L + l] = r->dz[j][i];
        for (c = 0; c < r->cs; ++c)
            for (j = 0; j < HPGEN_CH; ++j)
                for (i = 0; i < HPGEN_NZ; ++i) s->cdz[c][j][i * HPGEN_L + l] = r->cdz[c][j][i];
        s->hp[l] = r->have_prev;
        s->ch[l] = r->c_have;
        memcpy(s->lu[l], r->lu, sizeof r->lu);
        memcpy(s->piv[l], r->piv, sizeof r->piv);
        s->valid[l] = r->lu_valid;
    }
#endif
    s->k[l] = r->k;
}

static void hpgen_lane_scatter(const hpgen_lane_set* s, hpgen_run* r, int l) {
    int i;
    for (i = 0; i < HPGEN_NN; ++i) r->g[i] = s->g[i * HPGEN_L + l];
    for (i = 0; i < HPGEN_D; ++i) r->p[i] = s->p[i * HPGEN_L + l];
    for (i = 0; i < HPGEN_NZ; ++i) r->z[i] = s->z[i * HPGEN_L + l];
#if !HPGEN_EXPLICIT
    {
        long long c;
        int j;
        for (j = 0; j < HPGEN_PH; ++j)
            for (i = 0; i < HPGEN_NZ; ++i) r->dz[j][i] = s->dz[j][i * HPGEN_L + l];
        for (c = 0; c < r->cs; ++c)
            for (j = 0; j < HPGEN_CH; ++j)
                for (i = 0; i < HPGEN_NZ; ++i) r->cdz[c][j][i] = s->cdz[c][j][i * HPGEN_L + l];
        r->have_prev = s->hp[l];
        r->c_have = s->ch[l];
        memcpy(r->lu, s->lu[l], sizeof r->lu);
        memcpy(r->piv, s->piv[l], sizeof r->piv);
        r->lu_valid = s->valid[l];
    }
#endif
    r->k = s->k[l];
}

/* the lanes of runs[0..L-1], every one alive, no record written, statuses initialised */
static void hpgen_lanes_start(hpgen_lane_set* s, const hpgen_run* runs, hpgen_status* st) {
    int l;
    for (l = 0; l < HPGEN_L; ++l) {
        hpgen_status_init(st + l);
        hpgen_lane_gather(s, runs + l, l);
        s->alive[l] = 1;
        s->rec[l] = 0;
    }
    s->nalive = HPGEN_L;
}

/* The tail of a step of the lanes: every alive lane that did not step (ok[l] = 0) redoes
   the step by hpgen_run_cstep from its state before it (a lane that fails there stops);
   then every alive lane at a global step k % every == 0 writes its record (lane l's at
   g_rec + l per_run NN, p_rec + l per_run D) */
static inline void hpgen_lanes_redo_record(hpgen_lane_set* s, hpgen_run* runs,
                                           const long long* ok, const double* hv1,
                                           const hpgen_options* o, const hpgen_options* full,
                                           hpgen_status* st, long long every,
                                           long long per_run, double* g_rec, double* p_rec) {
    int i, l;
    for (l = 0; l < HPGEN_L; ++l) {
        if (!s->alive[l] || ok[l]) continue;
        hpgen_lane_scatter(s, runs + l, l);
        if (hpgen_run_cstep(runs + l, hv1, o, full, st + l, 1) != HPGEN_OK) {
            s->alive[l] = 0;
            --s->nalive;
            continue;
        }
        hpgen_lane_gather(s, runs + l, l);
    }
    for (l = 0; l < HPGEN_L; ++l) {
        if (!s->alive[l] || s->k[l] % every != 0) continue;
        for (i = 0; i < HPGEN_NN; ++i)
            g_rec[(l * per_run + s->rec[l]) * HPGEN_NN + i] = s->g[i * HPGEN_L + l];
        for (i = 0; i < HPGEN_D; ++i)
            p_rec[(l * per_run + s->rec[l]) * HPGEN_D + i] = s->p[i * HPGEN_L + l];
        ++s->rec[l];
    }
}

/* the alive lanes back into their runs, their statuses' steps set (a stopped lane's run
   and status are hpgen_run_cstep's) */
static inline void hpgen_lanes_finish(const hpgen_lane_set* s, hpgen_run* runs,
                                      hpgen_status* st) {
    int l;
    for (l = 0; l < HPGEN_L; ++l) {
        if (!s->alive[l]) continue;
        hpgen_lane_scatter(s, runs + l, l);
        st[l].step = s->k[l];
    }
}

/* ok[l] &= the entries of lane l of g1 (NN) and p1 (D) sum to a finite number (the common
   path of hpgen_all_finite; a lane whose sum is not finite redoes the step in scalar code,
   which tells an overflowing sum from a non-finite entry) */
static inline void hpgen_lanes_finite(const double* g1, const double* p1, long long* ok) {
    int i, l;
    for (l = 0; l < HPGEN_L; ++l) {
        double sg = 0.0, sp = 0.0;
        for (i = 0; i < HPGEN_NN; ++i) sg += g1[i * HPGEN_L + l];
        for (i = 0; i < HPGEN_D; ++i) sp += p1[i * HPGEN_L + l];
        ok[l] &= (sg - sg == 0.0) & (sp - sp == 0.0);
    }
}

/* (g, p, z) of the lanes with ok[l] from (g1, p1, zs): whole arrays when every lane stepped
   (the common case), else lane by lane. Returns whether every lane stepped. */
static inline int hpgen_lanes_commit(hpgen_lane_set* s, const long long* ok, const double* g1,
                                     const double* p1, const double* zs) {
    long long all = 1;
    int i, l;
    for (l = 0; l < HPGEN_L; ++l) all &= ok[l];
    if (all) {
        memcpy(s->g, g1, sizeof s->g);
        memcpy(s->p, p1, sizeof s->p);
        memcpy(s->z, zs, sizeof s->z);
        return 1;
    }
    for (l = 0; l < HPGEN_L; ++l) {
        if (!ok[l]) continue;
        for (i = 0; i < HPGEN_NN; ++i) s->g[i * HPGEN_L + l] = g1[i * HPGEN_L + l];
        for (i = 0; i < HPGEN_D; ++i) s->p[i * HPGEN_L + l] = p1[i * HPGEN_L + l];
        for (i = 0; i < HPGEN_NZ; ++i) s->z[i * HPGEN_L + l] = zs[i * HPGEN_L + l];
    }
    return 0;
}
