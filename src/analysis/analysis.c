/* analysis.c -- running a case's analyses: the model built once, every
 * request parsed against the registry (registry.c) before the first runs,
 * then each run in order into the case's JSON document. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "util/polyfmt.h"

void rs_options_default(rs_options_t *opt)
{
    opt->max_prec = 65536;
    opt->default_digits = 30;
    opt->with_scheme = 0;
    opt->time_limit = RS_BUDGET_TIME_DEFAULT;
    opt->time_spent = 0;
    opt->memory_limit = rs_budget_memory_default();
    rs_sweep_options_default(&opt->sweep);
    opt->polytext = NULL;
}

/* The equations as written and the lambda-matrix (set values substituted),
 * for derivations. */
static json_t *scheme_json(rs_run_t *run)
{
    const rs_case_struct *c = run->c;
    rs_assign_t *a;
    slong n, i, j;
    rs_variant_t *v;
    json_t *o = json_object(), *eqs = json_array(), *lets = json_array(), *M = json_array();
    /* det = 0 at the set values (v->vanishes) still has its matrix to show */
    if (rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0), rs_run_variant(&v, run, a, n) != RS_OK && !v->vanishes) {
        rs_assign_free(a, n);
        json_decref(o); json_decref(eqs); json_decref(lets); json_decref(M);
        return NULL;
    }
    rs_assign_free(a, n);
    for (i = 0; i < run->m->neqs; i++) json_array_append_new(eqs, json_string(run->m->eqs[i].text ? run->m->eqs[i].text : ""));
    for (i = 0; i < c->nlets; i++) json_array_append_new(lets, json_string(c->lets[i].text ? c->lets[i].text : ""));
    for (i = 0; i < v->s->n; i++) {
        json_t *row = json_array();
        for (j = 0; j < v->s->n; j++) {
            char *str = rs_polyfmt_fmpq_mpoly(v->s->M + i * v->s->n + j, (const char **) v->s->vars, v->s->ctx);
            json_array_append_new(row, json_string(str));
            free(str);
        }
        json_array_append_new(M, row);
    }
    json_object_set_new(o, "equations", eqs);
    json_object_set_new(o, "lets", lets);
    json_object_set_new(o, "matrix", M);
    if (v->s->from_char) {
        char *str = rs_polyfmt_fmpq_mpoly(v->s->charpoly, (const char **) v->s->vars, v->s->ctx);
        json_object_set_new(o, "char", json_string(str));
        free(str);
    }
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "nonzero_assumptions", rs_json_nonzero(v->s));
    {
        json_t *as = json_array();
        for (i = 0; i < c->nassume; i++) json_array_append_new(as, json_string(c->assume[i].text));
        json_object_set_new(o, "assume", as);
    }
    return o;
}

static int check_assumptions(const rs_case_t c, const rs_model_t m, rs_error_t err)
{
    slong i, k;
    for (i = 0; i < c->nassume; i++)
        for (k = 0; k < c->assume[i].n; k++) {
            const rs_expr_t *u = rs_an_undeclared_name(c->assume[i].e[k], m);
            if (u != NULL)
                return rs_error_set_at(err, RS_ERR_INPUT, c->assume[i].loc.file ? c->assume[i].loc.file : c->path,
                                       u->line, u->col,
                                       "unknown name '%s' in an assume line (expected a declared param, unknown or let)",
                                       u->name);
        }
    return RS_OK;
}

/* a `param NAME complex` without a value (neither set nor --set) */
static int complex_unset(const rs_case_struct *c, slong k)
{
    slong j;
    if (!c->params[k].complex) return 0;
    for (j = 0; j < c->nsets; j++) if (strcmp(c->sets[j].name, c->params[k].name) == 0) return 0;
    for (j = 0; j < c->ncsets; j++) if (strcmp(c->csets[j].name, c->params[k].name) == 0) return 0;
    return 1;
}

static slong first_complex_unset(const rs_case_struct *c)
{
    slong k;
    for (k = 0; k < c->nparams; k++) if (complex_unset(c, k)) return k;
    return -1;
}

static int mentions(const rs_expr_t *e, const char *name)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, name) == 0) return 1;
    return mentions(e->a, name) || mentions(e->b, name);
}

