/* test_registry.c -- the registry of analyses (src/analysis/registry.c):
 * the table is consistent, requests become typed requests, and bad
 * requests are input errors at the offending word before anything runs.
 * Expected values: the typed fields are read off the request texts below;
 * the columns are counted by hand in those texts (1-based, the request
 * text `analyse ` prefix included); the option ranges are the README's. */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "analysis/registry.h"
#include "analysis/sweep_impl.h"

/* HHT-like two-parameter case: params w, v; nothing set */
static const char *case_text =
    "param w v\n"
    "unknown x\n"
    "eq x[n+1] = x[n] - w*v*x[n]\n";

typedef struct {
    rs_case_t c;
    rs_model_t m;
    rs_options_t opt;
    rs_error_t err;
    rs_run_t run;
} fixture_t;

static void fixture_init(fixture_t *f, const char *text)
{
    rs_case_init(f->c);
    rs_error_init(f->err);
    rs_options_default(&f->opt);
    assert_int_equal(rs_case_parse_string(f->c, "t.case", text, strlen(text), f->err), RS_OK);
    rs_model_init(f->m);
    assert_int_equal(rs_model_lower(f->m, f->c, f->err), RS_OK);
    memset(&f->run, 0, sizeof f->run);
    f->run.c = f->c;
    f->run.m = f->m;
    f->run.opt = &f->opt;
    f->run.err = f->err;
}

static void fixture_clear(fixture_t *f)
{
    rs_model_clear(f->m);
    rs_case_clear(f->c);
}

/* parses `text` as the request on line 9, column 9 (after "analyse ") */
static int parse(rs_an_req_t *req, fixture_t *f, rs_request_t *q, const char *text)
{
    q->text = (char *) text;
    q->loc.file = (char *) "t.case";
    q->loc.line = 9;
    q->loc.col = 9;
    rs_error_init(f->err);
    return rs_an_req_parse(req, &f->run, q);
}

static void test_table(void **state)
{
    slong i, j, k, m;
    (void) state;
    for (i = 0; rs_an_registry[i].name != NULL; i++) {
        const rs_an_def_t *d = rs_an_registry + i;
        assert_non_null(d->run);
        assert_true(d->kinds != 0);
        assert_non_null(d->words);
        assert_non_null(d->summary);
        /* no two entries with one name for one model kind */
        for (j = 0; j < i; j++)
            assert_false(strcmp(rs_an_registry[j].name, d->name) == 0 && (rs_an_registry[j].kinds & d->kinds));
        /* keys unique, at most RS_AN_MAX_OPTS, ranges non-empty, defaults shown */
        for (k = 0; d->opts != NULL && d->opts[k].key != NULL; k++) {
            assert_true(k < RS_AN_MAX_OPTS);
            assert_non_null(d->opts[k].def);
            if (d->opts[k].type == RS_OPT_INTEGER) assert_true(d->opts[k].lo <= d->opts[k].hi);
            if (d->opts[k].type == RS_OPT_ENUM) assert_string_equal(d->opts[k].choices[0], d->opts[k].def);
            for (m = 0; m < k; m++) assert_string_not_equal(d->opts[m].key, d->opts[k].key);
        }
        /* an analysis with words parses them itself */
        if (d->words[0] != '\0') assert_non_null(d->parse);
    }
}

