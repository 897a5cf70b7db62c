/* registry.c -- the table of analyses and the parsing of requests against
 * it.  Every request of a case is parsed here before the first analysis
 * runs (rs_analysis_run), so a misspelled option after a long sweep is
 * reported at once; the names, grammars and model kinds printed by
 * `--list-analyses`, by --help and in the error lists all come from this
 * table (tests/cli/suite_cli.sh compares them with the README). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ctype.h>
#include <errno.h>
#include "analysis/registry.h"
#include "analysis/sweep_impl.h"
#include "analysis/an_qd.h"

/* ---- grammars ------------------------------------------------------------ */

static const char *const radius_methods[] = {"certified", "companion", "double", NULL};

static const rs_opt_spec_t radius_opts[] = {
    {"digits", RS_OPT_INTEGER, 1, RS_DIGITS_MAX, NULL, "N", "30"},
    {"method", RS_OPT_ENUM, 0, 0, radius_methods, NULL, "certified"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};
static const rs_opt_spec_t digits_opts[] = {
    {"digits", RS_OPT_INTEGER, 1, RS_DIGITS_MAX, NULL, "N", "30"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};
static const rs_opt_spec_t modes_opts[] = {
    {"reference", RS_OPT_EXPRS, 0, 0, NULL, "EXPR", "none"},
    {"h", RS_OPT_EXPR, 0, 0, NULL, "EXPR", "1"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};
/* exact integration: the one-step map spans the macro step H */
static const rs_opt_spec_t cosim_modes_opts[] = {
    {"reference", RS_OPT_EXPRS, 0, 0, NULL, "EXPR", "none"},
    {"h", RS_OPT_EXPR, 0, 0, NULL, "EXPR", "H"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};
/* exact integration: a transition's enclosure narrower than 10^-N */
static const rs_opt_spec_t cosim_region_opts[] = {
    {"digits", RS_OPT_INTEGER, 1, 60, NULL, "N", "15"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};
static const rs_opt_spec_t simulate_opts[] = {
    {"steps", RS_OPT_INTEGER, 1, RS_SIMULATE_MAX_STEPS, NULL, "N", "1000"},
    {"seed", RS_OPT_INTEGER, 0, 1000000000, NULL, "S", "1"},
    {"prec", RS_OPT_INTEGER, 32, 65536, NULL, "BITS", "128"},
    {NULL, 0, 0, 0, NULL, NULL, NULL}
};

/* sweep and map: the typed requests of the sweep/map engine (sweep_impl.h);
 * the same map grammar for the equations and for exact integration */
static int sweep_parse_as(rs_an_req_t *req, rs_run_t *run, int map)
{
    rs_sweep_request_t *r = malloc(sizeof *r);
    rs_sweep_request_init(r);
    req->u.sweep = r;
    return map ? rs_map_request_parse(r, run, req->q, req->rest) : rs_sweep_request_parse(r, run, req->q, req->rest);
}
static int sweep_parse(rs_an_req_t *req, rs_run_t *run) { return sweep_parse_as(req, run, 0); }
static void sweep_req_clear(rs_an_req_t *req)
{
    if (req->u.sweep == NULL) return;
    rs_sweep_request_clear((rs_sweep_request_t *) req->u.sweep);
    free(req->u.sweep);
}
static int map_parse(rs_an_req_t *req, rs_run_t *run) { return sweep_parse_as(req, run, 1); }
/* the equations' map: `map re(NAME) ..., im(NAME) ...` is the complex plane of
 * one parameter (an_complex.c), other maps the engine's */
static int eq_map_parse(rs_an_req_t *req, rs_run_t *run)
{
    return rs_an_complex_map_is(req->rest) ? rs_an_complex_map_parse(req, run) : map_parse(req, run);
}
static void eq_map_clear(rs_an_req_t *req)
{
    if (rs_an_complex_map_is(req->rest)) rs_an_complex_map_clear(req);
    else sweep_req_clear(req);
}

/* region re(NAME), im(NAME): the z-plane (an_complex.c); else region.c */
static int eq_region_parse(rs_an_req_t *req, rs_run_t *run)
{
    return rs_an_complex_map_is(req->rest) ? rs_an_complex_region_parse(req, run) : rs_an_region_parse(req, run);
}
static void eq_region_clear(rs_an_req_t *req)
{
    if (rs_an_complex_map_is(req->rest)) rs_an_complex_map_clear(req);
    else rs_an_region_req_clear(req);
}
static int run_eq_region(rs_run_t *run, const rs_an_req_t *req)
{
    return rs_an_complex_map_is(req->rest) ? rs_an_complex_region(run, req) : rs_an_region(run, req);
}

static int run_sweep(rs_run_t *run, const rs_an_req_t *req)
{
    return rs_an_sweep_run(run, req->q, (const rs_sweep_request_t *) req->u.sweep);
}
static int run_map(rs_run_t *run, const rs_an_req_t *req)
{
    if (run->m->qd != NULL) return rs_an_qd_map(run, req);   /* two real parameters over Q(sqrt d) */
    return rs_an_map_run(run, req->q, (const rs_sweep_request_t *) req->u.sweep);
}
static int run_eq_map(rs_run_t *run, const rs_an_req_t *req)
{
    return rs_an_complex_map_is(req->rest) ? rs_an_complex_map(run, req) : run_map(run, req);
}
static int run_cosim_map(rs_run_t *run, const rs_an_req_t *req)
{
    return rs_an_cosim_map_run(run, req->q, (const rs_sweep_request_t *) req->u.sweep);
}

#define EQ RS_AN_KINDS(RS_MODEL_EQUATIONS)
#define NUM (RS_AN_KINDS(RS_MODEL_RECURRENCE) | RS_AN_KINDS(RS_MODEL_COSIM))

/* The order is that of the error lists: the distinct names in order for
 * "expected an analysis (...)", and per model kind for "only ... apply". */
const rs_an_def_t rs_an_registry[] = {
    {"charpoly", NULL, EQ, "", NULL,
     "p(lambda) = det of the lambda-matrix, fraction-free; lambda^k and the rational content split off",
     NULL, NULL, rs_an_charpoly, 0},
    {"bilinear", NULL, EQ, "", NULL,
     "q(z) = (1-z)^n p((1+z)/(1-z)), degree drop, z = 0 multiplicity, p(1), p(-1)",
     NULL, NULL, rs_an_bilinear, 0},
    {"routh", NULL, EQ, "", NULL, "the exact Routh array of q, singular cases handled exactly and named",
     NULL, NULL, rs_an_routh, 0},
    {"hurwitz", NULL, EQ, "", NULL, "Hurwitz minors and the Lienard-Chipart conditions, factored over Q",
     NULL, NULL, rs_an_hurwitz, 0},
    {"jury", NULL, EQ, "", NULL, "Schur-Cohn on p(lambda) directly, cross-checked against Routh",
     NULL, NULL, rs_an_jury, 0},
    {"stability", NULL, EQ, "", NULL, "all parameters set: stable / marginal / unstable / singular with root counts",
     NULL, NULL, rs_an_stability, RS_AN_NOT_IN_P},
    {"region", NULL, EQ, "NAME [at P=V, ...] | NAME for all [P, ...] | NAME1, NAME2 [at P=V, ...] | re(NAME), im(NAME)",
     NULL, "the exact set of NAME values where the scheme is stable, marginal, unstable; re(NAME), im(NAME): the "
     "stable set in the complex plane of NAME", eq_region_parse, eq_region_clear, run_eq_region, 0},
    {"limit", NULL, EQ, "NAME -> 0|inf", NULL, "the limits of the roots with multiplicities",
     rs_an_limit_parse, NULL, rs_an_limit, 0},
    {"astability", NULL, EQ, "[NAME]", NULL,
     "NAME as z = h*lambda of y' = z y: real and imaginary intervals, A-stability, A(alpha), z -> inf",
     rs_an_astability_parse, NULL, rs_an_astability, 0},
    {"claim", NULL, EQ, "stable|bounded|unstable [when CONDITION [and|or ...]]", NULL,
     "proved (re-checked certificate), refuted (exact counterexample) or undecided",
     rs_an_claim_parse, rs_an_claim_req_clear, rs_an_claim, 0},
    {"radius", NULL, EQ, "", radius_opts, "the spectral radius as a certified interval, the roots as balls",
     NULL, NULL, rs_an_radius, RS_AN_NOT_IN_P},
    {"modes", NULL, EQ, "", modes_opts, "for each root: ln(lambda)/h, damping ratio, relative frequency error",
     NULL, NULL, rs_an_modes, RS_AN_NOT_IN_P},
    {"simulate", NULL, EQ, "", simulate_opts, "the measured growth per step of the equations themselves",
     NULL, NULL, rs_an_simulate, RS_AN_NOT_IN_P},
    {"sweep", NULL, EQ, "NAME from A to B steps K [log] [of radius|modes|stability] [at NAME=VALUE, ...] [h=EXPR reference=EXPR[,EXPR]]",
     NULL, "verdicts (and radius or modes) on a grid of one parameter", sweep_parse, sweep_req_clear, run_sweep, 0},
    {"map", NULL, EQ, "NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability] | re(NAME) A B N, im(NAME) C D M", NULL,
     "verdicts and radius on a grid of two parameters, with the exact boundary; re(NAME), im(NAME): the complex "
     "plane of NAME with its boundary locus", eq_map_parse, eq_map_clear, run_eq_map, 0},
    {"expect", NULL, EQ, "charpoly|bilinear POLY", NULL, "compares a printed polynomial with the derived one",
     rs_an_expect_parse, rs_an_expect_req_clear, rs_an_expect, 0},
    {"radius", NULL, NUM, "", digits_opts, "the certified spectral radius of the one-step map",
     NULL, NULL, rs_an_numeric_radius, 0},
    {"stability", NULL, NUM, "", digits_opts, "the verdict from the certified spectral radius",
     NULL, NULL, rs_an_numeric_stability, 0},
    {"modes", NULL, RS_AN_KINDS(RS_MODEL_COSIM), "", cosim_modes_opts,
     "for each eigenvalue of the one-step map: ln(lambda)/h, damping ratio, relative frequency error",
     NULL, NULL, rs_an_cosim_modes, 0},
    {"region", NULL, RS_AN_KINDS(RS_MODEL_COSIM), "NAME from A to B", cosim_region_opts,
     "certified stable/unstable intervals; each transition enclosed narrower than 10^-N, unseparated ones named",
     rs_an_cosim_region_parse, rs_an_cosim_box_req_clear, rs_an_cosim_region, 0},
    {"claim", NULL, RS_AN_KINDS(RS_MODEL_COSIM), "stable|bounded|unstable when A <= NAME <= B [and ...]", NULL,
     "proved over the box (Stein certificates on sub-boxes), refuted (certified point) or undecided (the sub-box)",
     rs_an_cosim_claim_parse, rs_an_cosim_box_req_clear, rs_an_cosim_claim, 0},
    {"sweep", NULL, RS_AN_KINDS(RS_MODEL_COSIM),
     "NAME from A to B steps K [log] [of radius|modes|stability] [h=EXPR reference=EXPR[,EXPR]]", NULL,
     "verdicts from the certified radius (and modes of the certified eigenvalues) on a grid of one parameter",
     sweep_parse, sweep_req_clear, run_sweep, 0},
    {"map", NULL, RS_AN_KINDS(RS_MODEL_COSIM), "NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]", NULL,
     "verdicts from the certified radius on a grid of two parameters", map_parse, sweep_req_clear, run_cosim_map, 0},
    {NULL, NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, 0}
};

#undef EQ
#undef NUM

/* ---- lookup -------------------------------------------------------------- */

static int def_named(const rs_an_def_t *d, const char *t, size_t n)
{
    slong k;
    if (strlen(d->name) == n && strncmp(d->name, t, n) == 0) return 1;
    for (k = 0; d->aliases != NULL && d->aliases[k] != NULL; k++)
        if (strlen(d->aliases[k]) == n && strncmp(d->aliases[k], t, n) == 0) return 1;
    return 0;
}

/* 1 when entry i applies to one of `kinds` and is the first such with its name */
static int first_of_name(slong i, int kinds)
{
    slong j;
    if (!(rs_an_registry[i].kinds & kinds)) return 0;
    for (j = 0; j < i; j++)
        if ((rs_an_registry[j].kinds & kinds) && strcmp(rs_an_registry[j].name, rs_an_registry[i].name) == 0)
            return 0;
    return 1;
}

/* the names of the entries for the model kinds in `kinds`, each once, in
 * table order, joined by ", " (and " and " before the last when `and`) */
static void names_list(char *buf, size_t len, int kinds, int and)
{
    slong i, n = 0, count = 0;
    buf[0] = '\0';
    for (i = 0; rs_an_registry[i].name != NULL; i++) count += first_of_name(i, kinds);
    for (i = 0; rs_an_registry[i].name != NULL; i++) {
        size_t used = strlen(buf);
        if (!first_of_name(i, kinds)) continue;
        snprintf(buf + used, len - used, "%s%s", n == 0 ? "" : (and && n == count - 1) ? " and " : ", ",
                 rs_an_registry[i].name);
        n++;
    }
}

/* the entry for the first word of q, or an error naming what applies */
static int lookup(const rs_an_def_t **out, rs_run_t *run, const rs_request_t *q)
{
    int kind = run->m->kind;
    const char *t = q->text;
    size_t n = 0;
    slong i;
    char list[400], msg[600], word[80];
    while (t[n] && !isspace((unsigned char) t[n])) n++;
    for (i = 0; rs_an_registry[i].name != NULL; i++)
        if ((rs_an_registry[i].kinds & RS_AN_KINDS(kind)) && def_named(rs_an_registry + i, t, n)) {
            *out = rs_an_registry + i;
            return RS_OK;
        }
    names_list(list, sizeof list, RS_AN_KINDS(kind), kind != RS_MODEL_EQUATIONS);
    if (kind == RS_MODEL_RECURRENCE)
        snprintf(msg, sizeof msg, "a recurrence with non-polynomial entries (exp, sin, ...) is numeric: only %s "
                 "apply, found '%%s'", list);
    else if (kind == RS_MODEL_COSIM)
        snprintf(msg, sizeof msg, "exact (analytic) subsystem integration gives a recurrence with "
                 "matrix-exponential entries: only %s apply, found '%%s'", list);
    else {
        snprintf(msg, sizeof msg, "expected an analysis (%s), found '%%s'", list);
        snprintf(word, sizeof word, "%.*s", (int) (n > 60 ? 60 : n), t);
        return rs_req_error(run, q, t, RS_ERR_INPUT, msg, word);
    }
    return rs_req_error(run, q, t, RS_ERR_INPUT, msg, t);
}

/* ---- options `key=value` --------------------------------------------------- */

static int opt_unknown(rs_run_t *run, const rs_an_req_t *req, const char *t)
{
    const rs_opt_spec_t *o = req->def->opts;
    char list[256] = "", msg[400];
    slong k;
    if (o == NULL) {
        snprintf(msg, sizeof msg, "expected end of line after %s, found '%%s'", req->def->name);
        return rs_req_error(run, req->q, t, RS_ERR_INPUT, msg, t);
    }
    for (k = 0; o[k].key != NULL; k++) {
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s%s=", k ? ", " : "", o[k].key);
    }
    snprintf(msg, sizeof msg, "expected an option (%s), found '%%s'", list);
    return rs_req_error(run, req->q, t, RS_ERR_INPUT, msg, t);
}

/* an expression starting at t: *end is where it stops */
static int opt_expr(rs_run_t *run, const rs_request_t *q, const char *t, const char **end)
{
    rs_src_t src;
    rs_expr_t *e = NULL;
    size_t pos = (size_t) (t - q->text);
    int r;
    rs_req_src(&src, q);
    r = rs_expr_parse(&e, &src, &pos, run->err);
    if (r == RS_OK) r = rs_an_check_names(run, q, e);
    rs_expr_free(e);
    *end = q->text + pos;
    return r;
}

static int opt_value(rs_optval_t *v, const rs_opt_spec_t *o, rs_run_t *run, const rs_request_t *q,
                     const char **next)
{
    const char *val = v->val;
    size_t n = strcspn(val, " \t");
    char word[64], msg[300];
    slong k;
    int r = RS_OK;
    snprintf(word, sizeof word, "%.*s", (int) (n < sizeof word ? n : sizeof word - 1), val);
    *next = val + n;
    switch (o->type) {
    case RS_OPT_INTEGER: {
        char *end;
        long x;
        errno = 0;
        x = strtol(word, &end, 10);
        if (n > 0 && n < sizeof word && *end == '\0' && errno == 0 && x >= o->lo && x <= o->hi) {
            v->num = x;
            return RS_OK;
        }
        snprintf(msg, sizeof msg, "%s= expects an integer from %ld to %ld (limit), found '%%s'", o->key,
                 (long) o->lo, (long) o->hi);
        return rs_req_error(run, q, v->at, (n > 0 && *end == '\0' && x > o->hi) ? RS_ERR_LIMIT : RS_ERR_INPUT,
                            msg, word);
    }
    case RS_OPT_ENUM: {
        char list[200] = "";
        for (k = 0; o->choices[k] != NULL; k++)
            if (strlen(o->choices[k]) == n && strncmp(o->choices[k], val, n) == 0) {
                v->num = k;
                return RS_OK;
            }
        for (k = 0; o->choices[k] != NULL; k++) {
            size_t used = strlen(list);
            snprintf(list + used, sizeof list - used, "%s%s", k == 0 ? "" : o->choices[k + 1] ? ", " : " or ",
                     o->choices[k]);
        }
        snprintf(msg, sizeof msg, "%s= expects %s, found '%%s'", o->key, list);
        return rs_req_error(run, q, v->at, RS_ERR_INPUT, msg, word);
    }
    case RS_OPT_EXPR:
        return opt_expr(run, q, val, next);
    case RS_OPT_EXPRS:
        for (;;) {
            v->list = realloc(v->list, (size_t) (v->nlist + 1) * sizeof(char *));
            v->list[v->nlist++] = val;
            r = opt_expr(run, q, val, next);
            if (r != RS_OK || **next != ',') break;
            val = *next + 1;
            while (*val == ' ' || *val == '\t') val++;
        }
        return r;
    }
    return RS_OK;
}

/* `key=value` words from t to the end of the text */
static int opts_parse(rs_an_req_t *req, rs_run_t *run, const char *t)
{
    const rs_opt_spec_t *o = req->def->opts;
    for (;;) {
        size_t n;
        slong k, found = -1;
        const char *next;
        int r;
        while (*t == ' ' || *t == '\t') t++;
        if (*t == '\0') return RS_OK;
        n = strcspn(t, "= \t");
        for (k = 0; o != NULL && o[k].key != NULL; k++)
            if (strlen(o[k].key) == n && strncmp(o[k].key, t, n) == 0 && t[n] == '=') found = k;
        if (found < 0) return opt_unknown(run, req, t);
        if (req->opt[found].at != NULL) {
            char msg[200];
            snprintf(msg, sizeof msg, "%s= is given twice, found '%%s'", o[found].key);
            return rs_req_error(run, req->q, t, RS_ERR_INPUT, msg, t);
        }
        req->opt[found].at = t;
        req->opt[found].val = t + n + 1;
        r = opt_value(req->opt + found, o + found, run, req->q, &next);
        if (r != RS_OK) return r;
        /* (an expression's parse stops after the blanks that follow it) */
        if (*next != '\0' && *next != ' ' && *next != '\t' && next[-1] != ' ' && next[-1] != '\t')
            return rs_req_error(run, req->q, next, RS_ERR_INPUT,
                                "expected a space or end of line after an option's value, found '%s'", next);
        t = next;
    }
}

int rs_an_opts_parse(rs_an_req_t *req, rs_run_t *run, const char *t)
{
    return opts_parse(req, run, t);
}

int rs_an_req_parse(rs_an_req_t *req, rs_run_t *run, const rs_request_t *q)
{
    int r;
    memset(req, 0, sizeof *req);
    req->q = q;
    r = lookup(&req->def, run, q);
    if (r != RS_OK) return r;
    r = rs_an_qd_check(run, req);   /* rk sdirk2: the analyses over Q(sqrt d) only */
    if (r != RS_OK)
    {
        req->def = NULL;            /* refused before its parse: nothing for its clear */
        return r;
    }
    req->rest = rs_req_skip_word(q->text);
    r = req->def->parse != NULL ? req->def->parse(req, run) : opts_parse(req, run, req->rest);
    /* over Q(sqrt d) a region is checked again once its parameters are known */
    if (r == RS_OK && run->m->qd != NULL && strcmp(req->def->name, "region") == 0) r = rs_an_qd_check(run, req);
    return r;
}

void rs_an_req_clear(rs_an_req_t *req)
{
    slong k;
    for (k = 0; k < RS_AN_MAX_OPTS; k++) free(req->opt[k].list);
    if (req->def != NULL && req->def->clear != NULL) req->def->clear(req);
    memset(req, 0, sizeof *req);
}

int rs_an_req_run(rs_run_t *run, const rs_an_req_t *req)
{
    size_t before = json_array_size(run->results), k;
    int r = req->def->run(run, req);
    /* a numeric limit raised below the analyses (root isolation) names no
     * place: the request's, as radius names it */
    if (r == RS_ERR_UNDECIDED && req->q != NULL) r = rs_req_relocate(run, req->q, r, req->def->name);
    /* numeric analyses that set their own "substituted": name the
     * parameters p does not depend on (placeholders) */
    if (r == RS_OK && (req->def->flags & RS_AN_NOT_IN_P)) {
        rs_variant_t *v;
        if (rs_run_numeric_variant(run, &v) == RS_OK && v->not_in_p != NULL)
            for (k = before; k < json_array_size(run->results); k++)
            {
                json_object_set(json_array_get(run->results, k), "not_in_p", v->not_in_p);
                if (v->valid_if != NULL)
                    json_object_set(json_array_get(run->results, k), "valid_if", v->valid_if);
            }
    }
    return r;
}

/* ---- the list for --list-analyses ------------------------------------------ */

static void kinds_text(char *buf, size_t len, int kinds)
{
    int eq = kinds & RS_AN_KINDS(RS_MODEL_EQUATIONS), rec = kinds & RS_AN_KINDS(RS_MODEL_RECURRENCE),
        co = kinds & RS_AN_KINDS(RS_MODEL_COSIM);
    snprintf(buf, len, "%s%s%s%s%s", eq ? "equations" : "", eq && (rec || co) ? ", " : "",
             rec ? "numeric recurrence" : "", rec && co ? ", " : "", co ? "co-simulation" : "");
}

/* "name words [key=META] [key=a|b]" */
static void synopsis(FILE *out, const rs_an_def_t *d)
{
    slong k, j;
    fputs(d->name, out);
    if (d->words[0] != '\0') fprintf(out, " %s", d->words);
    for (k = 0; d->opts != NULL && d->opts[k].key != NULL; k++) {
        const rs_opt_spec_t *o = d->opts + k;
        fprintf(out, " [%s=", o->key);
        if (o->type == RS_OPT_ENUM)
            for (j = 0; o->choices[j] != NULL; j++) fprintf(out, "%s%s", j > 0 ? "|" : "", o->choices[j]);
        else fputs(o->meta, out);
        fputs(o->type == RS_OPT_EXPRS ? ",...]" : "]", out);
    }
}

void rs_analysis_list(FILE *out, int names_only)
{
    slong i, k;
    if (names_only) {
        char list[400];
        names_list(list, sizeof list, RS_AN_KINDS(RS_MODEL_EQUATIONS) | RS_AN_KINDS(RS_MODEL_RECURRENCE)
                   | RS_AN_KINDS(RS_MODEL_COSIM), 0);
        fprintf(out, "%s\n", list);
        return;
    }
    for (i = 0; rs_an_registry[i].name != NULL; i++) {
        const rs_an_def_t *d = rs_an_registry + i;
        char kinds[80];
        synopsis(out, d);
        kinds_text(kinds, sizeof kinds, d->kinds);
        fprintf(out, "\n    models: %s\n    %s\n", kinds, d->summary);
        for (k = 0; d->opts != NULL && d->opts[k].key != NULL; k++) {
            const rs_opt_spec_t *o = d->opts + k;
            if (o->type == RS_OPT_INTEGER)
                fprintf(out, "    %s=%s: an integer from %ld to %ld (default %s)\n", o->key, o->meta, (long) o->lo,
                        (long) o->hi, o->def);
            else if (o->type == RS_OPT_ENUM)
                fprintf(out, "    %s=: one of the words (default %s)\n", o->key, o->def);
            else
                fprintf(out, "    %s=%s: %s (default %s)\n", o->key, o->meta,
                        o->type == RS_OPT_EXPR ? "an expression of set parameters"
                                               : "expressions of set parameters separated by ','", o->def);
        }
    }
}
