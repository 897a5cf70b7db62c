/* analysis/registry.h -- the registry of analyses: for each one its name,
 * the model kinds it applies to, its option grammar, the parse function that
 * turns the request text into a typed request, and the run function taking
 * that request.  rs_analysis_run parses and checks every request of a case
 * against it before the first analysis runs.  Private: not installed. */
#ifndef RECSTAB_ANALYSIS_REGISTRY_H
#define RECSTAB_ANALYSIS_REGISTRY_H

#include <flint/fmpq_poly.h>
#include "analysis/impl.h"
#include "recstab/model.h"
#include "recstab/cosim.h"

/* A set of the model kinds of model.h (RS_MODEL_EQUATIONS: difference
 * equations, `char`, polynomial recurrences; RS_MODEL_RECURRENCE: matrix
 * recurrences with exp, sin, ... entries, numeric only; RS_MODEL_COSIM:
 * exactly integrated subsystems): one bit per kind. */
#define RS_AN_KINDS(k) (1 << (k))

/* Types of a `key=value` option. */
typedef enum {
    RS_OPT_INTEGER,   /* a decimal integer in [lo, hi] */
    RS_OPT_ENUM,      /* one of choices[] */
    RS_OPT_EXPR,      /* an expression (evaluated by the analysis) */
    RS_OPT_EXPRS      /* expressions separated by ',' */
} rs_opt_type_t;

#define RS_AN_MAX_OPTS 4
#define RS_SIMULATE_MAX_STEPS 10000000   /* steps= of simulate */

typedef struct {
    const char *key;
    rs_opt_type_t type;
    slong lo, hi;                 /* RS_OPT_INTEGER: the range */
    const char *const *choices;   /* RS_OPT_ENUM: NULL-terminated, the first is the default */
    const char *meta;             /* the value's placeholder in the synopsis (N, EXPR, ...) */
    const char *def;              /* the default, as shown by --list-analyses */
} rs_opt_spec_t;

/* One parsed option: at == NULL when absent. */
typedef struct {
    const char *at;       /* the key in the request text */
    const char *val;      /* its value */
    slong num;            /* INTEGER: the value; ENUM: index into choices */
    slong nlist;          /* EXPRS: the expressions' starts */
    const char **list;
} rs_optval_t;

typedef struct rs_an_def_struct rs_an_def_t;

/* A request parsed against its registry entry.  Text pointers point into
 * q->text (error places stay exact). */
typedef struct {
    const rs_an_def_t *def;
    const rs_request_t *q;
    const char *rest;                 /* the text after the analysis name */
    rs_optval_t opt[RS_AN_MAX_OPTS];  /* by the order of def->opts */
    union {
        struct { int bilinear; rs_expr_t *poly; } expect;
        struct { slong param; rs_assign_t *at; slong nat;
                 int forall; slong *qv; slong nq;
                 int twod; slong param2; } region;   /* forall: `for all [P, ...]`; twod: `region N1, N2` */
        struct { slong param; int to_inf; } limit;
        struct { slong param; } astab;               /* astability: the parameter standing for z */
        struct { int kind; void *dnf; } claim;       /* dnf: an_claim.c's claim_dnf_t */
        void *sweep;                                 /* sweep, map: rs_sweep_request_t (sweep_impl.h) */
        void *cosim;                                 /* region, claim of exact integration (an_cosim_region.c) */
    } u;
} rs_an_req_t;

typedef int (*rs_an_parse_fn)(rs_an_req_t *req, rs_run_t *run);
typedef int (*rs_an_run_fn)(rs_run_t *run, const rs_an_req_t *req);
typedef void (*rs_an_clear_fn)(rs_an_req_t *req);

/* Entry flags. */
enum {
    RS_AN_NOT_IN_P = 1   /* numeric: lists the parameters given placeholders ("not_in_p") */
};

struct rs_an_def_struct {
    const char *name;
    const char *const *aliases;   /* other names (NULL-terminated) or NULL */
    int kinds;                    /* the RS_AN_KINDS(RS_MODEL_*) it applies to, or-ed */
    const char *words;            /* grammar of the words before the options ("NAME -> 0|inf"),
                                     "" when there are none */
    const rs_opt_spec_t *opts;    /* `key=value` options (key NULL ends), or NULL */
    const char *summary;          /* one line: what it gives */
    rs_an_parse_fn parse;         /* the words and options (NULL: the `key=value` options only) */
    rs_an_clear_fn clear;         /* frees what parse put in the request's union, or NULL */
    rs_an_run_fn run;
    int flags;
};