/* Complex set values: only for an equations case, on a parameter that is
 * not an angle and that no assume line compares (a real is required
 * there).  The error is at the set value when it is in the file, else at
 * the place that requires a real. */
static int check_complex_sets(const rs_case_t c, const rs_model_t m, rs_error_t err)
{
    slong k, i, j;
    for (k = 0; k < c->ncsets; k++) {
        const rs_cset_t *x = c->csets + k;
        slong pi = rs_case_param_index(c, x->name);
        char *val = rs_complex_str(x->re, x->im);
        const char *file = x->loc.line > 0 ? x->loc.file : NULL;
        int r = RS_OK;
        if (m->kind != RS_MODEL_EQUATIONS) {
            if (file) r = rs_error_set_at(err, RS_ERR_INPUT, file, x->loc.line, x->loc.col, "'%s' is set to the "
                                          "complex value %s, but this case's model is numeric (real entries only): "
                                          "expected a real value", x->name, val);
            else r = rs_error_set(err, RS_ERR_INPUT, "--set %s=%s: this case's model is numeric (real entries "
                                  "only): expected a real value", x->name, val);
        } else if (pi >= 0 && c->params[pi].angle) {
            r = rs_error_set(err, RS_ERR_INPUT, "--set %s=%s: '%s' is an angle parameter (it ranges over every "
                             "angle)", x->name, val, x->name);
        }
        for (i = 0; i < c->nassume && r == RS_OK; i++)
            for (j = 0; j < c->assume[i].n && r == RS_OK; j++) {
                const rs_cond_t *a = c->assume + i;
                if (!mentions(a->e[j], x->name)) continue;
                if (file)
                    r = rs_error_set_at(err, RS_ERR_INPUT, file, x->loc.line, x->loc.col, "'%s' is set to the "
                                        "complex value %s, but the assume line at %s:%d:%d compares it (a real "
                                        "is required there)", x->name, val, a->loc.file ? a->loc.file : c->path,
                                        a->loc.line, a->loc.col);
                else
                    r = rs_error_set_at(err, RS_ERR_INPUT, a->loc.file ? a->loc.file : c->path, a->loc.line,
                                        a->loc.col, "expected a real '%s' in this assume line, but --set gives it "
                                        "the complex value %s", x->name, val);
            }
        free(val);
        if (r != RS_OK) return r;
    }
    /* a complex parameter is never compared */
    for (k = 0; k < c->nparams; k++) {
        if (!c->params[k].complex) continue;
        for (i = 0; i < c->nassume; i++)
            for (j = 0; j < c->assume[i].n; j++)
                if (mentions(c->assume[i].e[j], c->params[k].name))
                    return rs_error_set_at(err, RS_ERR_INPUT, c->assume[i].loc.file ? c->assume[i].loc.file : c->path,
                                           c->assume[i].loc.line, c->assume[i].loc.col, "expected real parameters in "
                                           "an assume line, found '%s', declared complex (param %s complex)",
                                           c->params[k].name, c->params[k].name);
    }
    return RS_OK;
}

/* The analyses that run over Q(i) at complex set values (an_complex.c),
 * and those that take an unset complex parameter as complex. */
