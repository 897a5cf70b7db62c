/* scheme.h -- from the equations model (model.h) to the lambda-matrix.
 *
 * Each equation (lhs - rhs = 0) is evaluated exactly as a linear form in the
 * shifted unknowns with coefficients in Q[params]; x[n+k] becomes lambda^k
 * times the column of x.  Divisions by parameter expressions are multiplied
 * through and recorded as non-zero assumptions.  Each row is divided by
 * lambda^k, k the lowest shift its equation writes (terms with a zero
 * coefficient included: x[n+1] = 0*x[n] keeps its lambda).  Variables of the polynomial
 * context: the parameters in declaration order, then lambda (then sqrt(d)
 * for a model over Q(sqrt d): sqrt_d below). */
#ifndef RECSTAB_SCHEME_H
#define RECSTAB_SCHEME_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"
#include "recstab/casefile.h"
#include "recstab/model.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_SCHEME_MAX_DEGREE 4096   /* degree in lambda or in any parameter */
#define RS_SCHEME_MAX_UNKNOWNS 64

typedef struct {
    fmpq_mpoly_ctx_t ctx;       /* params..., lambda */
    fmpz_mpoly_ctx_t zctx;      /* same variables, integer coefficients */
    slong nvars;
    slong lambda_var;           /* == nparams */
    char **vars;                /* variable names, "lambda" last */
    slong n;                    /* unknowns (0 for a `char` case) */
    char **unknowns;            /* their names, the columns of M */
    fmpq_mpoly_struct *M;       /* n*n row-major lambda-matrix */
    slong *row_shift;           /* lowest shift each row's equation writes (the row was divided by lambda^it) */
    int from_char;              /* p given directly by `char` */
    int complex_char;           /* a `char` line over Q(i): M is its real 2x2 block form */
    fmpq_mpoly_t charpoly;      /* the `char` polynomial when from_char */
    slong nnonzero;             /* assumptions made by multiplying through */
    fmpq_mpoly_struct *nonzero; /* each must be != 0 */
    char **nonzero_text;        /* "m != 0" */
    rs_loc_t *nonzero_loc;      /* where each was first needed (file points into the
                                   model or its case: valid while they live) */
    slong sqrt_d;               /* d > 0: the model has coefficients in Q(sqrt d) (rk sdirk2);
                                   sqrt(d) is then the variable sqrt_var (after lambda), every
                                   entry reduced by sqrt(d)^2 = d: entries and det are p0 + sqrt(d) p1 */
    slong sqrt_var;
} rs_scheme_struct;
typedef rs_scheme_struct rs_scheme_t[1];

void rs_scheme_init(rs_scheme_t s);
void rs_scheme_clear(rs_scheme_t s);

/* Builds the lambda-matrix (or the char polynomial) of an equations model
 * (rs_model_lower), all parameters symbolic.  Errors name file:line:col. */
int rs_scheme_build(rs_scheme_t s, const rs_model_t m, rs_error_t err);

/* Evaluates an expression without unknowns (used for `char`, `expect`,
 * conditions): result num/den with den a polynomial in the parameters only,
 * den != 0.  Names are the case's params and lets and the scheme's unknowns
 * (s built from c's model).  allow_lambda: 0 parameters only, 1 lambda
 * allowed, 2 z allowed (stored in lambda's variable slot, for `expect
 * bilinear`). */
int rs_scheme_eval_poly(fmpq_mpoly_t num, fmpq_mpoly_t den, const rs_scheme_t s,
                        const rs_case_t c, const rs_expr_t *e, int allow_lambda,
                        rs_error_t err);

/* The same over Q(i): the name i (not declared by the case) is the imaginary
 * unit; the value is (re + i im)/den with re, im, den over Q[s's variables]
 * (den without i; a division by a complex expression is an input error). */
int rs_scheme_eval_poly_cx(fmpq_mpoly_t re, fmpq_mpoly_t im, fmpq_mpoly_t den, const rs_scheme_t s,
                           const rs_case_t c, const rs_expr_t *e, int allow_lambda, rs_error_t err);

/* Lowest exponent of variable var in p (0 for p = 0): the power of lambda a
 * row or a polynomial can be divided by.  For an fmpq_mpoly pass its zpoly
 * and ctx->zctx (same monomials). */
slong rs_scheme_min_degree(const fmpz_mpoly_t p, slong var, const fmpz_mpoly_ctx_t ctx);

/* dst = a copy of src (dst initialised; its old contents are cleared). */
void rs_scheme_copy(rs_scheme_t dst, const rs_scheme_t src);

/* Reduces p (in s's zctx) by sqrt(d)^2 = d when s->sqrt_d > 0: p becomes
 * p0 + sqrt(d) p1 with sqrt_var's degree at most 1 (nothing otherwise). */
void rs_scheme_reduce_sqrt(fmpz_mpoly_t p, const rs_scheme_t s);

/* Substitutes the rational value for variable var in every entry. */
void rs_scheme_substitute(rs_scheme_t s, slong var, const fmpq_t value);

/* The polynomial as a string in the scheme's variable names (malloc'd with
 * flint_malloc; free with flint_free). */
char *rs_scheme_poly_str(const fmpq_mpoly_t p, const rs_scheme_t s);
char *rs_scheme_zpoly_str(const fmpz_mpoly_t p, const rs_scheme_t s);

#ifdef __cplusplus
}
#endif
#endif
