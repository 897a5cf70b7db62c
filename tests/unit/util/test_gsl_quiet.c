/* test_gsl_quiet.c -- rs_gsl_quiet (error.h): GSL's error handler off for
 * the process, set once, safe from many threads at a time.
 * Expected behaviour from GSL's documentation: a routine that fails calls
 * the handler, and the default handler prints and aborts, so the LU
 * decomposition of a 2 x 2 matrix with a permutation of 3 ("permutation
 * length must match matrix size", GSL_EBADLEN) ends the test process
 * unless the handler is off (checked: without rs_gsl_quiet this test
 * aborts); with it off it returns GSL_EBADLEN.  gsl_set_error_handler returns the
 * handler it replaces, so the one in place can be compared with the one
 * gsl_set_error_handler_off installs. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_permutation.h>
#include "recstab/error.h"

/* GSL_EBADLEN through the handler (aborts under GSL's default handler) */
static int bad_length(void)
{
    gsl_matrix *m = gsl_matrix_calloc(2, 2);
    gsl_permutation *p = gsl_permutation_alloc(3);
    int sgn, st = gsl_linalg_LU_decomp(m, p, &sgn);
    gsl_permutation_free(p);
    gsl_matrix_free(m);
    return st;
}

static void test_quiet_from_threads(void **state)
{
    gsl_error_handler_t *h, *off;
    int k, nbad = 0;
    (void) state;
    /* many threads at once: one of them installs the handler, none races */
#pragma omp parallel for reduction(+ : nbad)
    for (k = 0; k < 64; k++) {
        rs_gsl_quiet();
        nbad += bad_length() == GSL_EBADLEN;
    }
    assert_int_equal(nbad, 64);
    /* the handler in place is GSL's "off" handler, and stays after more calls */
    rs_gsl_quiet();
    off = gsl_set_error_handler_off();
    h = gsl_set_error_handler(off);
    assert_ptr_equal(h, off);
    rs_gsl_quiet();
    assert_int_equal(bad_length(), GSL_EBADLEN);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quiet_from_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
