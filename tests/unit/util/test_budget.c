/* test_budget.c -- the resource budget (budget.h), the up-front determinant
 * estimate and the region's degenerate domains (issue 11). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <string.h>
#include <time.h>
#include <malloc.h>
#include <pthread.h>
#include <cmocka.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/budget.h"
#include "recstab/analysis.h"
#include "recstab/charpoly.h"
#include "recstab/routh.h"
#include "testutil.h"

static double mono(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* a time limit is reported at the first check past it, sticky for every
 * later check, with the message naming the limit and the option */
static void test_time_limit(void **state)
{
    rs_error_t err;
    double t0 = mono(), t;
    int r = RS_OK;
    (void) state;
    rs_error_init(err);
    rs_budget_start(0.05, 0, 0);
    while (r == RS_OK && mono() - t0 < 5.0) r = rs_budget_check(err, "the test loop");
    t = mono() - t0;
    assert_int_equal(r, RS_ERR_LIMIT);
    assert_true(t >= 0.05 && t < 1.05);
    assert_string_equal(err->msg, "time limit of 0.05 s reached during the test loop; raise it with --time-limit");
    assert_true(rs_budget_exceeded());
    rs_error_init(err);
    assert_int_equal(rs_budget_check(err, "another loop"), RS_ERR_LIMIT);
    assert_string_equal(err->msg, "time limit of 0.05 s reached during the test loop; raise it with --time-limit");
    /* a new start clears it; no limit means no error */
    rs_budget_start(0, 0, 0);
    assert_false(rs_budget_exceeded());
    assert_int_equal(rs_budget_check(NULL, "x"), RS_OK);
    rs_budget_stop();
}

/* FLINT and GMP allocations are counted: 32 MB against a limit of 8 MB */
static void test_memory_limit(void **state)
{
    rs_error_t err;
    slong before;
    void *p;
    mpz_t z;
    (void) state;
    rs_error_init(err);
    rs_budget_start(0, 0, 8);
    before = rs_budget_memory_used();
    p = flint_malloc(32 << 20);
    memset(p, 1, 32 << 20);
    assert_true(rs_budget_memory_used() - before >= (32 << 20));
    assert_int_equal(rs_budget_check(err, "the allocation test"), RS_ERR_LIMIT);
    assert_string_equal(err->msg, "memory limit of 8 MB reached during the allocation test; raise it with --memory-limit");
    flint_free(p);
    assert_true(rs_budget_memory_used() - before < (1 << 20));
    /* GMP's allocations (fmpz's big integers) go through the same count */
    rs_budget_start(0, 0, 8);
    mpz_init2(z, (mp_bitcnt_t) 1 << 28);   /* 32 MB */
    assert_int_equal(rs_budget_check(NULL, "mpz"), RS_ERR_LIMIT);
    mpz_clear(z);
    rs_budget_start(0, 0, 8);
    assert_int_equal(rs_budget_check(NULL, "after freeing"), RS_OK);
    rs_budget_stop();
}

static void test_estimate(void **state)
{
    rs_error_t err;
    (void) state;
    rs_error_init(err);
    rs_budget_start(10, 0, 100);
    assert_int_equal(rs_budget_estimate(err, "the work", 1.0, 1e6), RS_OK);
    assert_int_equal(rs_budget_estimate(err, "the work", 1000.0, 0), RS_ERR_LIMIT);
    assert_string_equal(err->msg, "the work would take about 1e+03 s (estimated), more than the time limit of 10 s "
                                  "allows; raise it with --time-limit");
    assert_int_equal(rs_budget_estimate(err, "the work", 1.0, 1e9), RS_ERR_LIMIT);
    assert_string_equal(err->msg, "the work would need about 954 MB (estimated), more than the memory limit of "
                                  "100 MB allows; raise it with --memory-limit");
    /* an estimate alone does not exceed the budget */
    assert_false(rs_budget_exceeded());
    rs_budget_stop();
}

/* det(lambda I - P) for a generic n x n matrix P of n^2 parameters */
static int generic_det(fmpz_mpoly_t det, slong n, fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    fmpz_mpoly_struct *A = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
    slong i;
    int r;
    for (i = 0; i < n * n; i++) {
        fmpz_mpoly_init(A + i, ctx);
        fmpz_mpoly_gen(A + i, i + 1, ctx);
        fmpz_mpoly_neg(A + i, A + i, ctx);
        if (i % (n + 1) == 0) {
            fmpz_mpoly_t l;
            fmpz_mpoly_init(l, ctx);
            fmpz_mpoly_gen(l, 0, ctx);
            fmpz_mpoly_add(A + i, A + i, l, ctx);
            fmpz_mpoly_clear(l, ctx);
        }
    }
    r = rs_charpoly_det(det, A, n, RS_CHARPOLY_MAX_TERMS, ctx, err);
    for (i = 0; i < n * n; i++) fmpz_mpoly_clear(A + i, ctx);
    flint_free(A);
    return r;
}

