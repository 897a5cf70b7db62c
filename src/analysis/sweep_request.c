/* sweep_request.c -- the sweep and map requests parsed into
 * rs_sweep_request_t (sweep_impl.h), for every model kind. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/sweep_impl.h"

#define SW_MAX_TOKENS 32

const char *const rs_sweep_of_names[3] = {"radius", "stability", "modes"};

typedef struct { const char *s; size_t n; } tok_t;

/* Splits at white space, ',' is a token of its own; stops at the first word
 * containing '=' (options), returned in *opts.  The words NAME=VALUE after
 * the word `at` (separated by ',' or blanks; h= and reference= are options)
 * go to at[0 .. *nat) instead (at most max of them). */
static slong tokenize(tok_t *t, slong max, const char *text, const char **opts, tok_t *at, slong *nat)
{
    slong n = 0;
    const char *p = text;
    int in_at = 0;
    *opts = NULL;
    *nat = 0;
    for (;;) {
        size_t len;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\0') break;
        if (*p == ',') len = 1;
        else {
            len = strcspn(p, " \t,");
            if (memchr(p, '=', len) != NULL) {
                int option = (strncmp(p, "h=", 2) == 0 || strncmp(p, "reference=", 10) == 0);
                if (!in_at || option) { *opts = p; break; }
                if (*nat < max) { at[*nat].s = p; at[*nat].n = len; }
                (*nat)++;
                p += len;
                continue;
            }
        }
        if (in_at && len == 1 && *p == ',') { p++; continue; }
        in_at = (len == 2 && strncmp(p, "at", 2) == 0);
        if (in_at) { p += len; continue; }
        if (n < max) { t[n].s = p; t[n].n = len; }
        n++;
        p += len;
    }
    return n;
}

/* the NAME=VALUE words of `at` into R->at (every name a parameter other
 * than the sweep's, each once) */
static int parse_at(rs_sweep_request_t *R, rs_run_t *run, const rs_request_t *q, const tok_t *w, slong nw)
{
    slong k, j;
    if (nw > SW_MAX_TOKENS) nw = SW_MAX_TOKENS;
    R->at = calloc((size_t) nw + 1, sizeof(rs_assign_t));
    for (k = 0; k < nw; k++) {
        const char *eq = memchr(w[k].s, '=', w[k].n);
        char name[80], num[200];
        size_t nl = (size_t) (eq - w[k].s), vl = w[k].n - nl - 1;
        slong idx;
        rs_error_t e2;
        if (nl >= sizeof name || vl >= sizeof num || nl == 0)
            return rs_req_error(run, q, w[k].s, RS_ERR_INPUT, "expected NAME=VALUE after 'at', found '%s'", w[k].s);
        memcpy(name, w[k].s, nl);
        name[nl] = '\0';
        memcpy(num, eq + 1, vl);
        num[vl] = '\0';
        idx = rs_case_param_index(run->c, name);
        if (idx < 0) return rs_req_error(run, q, w[k].s, RS_ERR_INPUT, "'%s' is not a parameter", w[k].s);
        for (j = 0; j < R->naxes; j++)
            if (R->axis[j].var == idx)
                return rs_req_error(run, q, w[k].s, RS_ERR_INPUT, "the swept parameter is also given a value at '%s'", w[k].s);
        for (j = 0; j < R->nat; j++)
            if (R->at[j].var == idx)
                return rs_req_error(run, q, w[k].s, RS_ERR_INPUT, "a second value for the same parameter at '%s'", w[k].s);
        R->at[R->nat].name = run->c->params[idx].name;
        R->at[R->nat].var = idx;
        fmpq_init(R->at[R->nat].value);
        R->nat++;
        rs_error_init(e2);
        if (rs_expr_parse_number(R->at[R->nat - 1].value, num, e2) != RS_OK)
            return rs_req_error(run, q, eq + 1, RS_ERR_INPUT, "expected a number: %s", e2->msg);
    }
    return RS_OK;
}

static int tok_is(const tok_t *t, const char *w)
{
    return strlen(w) == t->n && strncmp(t->s, w, t->n) == 0;
}

static int tok_number(fmpq_t q, const tok_t *t)
{
    char buf[128];
    rs_error_t e;
    if (t->n >= sizeof buf) return RS_ERR_INPUT;
    memcpy(buf, t->s, t->n);
    buf[t->n] = '\0';
    rs_error_init(e);
    return rs_expr_parse_number(q, buf, e);
}

static int tok_long(slong *out, const tok_t *t)
{
    char buf[32], *end;
    long x;
    if (t->n == 0 || t->n >= sizeof buf) return 0;
    memcpy(buf, t->s, t->n);
    buf[t->n] = '\0';
    errno = 0;
    x = strtol(buf, &end, 10);
    if (*end != '\0') return 0;
    if (errno == ERANGE) x = (x > 0) ? WORD_MAX : WORD_MIN;   /* clamped: a limit error, not a wrap */
    *out = x;
    return 1;
}

