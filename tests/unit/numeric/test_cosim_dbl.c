/* test_cosim_dbl.c -- cmocka tests of the interval-double one-step map and
 * certified radius (numeric/cosim_dbl.h) and of the numeric forms of a
 * map's model (numeric/cosim_forms.h).
 *
 * Independent references only:
 *   - the one-step map in Arb (rs_cosim_transition: arb_mat_exp of the Van
 *     Loan matrices, Woodbury solve in ball arithmetic) at 256 bits: every
 *     entry's midpoint inside the double enclosure, for Li et al.'s
 *     force/force, force/displacement and displacement/displacement models,
 *     explicit and implicit, K = 0..3, at random rational parameters;
 *   - at random Li force/force models: the Arb fast radius
 *     (rs_cosim_fast_radius, 64 bits) must meet the double enclosure, and
 *     the full certified radius at 128 digits (rs_cosim_radius, Arb QR +
 *     certified eigenvalues) must lie inside it;
 *   - the closed form of uncoupled oscillators x'' + d x' + c x = 0 over
 *     H = 1: rho = e^{-d/2} of the least damped one (underdamped);
 *   - the subsystems' blocks computed apart (a map's per-row precomputation)
 *     against the point's own computation, bit for bit;
 *   - the bench map's region: the double route certifies at every point of a
 *     grid and meets the full certified radius (rs_cosim_radius);
 *   - the numeric forms of cases/li-explicit-k1.case over (acc1, c1) against
 *     rs_cosim_li_ff (the paper's matrices written out in cosim.c, not the
 *     case file's lowering): every exact entry inside its interval.
 */
#include "testutil.h"
#include <math.h>
#include <string.h>
#include "recstab/cosim.h"
#include "recstab/casefile.h"
#include "numeric/cosim_fast.h"
#include "numeric/cosim_dbl.h"
#include "numeric/cosim_forms.h"

/* a random rational in [lo, lo + span) with denominator <= 64 */
static void rand_q(fmpq_t q, flint_rand_t st, slong lo, slong span)
{
    ulong den = 1 + n_randint(st, 64);
    fmpz_set_si(fmpq_numref(q), lo * (slong) den + (slong) n_randint(st, (ulong) span * den));
    fmpz_set_ui(fmpq_denref(q), den);
    fmpq_canonicalise(q);
}

/* Li model kind 0 ff, 1 fd, 2 dd at random parameters (c1 in [1/2, 3),
 * d1 in [0, 1), alphas in [1, 3), acc1 in [0, 3), adc1 in [0, 2)) */