/* det(lambda I - P) = sum_k (-1)^k lambda^(6-k) E_k(P), E_k the sum of the
 * C(6,k) principal k-minors, each k! distinct monomials of distinct
 * parameters: sum_k 6!/(6-k)! = 1957 terms, no cancellation.  Order 8 is
 * refused before any elimination (before the estimate: after 12 s and
 * 580 MB on this machine). */
static void test_det_estimate(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t det;
    rs_error_t err;
    double t0;
    (void) state;
    rs_error_init(err);
    fmpz_mpoly_ctx_init(ctx, 1 + 6 * 6, ORD_LEX);
    fmpz_mpoly_init(det, ctx);
    assert_int_equal(generic_det(det, 6, ctx, err), RS_OK);
    assert_int_equal(fmpz_mpoly_length(det, ctx), 1957);
    fmpz_mpoly_clear(det, ctx);
    fmpz_mpoly_ctx_clear(ctx);

    fmpz_mpoly_ctx_init(ctx, 1 + 8 * 8, ORD_LEX);
    fmpz_mpoly_init(det, ctx);
    t0 = mono();
    assert_int_equal(generic_det(det, 8, ctx, err), RS_ERR_LIMIT);
    assert_true(mono() - t0 < 2.0);
    assert_non_null(strstr(err->msg, "estimated before the elimination"));
    fmpz_mpoly_clear(det, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* A symbolic Routh row whose products cannot fit is refused at its estimate,
 * before the first product: q = sum_k (a+b+c+1)^(52+k) z^k (k = 0..8) has
 * coefficients of C(55,3) = 26 235 to C(63,3) = 39 711 terms (the dense
 * trivariate count), so row 2 multiplies pairs of about 10^9 term pairs each
 * (seconds apiece by the calibration in budget.h), far past a 1 s budget. */
static void test_routh_row_estimate(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, base, t;
    rs_routh_mpoly_t r;
    rs_error_t err;
    slong k;
    double t0;
    (void) state;
    rs_error_init(err);
    fmpz_mpoly_ctx_init(ctx, 4, ORD_LEX);      /* z, a, b, c */
    fmpz_mpoly_init(q, ctx); fmpz_mpoly_init(base, ctx); fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_set_str_pretty(base, "a+b+c+1", (const char *[]) {"z", "a", "b", "c"}, ctx);
    for (k = 0; k <= 8; k++) {
        fmpz_mpoly_pow_ui(t, base, 52 + k, ctx);
        assert_int_equal(fmpz_mpoly_length(t, ctx), (55 + k) * (54 + k) * (53 + k) / 6);
        fmpz_mpoly_gen(base, 0, ctx);
        fmpz_mpoly_pow_ui(base, base, k, ctx);
        fmpz_mpoly_mul(t, t, base, ctx);
        fmpz_mpoly_add(q, q, t, ctx);
        fmpz_mpoly_set_str_pretty(base, "a+b+c+1", (const char *[]) {"z", "a", "b", "c"}, ctx);
    }
    rs_routh_mpoly_init(r);
    rs_budget_start(1.0, 0.0, 0);
    t0 = mono();
    assert_int_equal(rs_routh_mpoly(r, q, 0, ctx, err), RS_ERR_LIMIT);
    assert_true(mono() - t0 < 1.0);
    assert_non_null(strstr(err->msg, "symbolic Routh array would take about"));
    rs_budget_stop();
    rs_routh_mpoly_clear(r, ctx);
    fmpz_mpoly_clear(q, ctx); fmpz_mpoly_clear(base, ctx); fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* A Routh array stopped by the budget reports the stop: before, the segment
 * loop took the unfinished remainder chain for a zero row and ran past its
 * arrays (heap overflow found by the fuzz regression region-algebraic-
 * endpoint-swell under --time-limit 1).  p = (lambda + 2)^12: any degree-12
 * polynomial with a non-trivial chain does; the budget is spent at once. */
static void test_routh_stop(void **state)
{
    fmpz_poly_t p, l;
    rs_routh_t r;
    rs_error_t err;
    (void) state;
    rs_error_init(err);
    fmpz_poly_init(p); fmpz_poly_init(l);
    fmpz_poly_set_coeff_si(l, 1, 1);
    fmpz_poly_set_coeff_si(l, 0, 2);
    fmpz_poly_pow(p, l, 12);
    rs_routh_init(r);
    rs_budget_start(1e-9, 1.0, 0);       /* already past the limit */
    assert_int_equal(rs_routh_fmpz_poly(r, p, err), RS_ERR_LIMIT);
    assert_non_null(strstr(err->msg, "time limit"));
    rs_budget_stop();
    rs_routh_clear(r);
    rs_error_clear(err);
    rs_error_init(err);
    rs_routh_init(r);
    rs_budget_start(0.0, 0.0, 0);        /* no limits (clears the sticky stop) */
    assert_int_equal(rs_routh_fmpz_poly(r, p, err), RS_OK);   /* all 12 roots at -2 */
    assert_int_equal(r->count->outside, 12);
    rs_budget_stop();
    rs_routh_clear(r);
    fmpz_poly_clear(p); fmpz_poly_clear(l);
}

static json_t *run_string(const char *text, int *code, rs_error_t err)
{
    rs_case_t c;
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome;
    rs_case_init(c);
    rs_options_default(&opt);
    opt.time_limit = 20;   /* the endless loop this guards against ends here */
    *code = rs_case_parse_string(c, "region.case", text, strlen(text), err);
    if (*code == RS_OK) *code = rs_analysis_run(&doc, &outcome, c, &opt, err);
    rs_case_clear(c);
    return doc;
}

/* assume w = 1/2 leaves one value: x[n+1] = (1 - h w) x[n] at h = 1 has the
 * root 1/2, so the region is the single stable point w = 1/2 (before: an
 * endless refinement between the equal ends 1/2 and 1/2) */
static void test_region_single_value(void **state)
{
    rs_error_t err;
    int code;
    json_t *doc, *o, *ivs, *iv;
    (void) state;
    rs_error_init(err);
    doc = run_string("param h w\nassume w = 1/2\nunknown x\neq x[n+1] = x[n] - h*w*x[n]\n"
                     "analyse region w at h=1\n", &code, err);
    assert_int_equal(code, RS_OK);
    o = json_array_get(json_object_get(doc, "results"), 0);
    ivs = json_object_get(o, "intervals");
    assert_int_equal(json_array_size(ivs), 1);
    iv = json_array_get(ivs, 0);
    assert_string_equal(json_string_value(json_object_get(iv, "status")), "stable");
    assert_true(json_is_true(json_object_get(iv, "lo_closed")));
    assert_true(json_is_true(json_object_get(iv, "hi_closed")));
    assert_true(json_equal(json_object_get(iv, "lo"), json_object_get(iv, "hi")));
    json_decref(doc);
}

/* w > 2, w < 1: no admissible value (before: SIGABRT in FLINT) */
static void test_region_contradictory(void **state)
{
    rs_error_t err;
    int code;
    (void) state;
    rs_error_init(err);
    assert_null(run_string("param h w\nassume w > 2, w < 1\nunknown x\neq x[n+1] = x[n] - h*w*x[n]\n"
                           "analyse region w at h=1\n", &code, err));
    assert_int_equal(code, RS_ERR_INPUT);
    assert_string_equal(err->msg, "the assumptions are contradictory: no value of 'w' satisfies them");
}

/* budget.c's cache of small freed blocks: a reused block holds its request
 * (usable size >= the request, every byte written), flint_calloc's reused
 * block is zero although it was freed dirty, the cached blocks stay counted
 * (the count never drops below what is held), and freeing everything brings
 * the count back to within the cache's bound (16 classes x 64 blocks x 248
 * bytes < 1 MB per thread; a thread's cache is emptied when it exits). */
#define NSMALL 12000   /* about 1.8 MB held: well past the counting's lag below */
static void small_blocks_round(void)
{
    static unsigned char *b[NSMALL];
    slong i, j, held = 0, before = rs_budget_memory_used();
    for (i = 0; i < NSMALL; i++) {
        size_t n = (size_t) (i * 37) % 300;
        b[i] = (i % 2) ? flint_malloc(n + 1) : flint_calloc(n + 1, 1);
        assert_non_null(b[i]);
        assert_true(malloc_usable_size(b[i]) >= n + 1);
        for (j = 0; j <= (slong) n; j++) {
            if (i % 2 == 0) assert_int_equal(b[i][j], 0);
            b[i][j] = 0xa5;
        }
        held += (slong) n + 1;
    }
    /* each thread adds its local sum to the count once it passes +-256 KB
     * (budget.c's FLUSH), so before and now each lag by less than that */
    assert_true(rs_budget_memory_used() - before >= held - 2 * (256 << 10));
    for (i = 0; i < NSMALL; i++) flint_free(b[i]);
}

static void *small_blocks_thread(void *arg)
{
    (void) arg;
    small_blocks_round();
    flint_cleanup();   /* this thread's FLINT caches (LeakSanitizer in check-sanitize) */
    return NULL;
}

static void test_small_block_cache(void **state)
{
    slong before;
    pthread_t th;
    int k;
    (void) state;
    rs_budget_start(0, 0, 0);
    before = rs_budget_memory_used();
    for (k = 0; k < 3; k++) small_blocks_round();   /* the later rounds reuse cached blocks */
    assert_true(rs_budget_memory_used() - before < (1 << 20));
    assert_int_equal(pthread_create(&th, NULL, small_blocks_thread, NULL), 0);
    assert_int_equal(pthread_join(th, NULL), 0);
    assert_true(rs_budget_memory_used() - before < (1 << 20));
    rs_budget_stop();
}

/* GMP's blocks of up to 16 bytes come from budget.c's reserved region (16 MB,
 * then malloc): many small mpz (past the region's 2^20 blocks, so both
 * sources), grown past 16 bytes (realloc out of the region) and shrunk
 * again, each value checked against the same arithmetic in fmpz; then freed
 * and allocated again (the freed blocks are reused: the count does not grow
 * by another region), also from a second thread. */
#define NMPZ 1100000
static void small_mpz_round(void)
{
    mpz_t *z = flint_malloc(NMPZ * sizeof(mpz_t));
    slong i;
    fmpz_t f, g;
    fmpz_init(f); fmpz_init(g);
    for (i = 0; i < NMPZ; i++) {
        mpz_init2(z[i], 64);
        mpz_set_si(z[i], (slong) i * 7919 - 3);
    }
    for (i = 0; i < NMPZ; i += 1013) {   /* grown to about 200 bits, then reduced */
        mpz_mul_2exp(z[i], z[i], 150 + (ulong) (i % 50));
        mpz_add_ui(z[i], z[i], 1);
        fmpz_set_si(f, (slong) i * 7919 - 3);
        fmpz_mul_2exp(f, f, 150 + (ulong) (i % 50));
        fmpz_add_ui(f, f, 1);
        fmpz_set_mpz(g, z[i]);
        assert_true(fmpz_equal(f, g));
        mpz_realloc2(z[i], 64);           /* too big for 64 bits: GMP sets it to 0 */
        mpz_set_si(z[i], (slong) i * 7919 - 3);
    }
    for (i = 0; i < NMPZ; i += 7)
        assert_int_equal(mpz_get_si(z[i]), (slong) i * 7919 - 3);
    for (i = 0; i < NMPZ; i++) mpz_clear(z[i]);
    flint_free(z);
    fmpz_clear(f); fmpz_clear(g);
}

static void *small_mpz_thread(void *arg)
{
    (void) arg;
    small_mpz_round();
    flint_cleanup();   /* this thread's FLINT caches (LeakSanitizer in check-sanitize) */
    return NULL;
}

static void test_gmp_small_blocks(void **state)
{
    slong before, after1;
    pthread_t th;
    (void) state;
    rs_budget_start(0, 0, 0);
    before = rs_budget_memory_used();
    small_mpz_round();
    after1 = rs_budget_memory_used();
    small_mpz_round();
    assert_true(rs_budget_memory_used() - after1 < (4 << 20));
    assert_int_equal(pthread_create(&th, NULL, small_mpz_thread, NULL), 0);
    assert_int_equal(pthread_join(th, NULL), 0);
    assert_true(rs_budget_memory_used() - before < (40 << 20));
    rs_budget_stop();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_time_limit), cmocka_unit_test(test_memory_limit), cmocka_unit_test(test_estimate),
        cmocka_unit_test(test_det_estimate), cmocka_unit_test(test_routh_row_estimate), cmocka_unit_test(test_routh_stop), cmocka_unit_test(test_region_single_value),
        cmocka_unit_test(test_region_contradictory), cmocka_unit_test(test_small_block_cache),
        cmocka_unit_test(test_gmp_small_blocks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