static void test_typed(void **state)
{
    fixture_t f;
    rs_request_t q;
    rs_an_req_t req;
    (void) state;
    fixture_init(&f, case_text);

    assert_int_equal(parse(&req, &f, &q, "radius digits=12 method=double"), RS_OK);
    assert_string_equal(req.def->name, "radius");
    assert_true(req.def->kinds & RS_AN_KINDS(RS_MODEL_EQUATIONS));
    assert_int_equal(rs_an_opt(&req, "digits")->num, 12);
    assert_string_equal(rs_an_opt_choice(&req, "method"), "double");
    rs_an_req_clear(&req);

    assert_int_equal(parse(&req, &f, &q, "radius"), RS_OK);
    assert_null(rs_an_opt(&req, "digits")->at);
    assert_string_equal(rs_an_opt_choice(&req, "method"), "certified");
    rs_an_req_clear(&req);

    /* two references: the second starts at "2*w" */
    assert_int_equal(parse(&req, &f, &q, "modes reference=1, 2*w h=1/10"), RS_OK);
    assert_int_equal(rs_an_opt(&req, "reference")->nlist, 2);
    assert_ptr_equal(rs_an_opt(&req, "reference")->list[1], q.text + strlen("modes reference=1, "));
    assert_ptr_equal(rs_an_opt(&req, "h")->val, q.text + strlen("modes reference=1, 2*w h="));
    rs_an_req_clear(&req);

    assert_int_equal(parse(&req, &f, &q, "limit v -> inf"), RS_OK);
    assert_int_equal(req.u.limit.param, 1);
    assert_int_equal(req.u.limit.to_inf, 1);
    rs_an_req_clear(&req);

    assert_int_equal(parse(&req, &f, &q, "region w at v=1/2"), RS_OK);
    assert_int_equal(req.u.region.param, 0);
    assert_int_equal(req.u.region.nat, 1);
    assert_int_equal(req.u.region.at[0].var, 1);
    assert_int_equal(fmpz_get_si(fmpq_numref(req.u.region.at[0].value)), 1);
    assert_int_equal(fmpz_get_si(fmpq_denref(req.u.region.at[0].value)), 2);
    rs_an_req_clear(&req);

    assert_int_equal(parse(&req, &f, &q, "expect bilinear z + 1"), RS_OK);
    assert_int_equal(req.u.expect.bilinear, 1);
    assert_non_null(req.u.expect.poly);
    rs_an_req_clear(&req);

    /* sweep and map: the sweep engine's typed request (4 steps: 5 points; a 3 x 2 map) */
    assert_int_equal(parse(&req, &f, &q, "sweep w from 0 to 1 steps 4 of stability"), RS_OK);
    assert_string_equal(req.def->name, "sweep");
    assert_int_equal(((rs_sweep_request_t *) req.u.sweep)->naxes, 1);
    assert_int_equal(((rs_sweep_request_t *) req.u.sweep)->axis[0].count, 4);
    assert_int_equal(((rs_sweep_request_t *) req.u.sweep)->of, RS_SWEEP_OF_STABILITY);
    rs_an_req_clear(&req);
    assert_int_equal(parse(&req, &f, &q, "map w 0 1 3, v 1 2 2"), RS_OK);
    assert_int_equal(((rs_sweep_request_t *) req.u.sweep)->naxes, 2);
    assert_int_equal(((rs_sweep_request_t *) req.u.sweep)->axis[1].var, 1);
    rs_an_req_clear(&req);

    assert_int_equal(parse(&req, &f, &q, "claim bounded when w > 0 or w < -1"), RS_OK);
    assert_non_null(req.u.claim.dnf);
    rs_an_req_clear(&req);
    fixture_clear(&f);
}

/* code, column and the start of the message of a bad request */
static void bad(fixture_t *f, const char *text, int code, int col, const char *msg)
{
    rs_request_t q;
    rs_an_req_t req;
    int r = parse(&req, f, &q, text);
    rs_an_req_clear(&req);
    if (r != code || f->err->line != 9 || f->err->col != col || strncmp(f->err->msg, msg, strlen(msg)) != 0)
        fail_msg("'%s': code %d at 9:%d '%s', expected %d at 9:%d '%s...'", text, r, f->err->col, f->err->msg,
                 code, col, msg);
}