static int check_complex_request(rs_run_t *run, const rs_an_req_t *req)
{
    static const char *const ok[] = {"charpoly", "bilinear", "routh", "hurwitz", "jury", "stability", "radius",
                                      "modes", "claim", "sweep", "region", "map", "simulate", "limit", "expect",
                                      "astability", NULL};
    const rs_cset_t *x = run->c->csets;
    const char *nm = req->def->name;
    char *val, msg[RS_ERROR_MSG_LEN];
    slong k;
    if (strcmp(nm, "expect") == 0 && req->u.expect.bilinear && rs_case_param_index(run->c, "z") >= 0)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "expect bilinear: z is the bilinear variable "
                            "and also the parameter z (param z complex): compare the charpoly instead%s", "");
    for (k = 0; k < run->c->nparams; k++) {
        const char *pn = run->c->params[k].name;
        if (!complex_unset(run->c, k)) continue;
        if (strcmp(nm, "charpoly") == 0 || strcmp(nm, "astability") == 0
            || (strcmp(nm, "expect") == 0 && !req->u.expect.bilinear)
            || ((strcmp(nm, "map") == 0 || strcmp(nm, "region") == 0) && rs_an_complex_map_is(req->rest)))
            continue;
        if (strcmp(nm, "region") == 0)
            snprintf(msg, sizeof msg, "region over the complex parameter '%s' (param %s complex): use region re(%s), "
                     "im(%s) (the stable set in the plane, exact), astability (its axis intervals and A-stability) or "
                     "map re(%s) A B N, im(%s) C D M (the plane, exact per point)", pn, pn, pn, pn, pn, pn);
        else
            snprintf(msg, sizeof msg, "'%s' takes its parameters as real, but '%s' is complex (param %s complex) and "
                     "has no value: set it (set %s = A + B*i), or use charpoly, astability or map re(%s) A B N, "
                     "im(%s) C D M", nm, pn, pn, pn, pn, pn);
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
    if (run->c->ncsets == 0) return RS_OK;
    if ((strcmp(nm, "map") == 0 || strcmp(nm, "region") == 0) && rs_an_complex_map_is(req->rest)) {
        for (k = 0; k < run->c->ncsets; k++)
            if (rs_an_complex_map_of(req->rest, run->c->csets[k].name)) {
                /* the plane's own parameter: its set value would be silently overridden */
                x = run->c->csets + k;
                val = rs_complex_str(x->re, x->im);
                snprintf(msg, sizeof msg, "'%s re(%s), im(%s)' covers the plane of %s, which has a set value (%s = %s): "
                         "remove that set value to map the plane", nm, x->name, x->name, x->name, x->name, val);
                free(val);
                return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
            }
        val = rs_complex_str(x->re, x->im);
        snprintf(msg, sizeof msg, "'%s re(NAME), im(NAME)' does not run at a complex set value (%s = %s): the plane "
                 "of a complex parameter is mapped without set values; over Q(i) recstab runs %s of real "
                 "parameters", nm, x->name, val, strcmp(nm, "map") == 0 ? "map N1 ..., N2 ..." : "region NAME");
        free(val);
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
    /* region N1, N2 of a model over Q(sqrt d): over Q(sqrt d)(i) (an_qd_cx2.c) */
    if (strcmp(nm, "region") == 0 && (req->u.region.forall || (req->u.region.twod && run->m->qd == NULL))) {
        val = rs_complex_str(x->re, x->im);
        snprintf(msg, sizeof msg, "'region %s' does not run at a complex set value (%s = %s): over Q(i) recstab "
                 "runs region NAME of one real parameter, the others set", req->u.region.forall ? "NAME for all"
                 : "N1, N2", x->name, val);
        free(val);
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
    for (k = 0; ok[k] != NULL; k++)
        if (strcmp(req->def->name, ok[k]) == 0) return RS_OK;
    val = rs_complex_str(x->re, x->im);
    snprintf(msg, sizeof msg, "'%s' does not run at a complex set value (%s = %s): over Q(i) recstab runs "
             "charpoly, bilinear, routh, hurwitz, jury, stability, radius, modes, sweep, map, simulate, limit, astability, "
             "claim and region NAME", req->def->name,
             x->name, val);
    free(val);
    return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
}

static void free_requests(rs_request_t *q, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        flint_free(q[i].text);
        flint_free(q[i].loc.file);
    }
    free(q);
}

/* The analyses of a case without `analyse`, `expect` or `claim` lines:
 * charpoly and stability when p depends on no unset parameter; else
 * charpoly, hurwitz and, with one free parameter, its region.  Numeric
 * cases (exp/sin recurrences, exact integration): stability.  An
 * identically zero determinant is the usual error. */
static int default_requests(rs_run_t *run, rs_request_t **out, slong *nout)
{
    const rs_case_struct *c = run->c;
    const rs_loc_t *at = run->m->neqs > 0 ? &run->m->eqs[0].loc : c->charexpr != NULL ? &c->charloc : NULL;
    const char *names[3];
    char region[80 + RS_CASE_MAX_NAMES];
    slong n = 0, i, nfree = 0, last = -1, cpar;
    rs_variant_t *v;
    int r;
    *out = NULL;
    *nout = 0;
    if (run->m->kind != RS_MODEL_EQUATIONS) {
        names[n++] = "stability";
    } else if (run->m->qd != NULL) {
        /* over Q(sqrt d) (an_qd.c): its polynomial, the point when set, else the test
         * equation's region */
        names[n++] = "charpoly";
        if (c->nsets + c->ncsets > 0) names[n++] = "stability";
        else if (rs_an_qd_test_equation(c)) names[n++] = "astability";
    } else if (c->ncsets > 0) {
        /* complex set values: the polynomial and its verdict over Q(i) */
        names[n++] = "charpoly";
        names[n++] = "stability";
    } else if ((cpar = first_complex_unset(c)) >= 0) {
        /* a complex parameter without a value: its stability region */
        names[n++] = "charpoly";
        snprintf(region, sizeof region, "astability %s", c->params[cpar].name);
        names[n++] = region;
    } else {
        r = rs_run_numeric_variant(run, &v);
        if (r != RS_OK && v != NULL && v->vanishes) {
            /* p = 0 at the set values: stability says singular and why */
            rs_error_init(run->err);
            names[n++] = "stability";
            goto build;
        }
        if (r != RS_OK) return r;
        for (i = 0; i < v->s->nvars; i++)
            if (i != v->s->lambda_var && fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) > 0) {
                nfree++;
                last = i;
            }
        names[n++] = "charpoly";
        if (nfree == 0) {
            names[n++] = "stability";
        } else {
            names[n++] = "hurwitz";
            if (nfree == 1) {
                snprintf(region, sizeof region, "region %s", v->s->vars[last]);
                names[n++] = region;
            }
        }
    }
build:
    *out = calloc((size_t) n, sizeof(rs_request_t));
    for (i = 0; i < n; i++) {
        (*out)[i].text = rs_strdup(names[i]);
        (*out)[i].loc.file = rs_strdup(at != NULL && at->file != NULL ? at->file : c->path);
        (*out)[i].loc.line = at != NULL ? at->line : 1;
        (*out)[i].loc.col = at != NULL ? at->col : 1;
    }
    *nout = n;
    return RS_OK;
}