static void rand_li(rs_cosim_t cs, flint_rand_t st, int kind, int method, slong order)
{
    fmpq_t v[7];
    fmpz_t two;
    rs_error_t err;
    int i;
    fmpz_init_set_ui(two, 2);
    for (i = 0; i < 7; i++) fmpq_init(v[i]);
    rand_q(v[0], st, 0, 3);
    fmpq_add_si(v[0], v[0], 1);
    fmpq_div_fmpz(v[0], v[0], two);
    rand_q(v[1], st, 0, 1);
    for (i = 2; i < 5; i++) rand_q(v[i], st, 1, 2);
    rand_q(v[5], st, 0, 3);
    rand_q(v[6], st, 0, 2);
    if (kind == 0) assert_int_equal(rs_cosim_li_ff(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    else if (kind == 1) assert_int_equal(rs_cosim_li_fd(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    else assert_int_equal(rs_cosim_li_dd(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    cs->method = method;
    cs->order = order;
    for (i = 0; i < 7; i++) fmpq_clear(v[i]);
    fmpz_clear(two);
}

/* the Arb map at 256 bits inside the double enclosure, which is narrow */
static void test_transition_vs_arb(void **state)
{
    flint_rand_t st;
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_error_t err;
    int kind, meth, it, checked = 0;
    slong K, i, dim;
    (void) state;
    flint_randinit(st);
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    for (kind = 0; kind < 3; kind++)
        for (meth = 0; meth < 2; meth++)
            for (K = 0; K <= 3; K++)
                for (it = 0; it < 3; it++) {
                    arb_mat_t T;
                    double *Tm, *Tr;
                    rand_li(cs, st, kind, meth ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT, K);
                    assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
                    dim = rs_cosim_dbl_dim(d);
                    assert_int_equal(dim, rs_cosim_transition_dim(cs));
                    arb_mat_init(T, dim, dim);
                    Tm = flint_malloc(2 * dim * dim * sizeof(double));
                    Tr = Tm + dim * dim;
                    if (rs_cosim_transition(T, cs, 256, err) == RS_OK) {
                        assert_int_equal(rs_cosim_dbl_transition(Tm, Tr, d), RS_OK);
                        for (i = 0; i < dim * dim; i++) {
                            arb_ptr e = arb_mat_entry(T, i / dim, i % dim);
                            arb_t lo, hi;
                            arb_init(lo);
                            arb_init(hi);
                            {
                                arb_t rad;
                                arb_set_d(lo, Tm[i]);
                                arb_init(rad);
                                arb_set_d(rad, Tr[i]);
                                arb_sub(lo, lo, rad, 256);   /* Tm - Tr, exact at 256 bits */
                                arb_set_d(hi, Tm[i]);
                                arb_add(hi, hi, rad, 256);   /* Tm + Tr */
                                arb_clear(rad);
                            }
                            assert_true(arf_cmp(arb_midref(e), arb_midref(lo)) >= 0);
                            assert_true(arf_cmp(arb_midref(e), arb_midref(hi)) <= 0);
                            /* a useful enclosure: absolute 1e-11 on these O(1..100) entries */
                            assert_true(Tr[i] < 1e-11);
                            arb_clear(lo);
                            arb_clear(hi);
                        }
                        checked++;
                    }
                    flint_free(Tm);
                    arb_mat_clear(T);
                }
    assert_true(checked >= 60);
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
    flint_randclear(st);
}

/* random force/force models: Arb fast radius meets the double one, the
 * 128-digit radius inside it */
static void test_radius_vs_arb(void **state)
{
    flint_rand_t st;
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_error_t err;
    int it, meth, total = 0, dbl_ok = 0, nref = 0;
    (void) state;
    flint_randinit(st);
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    for (meth = 0; meth < 2; meth++)
        for (it = 0; it < 14; it++) {
            rs_radius_t f, g, ref;
            rs_radius_init(f);
            rs_radius_init(g);
            rs_radius_init(ref);
            rand_li(cs, st, 0, meth ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT, 1 + it % 3);
            assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
            total++;
            if (rs_cosim_dbl_radius(f, d) == RS_OK) {
                dbl_ok++;
                assert_true(arb_le(f->lower, f->upper));
                if (rs_cosim_fast_radius(g, cs, 64, err) == RS_OK) {
                    assert_true(arb_le(f->lower, g->upper));
                    assert_true(arb_le(g->lower, f->upper));
                }
                if (rs_cosim_radius(ref, cs, 128, 2048, err) == RS_OK) {
                    nref++;
                    assert_true(arb_le(f->lower, ref->lower));
                    assert_true(arb_le(ref->upper, f->upper));
                }
            }
            rs_radius_clear(f);
            rs_radius_clear(g);
            rs_radius_clear(ref);
        }
    /* random coupled models: simple dominant eigenvalues almost always */
    assert_true(dbl_ok >= total * 8 / 10);
    assert_true(nref >= dbl_ok * 8 / 10);   /* the reference comparison really ran */
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
    flint_randclear(st);
}

/* uncoupled: sub 1 x'' + x'/5 + x = 0, sub 2 x'' + 3x'/5 + x = 0: rho = e^{-1/10} */
static void test_uncoupled_closed_form(void **state)
{
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_radius_t f;
    rs_error_t err;
    fmpq_t v[7];
    arb_t t;
    int i;
    const char *s[7] = { "1", "1/5", "1", "1", "3", "0", "0" };
    (void) state;
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    rs_radius_init(f);
    arb_init(t);
    for (i = 0; i < 7; i++) {
        fmpq_init(v[i]);
        assert_int_equal(fmpq_set_str(v[i], s[i], 10), 0);
    }
    assert_int_equal(rs_cosim_li_ff(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    cs->order = 1;
    assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
    assert_int_equal(rs_cosim_dbl_radius(f, d), RS_OK);
    arb_set_si(t, -1);
    arb_div_ui(t, t, 10, 256);
    arb_exp(t, t, 256);
    assert_true(arb_le(f->lower, t));
    assert_true(arb_ge(f->upper, t));
    /* and it decides 6 digits */
    arb_sub(t, f->upper, f->lower, 128);
    assert_true(arf_cmpabs_2exp_si(arb_midref(t), -20) < 0);
    /* equal subsystems: double eigenvalues, no isolated disc: declined */
    fmpq_set_ui(v[4], 1, 1);
    assert_int_equal(rs_cosim_li_ff(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    cs->order = 1;
    assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
    assert_int_equal(rs_cosim_dbl_radius(f, d), RS_ERR_UNDECIDED);
    for (i = 0; i < 7; i++) fmpq_clear(v[i]);
    arb_clear(t);
    rs_radius_clear(f);
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
}

/* the subsystems' blocks computed apart (rs_cosim_dbl_sub, as a map
 * precomputes them per row) give the same doubles as the point's own
 * computation: transition and radius bit for bit */
static void test_pre_blocks_identical(void **state)
{
    flint_rand_t st;
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_error_t err;
    int kind, meth, it, radii = 0;
    slong K, dim;
    (void) state;
    flint_randinit(st);
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    for (kind = 0; kind < 3; kind++)
        for (meth = 0; meth < 2; meth++)
            for (K = 0; K <= 3; K++)
                for (it = 0; it < 2; it++) {
                    double *T1, *T2, *S[2];
                    const double *pre[2];
                    rs_radius_t f, g;
                    int s, r1, r2;
                    rand_li(cs, st, kind, meth ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT, K);
                    assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
                    dim = rs_cosim_dbl_dim(d);
                    T1 = flint_calloc(4 * dim * dim, sizeof(double));
                    T2 = T1 + 2 * dim * dim;
                    for (s = 0; s < 2; s++) {
                        S[s] = flint_malloc(rs_cosim_dbl_sub_len(d, s) * sizeof(double));
                        assert_int_equal(rs_cosim_dbl_sub(S[s], d, s), 1);
                        pre[s] = S[s];
                    }
                    r1 = rs_cosim_dbl_transition(T1, T1 + dim * dim, d);
                    r2 = rs_cosim_dbl_transition_pre(T2, T2 + dim * dim, d, pre);
                    assert_int_equal(r1, r2);
                    if (r1 == RS_OK) assert_memory_equal(T1, T2, 2 * dim * dim * sizeof(double));
                    rs_radius_init(f);
                    rs_radius_init(g);
                    r1 = rs_cosim_dbl_radius(f, d);
                    r2 = rs_cosim_dbl_radius_pre(g, d, pre);
                    assert_int_equal(r1, r2);
                    if (r1 == RS_OK) {
                        radii++;
                        assert_true(arb_equal(f->lower, g->lower));
                        assert_true(arb_equal(f->upper, g->upper));
                    }
                    rs_radius_clear(f);
                    rs_radius_clear(g);
                    flint_free(S[0]);
                    flint_free(S[1]);
                    flint_free(T1);
                }
    assert_true(radii >= 20);
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
    flint_randclear(st);
}

/* the bench map's region (cases/li-explicit-k1.case: acc1 in [0, 3], c1 in
 * [1/2, 2], d1 = 1/5, alphas 1, adc1 = 1), explicit and implicit k = 1:
 * the double route (Hessenberg QR + inverse iteration eigenvectors)
 * certifies at every point of a 7 x 6 grid, as GSL's eigenvectors did, and
 * meets the full certified radius (rs_cosim_radius, 6 digits) */
static void test_grid_certifies(void **state)
{
    static const char *acc[7] = { "0", "1/3", "1", "3/2", "2", "5/2", "3" };
    static const char *c1[6] = { "1/2", "3/4", "101/100", "3/2", "7/4", "2" };
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_error_t err;
    fmpq_t v[7];
    int i, j, k, meth, ok = 0, total = 0;
    (void) state;
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    for (k = 0; k < 7; k++) fmpq_init(v[k]);
    for (meth = 0; meth < 2; meth++)
        for (i = 0; i < 7; i++)
            for (j = 0; j < 6; j++) {
                rs_radius_t f, g;
                const char *sv[7] = { c1[j], "1/5", "1", "1", "1", acc[i], "1" };
                for (k = 0; k < 7; k++) assert_int_equal(fmpq_set_str(v[k], sv[k], 10), 0);
                assert_int_equal(rs_cosim_li_ff(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
                cs->method = meth ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT;
                cs->order = 1;
                assert_int_equal(rs_cosim_dbl_set_cosim(d, cs, err), RS_OK);
                rs_radius_init(f);
                rs_radius_init(g);
                total++;
                if (rs_cosim_dbl_radius(f, d) == RS_OK) {
                    ok++;
                    assert_int_equal(rs_cosim_radius(g, cs, 6, 1024, err), RS_OK);
                    assert_true(arb_le(f->lower, g->upper));
                    assert_true(arb_le(g->lower, f->upper));
                }
                rs_radius_clear(f);
                rs_radius_clear(g);
            }
    assert_int_equal(ok, total);
    for (k = 0; k < 7; k++) fmpq_clear(v[k]);
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
}

static int in_ival(const fmpq_t q, double m, double r)
{
    arb_t a, b;
    int ok;
    arb_init(a);
    arb_init(b);
    arb_set_d(a, m);
    mag_set_d(arb_radref(a), r);
    arb_set_fmpq(b, q, 256);
    ok = arb_contains(a, b);
    arb_clear(a);
    arb_clear(b);
    return ok;
}

/* the numeric forms of the Li case over (acc1, c1) at grid-like points */
static void test_forms_vs_li(void **state)
{
    static const char *pts[][2] = { { "0", "1/2" }, { "1", "101/100" }, { "3", "2" }, { "7/3", "13/17" } };
    rs_case_t c;
    rs_cosim_model_struct F;
    rs_cosim_nforms_struct *N;
    rs_cosim_t cs;
    rs_cosim_dbl_t d;
    rs_error_t err;
    const char *axis[2] = { "acc1", "c1" };
    fmpq x[2], one[1], fifth[1];
    slong p, i, j, n;
    (void) state;
    rs_case_init(c);
    assert_int_equal(rs_case_parse_file(c, RS_SOURCE_DIR "/cases/li-explicit-k1.case", err), RS_OK);
    assert_int_equal(rs_cosim_model_init(&F, c, err), RS_OK);
    N = rs_cosim_nforms_new(&F, c, axis, 2);
    assert_non_null(N);
    /* S1: v1' = -c1 x1 - d1 v1 + lc, S2: v2' = -ac21/am21 c1 x2 - ...: the
     * subsystems' rows (A_s, B_s) depend on c1 (axis 1) only, not on acc1
     * (it enters through the force, C) */
    assert_int_equal(rs_cosim_nforms_sub_axes(N, 0), 2u);
    assert_int_equal(rs_cosim_nforms_sub_axes(N, 1), 2u);
    rs_cosim_init(cs, 2, 2);
    rs_cosim_dbl_init(d);
    fmpq_init(x + 0);
    fmpq_init(x + 1);
    fmpq_init(one);
    fmpq_init(fifth);
    fmpq_one(one);
    fmpq_set_si(fifth, 1, 5);
    for (p = 0; p < 4; p++) {
        assert_int_equal(fmpq_set_str(x + 0, pts[p][0], 10), 0);
        assert_int_equal(fmpq_set_str(x + 1, pts[p][1], 10), 0);
        assert_int_equal(rs_cosim_nforms_at(d, N, x), 1);
        /* the case: d1 = 1/5, am21 = ac21 = ad21 = 1, adc1 = 1 */
        assert_int_equal(rs_cosim_li_ff(cs, x + 1, fifth, one, one, one, x + 0, one, err), RS_OK);
        assert_int_equal(d->m, 1);
        assert_int_equal(d->order, 1);
        assert_int_equal(d->method, RS_COSIM_EXPLICIT);
        n = 4;
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) {
                assert_true(in_ival(fmpq_mat_entry(cs->A1, i, j), d->A1m[i * 2 + j], d->A1r[i * 2 + j]));
                assert_true(in_ival(fmpq_mat_entry(cs->A2, i, j), d->A2m[i * 2 + j], d->A2r[i * 2 + j]));
            }
        for (i = 0; i < n; i++) {
            assert_true(in_ival(i < 2 ? fmpq_mat_entry(cs->B1, i, 0) : fmpq_mat_entry(cs->B2, i - 2, 0), d->Bm[i],
                                d->Br[i]));
            assert_true(in_ival(fmpq_mat_entry(cs->C, 0, i), d->Cm[i], d->Cr[i]));
        }
        assert_true(in_ival(cs->H, d->Hm, d->Hr));
    }
    fmpq_clear(x + 0);
    fmpq_clear(x + 1);
    fmpq_clear(one);
    fmpq_clear(fifth);
    rs_cosim_dbl_clear(d);
    rs_cosim_clear(cs);
    rs_cosim_nforms_free(N);
    rs_cosim_model_clear(&F);
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_transition_vs_arb),
        cmocka_unit_test(test_radius_vs_arb),
        cmocka_unit_test(test_uncoupled_closed_form),
        cmocka_unit_test(test_pre_blocks_identical),
        cmocka_unit_test(test_grid_certifies),
        cmocka_unit_test(test_forms_vs_li),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