static void test_bad(void **state)
{
    fixture_t f;
    (void) state;
    fixture_init(&f, case_text);
    /* issue 12: accepted silently before the registry */
    bad(&f, "modes refrence=1 hh=3", RS_ERR_INPUT, 15, "expected an option (reference=, h=), found 'refrence=1 hh=3'");
    bad(&f, "modes h=1 hh=3", RS_ERR_INPUT, 19, "expected an option (reference=, h=), found 'hh=3'");
    bad(&f, "radius digits=5 digits=6", RS_ERR_INPUT, 25, "digits= is given twice");
    /* ranges: digits 1..20000, seed 0..10^9, prec 32..65536 */
    bad(&f, "radius digits=0", RS_ERR_INPUT, 16, "digits= expects an integer from 1 to 20000");
    bad(&f, "radius digits=20001", RS_ERR_LIMIT, 16, "digits= expects an integer from 1 to 20000");
    bad(&f, "simulate prec=31", RS_ERR_INPUT, 18, "prec= expects an integer from 32 to 65536");
    bad(&f, "simulate seed=", RS_ERR_INPUT, 18, "seed= expects an integer from 0 to 1000000000");
    bad(&f, "radius method=exact", RS_ERR_INPUT, 16, "method= expects certified, companion or double, found 'exact'");
    bad(&f, "routh now", RS_ERR_INPUT, 15, "expected end of line after routh, found 'now'");
    bad(&f, "frobnicate", RS_ERR_INPUT, 9, "expected an analysis (charpoly, bilinear, routh, hurwitz, jury, "
        "stability, region, limit, astability, claim, radius, modes, simulate, sweep, map, expect), found 'frobnicate'");
    /* model-dependent checks up front: parameter names */
    bad(&f, "region q", RS_ERR_INPUT, 16, "'q' is not a parameter");
    bad(&f, "region w at w=1", RS_ERR_INPUT, 16, "the region parameter 'w' is also given a value");
    bad(&f, "limit v -> 1", RS_ERR_INPUT, 20, "expected 0 or inf, found '1'");
    bad(&f, "claim stable when w < 1 xor v > 0", RS_ERR_INPUT, 33, "expected 'and', 'or', ',' or end of line");
    bad(&f, "expect charpoly lambda +", RS_ERR_INPUT, 33, "expected an expression");
    /* undeclared names in expressions, at the name */
    bad(&f, "claim stable when 0 < ww < 1", RS_ERR_INPUT, 31, "unknown name 'ww'");
    bad(&f, "modes h=1/2 reference=1,wx", RS_ERR_INPUT, 33, "unknown name 'wx'");
    bad(&f, "expect charpoly lambda + vv", RS_ERR_INPUT, 34, "unknown name 'vv'");
    fixture_clear(&f);
}

/* the model kind decides which entries exist */
static void test_kinds(void **state)
{
    fixture_t f;
    rs_request_t q;
    rs_an_req_t req;
    (void) state;
    fixture_init(&f, "param h\nset h = 1/10\nrecurrence 1 = [1]\nrecurrence 0 = [-exp(-h)]\n");
    assert_int_equal(f.m->kind, RS_MODEL_RECURRENCE);
    assert_int_equal(parse(&req, &f, &q, "radius digits=20"), RS_OK);
    assert_true(req.def->kinds & RS_AN_KINDS(RS_MODEL_RECURRENCE));
    assert_int_equal(rs_an_opt(&req, "digits")->num, 20);
    rs_an_req_clear(&req);
    /* method= belongs to the equations' radius only */
    bad(&f, "radius method=double", RS_ERR_INPUT, 16, "expected an option (digits=), found 'method=double'");
    bad(&f, "routh", RS_ERR_INPUT, 9, "a recurrence with non-polynomial entries (exp, sin, ...) is numeric: only "
        "radius and stability apply, found 'routh'");
    fixture_clear(&f);
}

/* a bad request after a good one: the run fails before the first runs
 * (no document), with the bad request's place */
static void test_checked_first(void **state)
{
    const char *text = "param w\nunknown x\nset w = 1/2\neq x[n+1] = x[n] - w*x[n]\n"
                       "analyse stability\nanalyse radius digits=30 method=certfied\n";
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome = 0;
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    assert_int_equal(rs_analysis_run(&doc, &outcome, c, &opt, err), RS_ERR_INPUT);
    assert_null(doc);
    assert_int_equal(err->line, 6);
    assert_int_equal(err->col, 26);
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_typed),
        cmocka_unit_test(test_bad),
        cmocka_unit_test(test_kinds),
        cmocka_unit_test(test_checked_first),
    };
    return cmocka_run_group_tests_name("registry", tests, NULL, NULL);
}