static char *tok_str(const tok_t *t)
{
    char *s = malloc(t->n + 1);
    memcpy(s, t->s, t->n);
    s[t->n] = '\0';
    return s;
}

static int tok_error(rs_run_t *run, const rs_request_t *q, const tok_t *t, const char *fmt)
{
    char *w = tok_str(t);
    int r = rs_req_error(run, q, t->s, RS_ERR_INPUT, fmt, w);
    free(w);
    return r;
}

static int parse_of(rs_run_t *run, const rs_request_t *q, const tok_t *t, slong nt, slong *pos, int *kind,
                    int allow_modes)
{
    *kind = RS_SWEEP_OF_RADIUS;
    if (*pos < nt && tok_is(t + *pos, "of")) {
        if (*pos + 1 >= nt)
            return rs_req_error(run, q, t[*pos].s, RS_ERR_INPUT, "expected radius, %s after 'of'",
                                allow_modes ? "modes or stability" : "or stability");
        if (tok_is(t + *pos + 1, "radius")) *kind = RS_SWEEP_OF_RADIUS;
        else if (tok_is(t + *pos + 1, "stability")) *kind = RS_SWEEP_OF_STABILITY;
        else if (allow_modes && tok_is(t + *pos + 1, "modes")) *kind = RS_SWEEP_OF_MODES;
        else return tok_error(run, q, t + *pos + 1, allow_modes
                              ? "expected radius, modes or stability after 'of', found '%s'"
                              : "expected radius or stability after 'of', found '%s'");
        *pos += 2;
    }
    if (*pos < nt) return tok_error(run, q, t + *pos, "unexpected '%s' at the end of the request");
    return RS_OK;
}

/* The keys of the `of modes` options (h=, reference=; reference required):
 * checked here, before anything runs; the values are expressions, evaluated
 * per point by the run (sweep_poly.c). */
static int check_modes_keys(rs_run_t *run, const rs_request_t *q, const char *opts)
{
    const char *p = opts;
    int have_ref = 0;
    while (p != NULL && *p) {
        size_t len;
        const char *eq;
        while (*p == ' ' || *p == '\t') p++;
        len = strcspn(p, " \t");
        eq = memchr(p, '=', len);
        if (eq != NULL) {
            if (eq - p == 9 && strncmp(p, "reference", 9) == 0) have_ref = 1;
            else if (!(eq - p == 1 && p[0] == 'h'))
                return rs_req_error(run, q, p, RS_ERR_INPUT, "expected an option (h=, reference=), found '%s'", p);
        }
        p += len;
    }
    if (!have_ref)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT,
                            "sweep ... of modes needs reference=EXPR (the exact frequency of the mode, e.g. "
                            "reference=w with h=1 for a scaled w = omega*h), found '%s'", q->text);
    return RS_OK;
}

void rs_sweep_request_init(rs_sweep_request_t *r)
{
    slong ax;
    memset(r, 0, sizeof *r);
    for (ax = 0; ax < 2; ax++) {
        fmpq_init(r->axis[ax].from);
        fmpq_init(r->axis[ax].to);
        r->axis[ax].var = -1;
    }
}

void rs_sweep_request_clear(rs_sweep_request_t *r)
{
    slong ax;
    if (r->at != NULL) rs_assign_free(r->at, r->nat);
    r->at = NULL;
    r->nat = 0;
    for (ax = 0; ax < 2; ax++) {
        fmpq_clear(r->axis[ax].from);
        fmpq_clear(r->axis[ax].to);
    }
}

/* the parameter named by token t into ax */
static int parse_param(rs_sweep_axis_t *ax, rs_run_t *run, const rs_request_t *q, const tok_t *t)
{
    ax->at = t->s;
    if (t->n >= sizeof ax->name) return tok_error(run, q, t, "'%s' is not a parameter");
    memcpy(ax->name, t->s, t->n);
    ax->name[t->n] = '\0';
    ax->var = rs_case_param_index(run->c, ax->name);
    if (ax->var < 0) return tok_error(run, q, t, "'%s' is not a parameter");
    return RS_OK;
}