/* Parses every request against the registry (*out: nq typed requests) before
 * any runs: the first bad one is the error. */
static int parse_requests(rs_an_req_t **out, rs_run_t *run, const rs_request_t *q, slong nq)
{
    slong i;
    int r = RS_OK;
    *out = calloc((size_t) nq + 1, sizeof(rs_an_req_t));
    for (i = 0; i < nq && r == RS_OK; i++) {
        r = rs_an_req_parse(*out + i, run, q + i);
        if (r == RS_OK) r = check_complex_request(run, *out + i);
    }
    return r;
}

static void clear_requests(rs_an_req_t *req, slong n)
{
    slong i;
    for (i = 0; req != NULL && i < n; i++) rs_an_req_clear(req + i);
    free(req);
}

/* Runs the parsed requests in order, each checked against the budget;
 * `relocate`: a limit error without a place is put at its request (the
 * case's own requests, not the defaults). */
static int run_requests(rs_run_t *run, const rs_an_req_t *req, slong n, int relocate)
{
    slong i;
    int r = RS_OK;
    for (i = 0; i < n && r == RS_OK; i++) {
        r = rs_an_req_run(run, req + i);
        /* a loop stopped by the budget may have ended in another error or in
         * a partial result: the budget's message is the one to report, at
         * the request that ran out */
        if (rs_budget_exceeded()) r = rs_budget_error(run->err);
        if (relocate && r == RS_ERR_LIMIT && run->err->line == 0) {
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "%s", run->err->msg);
            r = rs_req_error(run, req[i].q, req[i].q->text, r, "%s", msg);
        }
    }
    return r;
}

static void run_clear(rs_run_t *run)
{
    slong i;
    for (i = 0; i < run->nvariants; i++) rs_variant_free(run->variants[i]);
    free(run->variants);
    rs_scheme_clear(run->sym);
    json_decref(run->results);
}