/* The registry, in the order of the error lists (NULL name ends it). */
extern const rs_an_def_t rs_an_registry[];

/* Parses q against the registry for the case's model kind: unknown
 * analysis, wrong kind, unknown option, value out of range are input errors
 * at the offending word.  Clear with rs_an_req_clear (also after an error). */
/* The key=value options of req's entry in t (for entries with their own
 * parse function: the text after their grammar), into req->opt. */
int rs_an_opts_parse(rs_an_req_t *req, rs_run_t *run, const char *t);
int rs_an_req_parse(rs_an_req_t *req, rs_run_t *run, const rs_request_t *q);
void rs_an_req_clear(rs_an_req_t *req);
/* Runs a parsed request. */
int rs_an_req_run(rs_run_t *run, const rs_an_req_t *req);

/* The value of option `key` of the request (run.c; absent: at == NULL). */
const rs_optval_t *rs_an_opt(const rs_an_req_t *req, const char *key);
/* The choice of an RS_OPT_ENUM option (its default when absent). */
const char *rs_an_opt_choice(const rs_an_req_t *req, const char *key);

/* (run.c) The first name of e the model does not declare (param, unknown,
 * let or reserved), or NULL; rs_an_check_names: that as an input error at the
 * name (a typo would otherwise surface late, or without a place). */
const rs_expr_t *rs_an_undeclared_name(const rs_expr_t *e, const rs_model_t m);
int rs_an_check_names(rs_run_t *run, const rs_request_t *q, const rs_expr_t *e);

/* Parse functions of the analyses with words (in their files). */
int rs_an_region_parse(rs_an_req_t *req, rs_run_t *run);
void rs_an_region_req_clear(rs_an_req_t *req);
int rs_an_limit_parse(rs_an_req_t *req, rs_run_t *run);
int rs_an_astability_parse(rs_an_req_t *req, rs_run_t *run);
int rs_an_claim_parse(rs_an_req_t *req, rs_run_t *run);
void rs_an_claim_req_clear(rs_an_req_t *req);
int rs_an_expect_parse(rs_an_req_t *req, rs_run_t *run);
void rs_an_expect_req_clear(rs_an_req_t *req);

/* Run functions (one file each in src/analysis/: an_NAME.c; sweep and map
 * in analysis_sweep.c and analysis_cosim.c). */
int rs_an_charpoly(rs_run_t *run, const rs_an_req_t *req);
int rs_an_expect(rs_run_t *run, const rs_an_req_t *req);
int rs_an_bilinear(rs_run_t *run, const rs_an_req_t *req);
int rs_an_routh(rs_run_t *run, const rs_an_req_t *req);
int rs_an_hurwitz(rs_run_t *run, const rs_an_req_t *req);
int rs_an_jury(rs_run_t *run, const rs_an_req_t *req);
int rs_an_stability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_region(rs_run_t *run, const rs_an_req_t *req);
int rs_an_limit(rs_run_t *run, const rs_an_req_t *req);
int rs_an_astability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_claim(rs_run_t *run, const rs_an_req_t *req);
/* an_claim.c: prove or refute a claim of kind (0 stable, 1 bounded) on the
 * set b; region NAME for all uses it cell by cell (search 0: prove, then
 * search if not proved; 1: both; 2: search first, prove if nothing found) */
int rs_an_claim_decide(int *verdict, json_t **ev, rs_run_t *run, int kind, const rs_bound_t *b, int search);
/* an_region_forall.c: the critical values of parameter tv for `for all`
 * over the variables qv[0..nq-1] (univariate in tv, appended to *out); the
 * status of one cell at tv = t decided for all of them */
int rs_an_forall_critical(fmpz_poly_struct **out, slong *nout, rs_run_t *run, const rs_variant_t *v, slong tv,
                          const slong *qv, slong nq, const rs_bound_t *b, int *full);
/* 1 when q's leading coefficient (lambda = -1 a root where it vanishes) has
 * no zero on the domain b with tv = t */
int rs_an_forall_lead_nonzero(rs_run_t *run, const rs_variant_t *v, slong tv, const fmpq_t t, const rs_bound_t *b);
int rs_an_forall_cell(rs_status_t *st, int *decided, json_t **ev, rs_run_t *run, slong tv, const fmpq_t t,
                      int search_first);