int rs_sweep_request_parse(rs_sweep_request_t *R, rs_run_t *run, const rs_request_t *q, const char *rest)
{
    tok_t t[SW_MAX_TOKENS], at[SW_MAX_TOKENS];
    const char *opts;
    slong nat, nt = tokenize(t, SW_MAX_TOKENS, rest, &opts, at, &nat), pos;
    rs_sweep_axis_t *ax = R->axis;
    int r;
    if (nt > SW_MAX_TOKENS) nt = SW_MAX_TOKENS;
    R->kind = RS_SWEEP_KIND_SWEEP;
    R->naxes = 1;
    if (nt < 7 || !tok_is(t + 1, "from") || !tok_is(t + 3, "to") || !tok_is(t + 5, "steps"))
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected 'sweep NAME from A to B steps K [log] [of radius|modes|stability] "
                            "[at NAME=VALUE, ...]', found '%s'", rest);
    r = parse_param(ax, run, q, t);
    if (r == RS_OK && nat > 0 && run->m->kind == RS_MODEL_COSIM)
        r = rs_req_error(run, q, at[0].s, RS_ERR_INPUT, "'at' is for sweeps of equations; for this co-simulation "
                         "give the values with set or --set, found '%s'", at[0].s);
    if (r == RS_OK) r = parse_at(R, run, q, at, nat);
    if (r != RS_OK) return r;
    ax->from_at = t[2].s;
    if (tok_number(ax->from, t + 2) != RS_OK) return tok_error(run, q, t + 2, "expected a number after 'from', found '%s'");
    if (tok_number(ax->to, t + 4) != RS_OK) return tok_error(run, q, t + 4, "expected a number after 'to', found '%s'");
    if (!tok_long(&ax->count, t + 6) || ax->count < 1)
        return tok_error(run, q, t + 6, "expected a positive integer number of steps, found '%s'");
    pos = 7;
    if (pos < nt && tok_is(t + pos, "log")) { R->logsp = 1; pos++; }
    r = parse_of(run, q, t, nt, &pos, &R->of, 1);
    if (r == RS_OK && opts != NULL && R->of != RS_SWEEP_OF_MODES)
        r = rs_req_error(run, q, opts, RS_ERR_INPUT, "options are only for 'of modes', found '%s'", opts);
    R->opts = opts;
    if (r == RS_OK && R->of == RS_SWEEP_OF_MODES) r = check_modes_keys(run, q, opts);
    if (r == RS_OK && R->logsp && (fmpq_sgn(ax->from) <= 0 || fmpq_sgn(ax->to) <= 0))
        r = rs_req_error(run, q, ax->from_at, RS_ERR_INPUT, "log spacing needs A > 0 and B > 0, found '%s'", ax->from_at);
    if (r == RS_OK && ax->count >= run->opt->sweep.max_points)
        r = rs_sweep_limit_error(run, q, (double) ax->count + 1.0, "the sweep");
    return r;
}

int rs_map_request_parse(rs_sweep_request_t *R, rs_run_t *run, const rs_request_t *q, const char *rest)
{
    tok_t t[SW_MAX_TOKENS], at[SW_MAX_TOKENS];
    const char *opts;
    slong nat, nt = tokenize(t, SW_MAX_TOKENS, rest, &opts, at, &nat), pos, ax, max = run->opt->sweep.max_points;
    rs_sweep_axis_t *X = R->axis;
    int r = RS_OK;
    if (nt > SW_MAX_TOKENS) nt = SW_MAX_TOKENS;
    R->kind = RS_SWEEP_KIND_MAP;
    R->naxes = 2;
    if (opts != NULL) return rs_req_error(run, q, opts, RS_ERR_INPUT, "unexpected option '%s' for map", opts);
    if (nat > 0) return rs_req_error(run, q, at[0].s, RS_ERR_INPUT, "map takes no 'at' (give the values with set or --set), found '%s'", at[0].s);
    if (nt < 9 || !tok_is(t + 4, ","))
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected 'map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]', found '%s'", rest);
    for (ax = 0; ax < 2 && r == RS_OK; ax++) {
        const tok_t *u = t + 5 * ax;
        r = parse_param(X + ax, run, q, u);
        X[ax].from_at = u[1].s;
        if (r != RS_OK) break;
        else if (tok_number(X[ax].from, u + 1) != RS_OK) r = tok_error(run, q, u + 1, "expected a number (the first value), found '%s'");
        else if (tok_number(X[ax].to, u + 2) != RS_OK) r = tok_error(run, q, u + 2, "expected a number (the last value), found '%s'");
        else if (!tok_long(&X[ax].count, u + 3) || X[ax].count < 1)
            r = tok_error(run, q, u + 3, "expected a positive integer number of points, found '%s'");
    }
    if (r == RS_OK && X[0].var == X[1].var) r = tok_error(run, q, t + 5, "map needs two different parameters, found '%s' twice");
    pos = 9;
    if (r == RS_OK) r = parse_of(run, q, t, nt, &pos, &R->of, 0);
    /* K1 * K2 compared by division: the product may overflow */
    if (r == RS_OK && (X[0].count > max || X[1].count > max || X[0].count > max / X[1].count)) {
        char desc[200];
        snprintf(desc, sizeof desc, "the map (%ld x %ld)", (long) X[0].count, (long) X[1].count);
        r = rs_sweep_limit_error(run, q, (double) X[0].count * (double) X[1].count, desc);
    }
    return r;
}