/* The case's document around the results (takes run->results). */
static json_t *case_doc(rs_run_t *run, const rs_request_t *defaults, slong ndefaults)
{
    const rs_case_struct *c = run->c;
    json_t *d = json_object(), *arr;
    slong i;
    char *shown = rs_utf8_escape(c->path);   /* json_string refuses invalid UTF-8 */
    json_object_set_new(d, "case", json_string(shown));
    flint_free(shown);
    json_object_set_new(d, "title", c->title ? json_string(c->title) : json_null());
    if (c->nlabels > 0) {
        json_t *lab = json_object();
        for (i = 0; i < c->nlabels; i++) json_object_set_new(lab, c->label_names[i], json_string(c->label_texts[i]));
        json_object_set_new(d, "labels", lab);
    }
    arr = json_array();
    for (i = 0; i < c->nparams; i++) json_array_append_new(arr, json_string(c->params[i].name));
    json_object_set_new(d, "params", arr);
    arr = json_array();
    for (i = 0; i < run->m->nunknowns; i++) json_array_append_new(arr, json_string(run->m->unknowns[i].name));
    json_object_set_new(d, "unknowns", arr);
    json_object_set_new(d, "set", rs_json_sets(c));
    if (ndefaults > 0) {
        arr = json_array();
        for (i = 0; i < ndefaults; i++) json_array_append_new(arr, json_string(defaults[i].text));
        json_object_set_new(d, "default_analyses", arr);
    }
    /* qd: the scheme has sqrt(d) as a variable (an_qd.c prints p over Q(sqrt d)) */
    if (run->opt->with_scheme && run->m->kind == RS_MODEL_EQUATIONS && run->m->qd == NULL) {
        json_t *sc = scheme_json(run);
        if (sc == NULL) {
            json_decref(d);
            return NULL;
        }
        json_object_set_new(d, "scheme", sc);
    }
    json_object_set_new(d, "results", run->results);
    run->results = NULL;
    return d;
}

int rs_analysis_run(json_t **doc, int *outcome, const rs_case_t c,
                    const rs_options_t *opt, rs_error_t err)
{
    rs_run_t run;
    slong ndefaults = 0, nreq = 0;
    rs_request_t *defaults = NULL;
    rs_model_t m;
    rs_an_req_t *req = NULL;
    int r = RS_OK;
    memset(&run, 0, sizeof run);
    rs_model_init(m);
    run.c = c;
    run.m = m;
    run.opt = opt;
    run.err = err;
    run.results = json_array();
    run.deg_lower = -1;
    run.deg_exact = -1;
    *doc = NULL;
    *outcome = RS_OUTCOME_OK;
    rs_budget_start(opt->time_limit, opt->time_spent, opt->memory_limit);
    /* an error in the equations must surface even when no analysis asks */
    rs_scheme_init(run.sym);
    r = rs_model_lower(m, c, err);
    if (r == RS_OK) r = check_assumptions(c, m, err);
    if (r == RS_OK) r = check_complex_sets(c, m, err);
    if (r == RS_OK && m->kind == RS_MODEL_EQUATIONS) {
        r = rs_scheme_build(run.sym, m, err);
        run.have_sym = (r == RS_OK);
    }
    if (r == RS_OK && c->nrequests == 0) r = default_requests(&run, &defaults, &ndefaults);
    if (r == RS_OK) {
        nreq = c->nrequests > 0 ? c->nrequests : ndefaults;
        r = parse_requests(&req, &run, c->nrequests > 0 ? c->requests : defaults, nreq);
    }
    if (r == RS_OK) r = run_requests(&run, req, nreq, c->nrequests > 0);
    if (r == RS_OK && rs_budget_exceeded()) r = rs_budget_error(err);
    rs_budget_stop();
    clear_requests(req, nreq);
    if (r == RS_OK) {
        *doc = case_doc(&run, defaults, ndefaults);
        if (*doc == NULL) r = err->code ? err->code : RS_ERR_INTERNAL;
    }
    free_requests(defaults, ndefaults);
    if (r == RS_OK) *outcome = run.outcome;
    run_clear(&run);
    rs_model_clear(m);
    return r;
}