int rs_an_forall_prove(int *proved, json_t **ev, rs_run_t *run, slong tv, const fmpq_t lo, const fmpq_t hi, int kind);
void rs_an_forall_subst(fmpz_mpoly_t out, const fmpz_mpoly_t f, slong u, const fmpq_t x, const fmpz_mpoly_ctx_t ctx);
int rs_an_radius(rs_run_t *run, const rs_an_req_t *req);

/* an_complex.c: the analyses at complex set values (run->c->ncsets > 0),
 * over Q(i); rs_an_complex_char_check: a `char` line with i at real values,
 * its complex verdict beside the real one (o gets "complex_check"). */
int rs_an_complex_mode(const rs_run_t *run);
char *rs_complex_str(const fmpq_t re, const fmpq_t im);
int rs_an_complex_charpoly(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_bilinear(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_routh(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_stability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_radius(rs_run_t *run, const rs_an_req_t *req);
/* an_complex_conds.c: hurwitz (Bilharz) and jury (Schur-Cohn) conditions
 * of p over Q(i)[real params], at complex set values or from a char line
 * with i; _applies: the run's p has complex coefficients */
int rs_an_complex_conds_applies(rs_run_t *run);
int rs_an_complex_hurwitz(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_jury(rs_run_t *run, const rs_an_req_t *req);
/* p over Q(i) with every parameter a number (an input error naming one still
 * free); *at the complex set values (a new JSON object) */
int rs_an_complex_point_poly(fmpq_poly_t pr, fmpq_poly_t pi, json_t **at, rs_variant_t **vp, rs_run_t *run,
                             const rs_an_req_t *req);
int rs_an_complex_char_check(rs_run_t *run, const rs_an_req_t *req, rs_status_t real_st, json_t *o);
/* a char line with i at real values: o's "roots" replaced by p's own (the
 * block form's radius is p conj(p)'s, the same moduli) */
int rs_an_complex_char_roots(rs_run_t *run, const rs_an_req_t *req, json_t *o, slong digits);
/* `map re(NAME) A B N, im(NAME) C D M [of stability]` (req->u.sweep holds its request) */
int rs_an_complex_map_is(const char *rest);
/* 1 when rest is the plane of parameter name: re(name), ... */
int rs_an_complex_map_of(const char *rest, const char *name);
int rs_an_complex_map_parse(rs_an_req_t *req, rs_run_t *run);
void rs_an_complex_map_clear(rs_an_req_t *req);
int rs_an_complex_region_parse(rs_an_req_t *req, rs_run_t *run);
int rs_an_complex_region(rs_run_t *run, const rs_an_req_t *req);
int rs_an_complex_map(rs_run_t *run, const rs_an_req_t *req);
int rs_an_modes(rs_run_t *run, const rs_an_req_t *req);
/* "h", "modes", "spurious", "note" of a modes element o from the certified
 * roots rr at time step h, references refs[0 .. nref) (an_modes.c) */
void rs_an_modes_json(json_t *o, const rs_radius_t rr, const arb_t h, const arb_t *refs, slong nref, slong prec,
                      slong digits);
/* modes of an exactly integrated co-simulation (analysis_cosim.c) */
int rs_an_cosim_modes(rs_run_t *run, const rs_an_req_t *req);
/* the run's co-simulation at the case's set values, from the forms lowered once */
int rs_run_cosim(rs_cosim_t cs, rs_run_t *run);
/* ... with names[i] = values[i] (i < n) overriding them */
int rs_run_cosim_at(rs_cosim_t cs, rs_run_t *run, const char *const *names, const fmpq *values, slong n);
/* region NAME from A to B [digits=N] and claim stable|bounded|unstable when A <= NAME <= B [and ...]
 * of exact integration (an_cosim_region.c): certified by Stein certificates over parameter boxes */
int rs_an_cosim_region_parse(rs_an_req_t *req, rs_run_t *run);
int rs_an_cosim_claim_parse(rs_an_req_t *req, rs_run_t *run);
void rs_an_cosim_box_req_clear(rs_an_req_t *req);
int rs_an_cosim_region(rs_run_t *run, const rs_an_req_t *req);
int rs_an_cosim_claim(rs_run_t *run, const rs_an_req_t *req);
int rs_an_simulate(rs_run_t *run, const rs_an_req_t *req);
/* radius and stability of numeric recurrences and co-simulations (an_radius.c) */
int rs_an_numeric_radius(rs_run_t *run, const rs_an_req_t *req);
int rs_an_numeric_stability(rs_run_t *run, const rs_an_req_t *req);

#endif
