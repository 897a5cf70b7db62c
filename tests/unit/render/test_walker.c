/* test_walker.c -- the render walker over hand-made result documents, in the
 * three formats (text report, Markdown, LaTeX).
 *
 * Each expected output is written by hand from the documented layout of the
 * format (the report's "  LABEL        value" lines, 12-character labels; the
 * derivation's headings, lists and tables; LaTeX math from the rules of
 * rs_derivation_tex_poly: x[n] -> x_{n}, '*' -> "\,", a^2 -> a^{2},
 * 1/2 -> \tfrac{1}{2}, greek names -> \lambda), not copied from a run. */
#include "testutil.h"
#include <stdlib.h>
#include <jansson.h>
#include "recstab/report.h"
#include "recstab/derivation.h"

enum { TEXT, MARKDOWN, LATEX };

/* the document rendered in one format, as a string (caller frees) */
static char *render(const char *json, int format)
{
    json_error_t e;
    json_t *doc = json_loads(json, 0, &e);
    char *buf = NULL;
    size_t len = 0;
    FILE *f;
    if (doc == NULL) fail_msg("bad test JSON: %s (line %d)", e.text, e.line);
    f = open_memstream(&buf, &len);
    if (format == TEXT) rs_report_text(f, doc);
    else if (format == MARKDOWN) rs_derivation_markdown(f, doc);
    else rs_derivation_latex(f, doc, 0);
    fclose(f);
    json_decref(doc);
    return buf;
}

static void check(const char *json, int format, const char *expected)
{
    char *got = render(json, format);
    if (strcmp(got, expected) != 0)
        fail_msg("format %d:\n--- expected\n%s--- got\n%s---", format, expected, got);
    free(got);
}

/* a scheme, a charpoly with lambda^1 divided out, a Routh array with a
 * singular step and a verdict, and an analysis no layout knows */
static const char *doc_scheme =
    "{\"case\": \"demo.case\", \"title\": \"Demo_1\","
    " \"scheme\": {\"assume\": [\"w > 0\"], \"lets\": [\"y[n] = 2*x[n]\"],"
    "             \"equations\": [\"x[n+1] - x[n] = 0\"], \"matrix\": [[\"lambda - 1\"]]},"
    " \"results\": ["
    "  {\"analysis\": \"charpoly\", \"poly\": \"lambda^2 - 1/2\", \"degree\": 2, \"content\": \"3\","
    "   \"removed_lambda_power\": 1},"
    "  {\"analysis\": \"routh\", \"rows\": [[\"2\", \"1\"], [\"w\"], [\"1\"]],"
    "   \"events\": [{\"kind\": \"zero row\", \"text\": \"row z^1 replaced\"}],"
    "   \"status\": \"stable\", \"inside\": 2, \"on\": 0, \"outside\": 0},"
    "  {\"analysis\": \"xyz\", \"n\": 3, \"s\": \"t\"}]}";

static void test_scheme_text(void **state)
{
    (void) state;
    /* the report shows no scheme; xyz falls back to key/value lines */
    check(doc_scheme, TEXT,
          "case demo.case: Demo_1\n"
          "\n"
          "charpoly\n"
          "  p(lambda)    lambda^2 - 1/2\n"
          "  degree       2\n"
          "  removed      lambda^1 (roots at 0) divided out\n"
          "  content      3 (det = content * lambda^k * p)\n"
          "\n"
          "routh\n"
          "  z^2          2   1\n"
          "  z^1          w\n"
          "  z^0          1\n"
          "  zero row     row z^1 replaced\n"
          "  verdict      stable: 2 inside, 0 on, 0 outside the unit circle\n"
          "\n"
          "xyz\n"
          "  n            3\n"
          "  s            t\n");
}

static void test_scheme_markdown(void **state)
{
    (void) state;
    /* the derivations skip analyses they have no layout for (xyz) */
    check(doc_scheme, MARKDOWN,
          "## Demo\\_1\n"
          "\n"
          "Assumptions: $w > 0$.\n"
          "\n"
          "### Difference equations\n"
          "\n"
          "$$\n"
          "\\begin{aligned}\n"
          "y_{n} &= 2\\,x_{n} && \\text{(let)} \\\\\n"
          "x_{n+1} - x_{n} &= 0\n"
          "\\end{aligned}\n"
          "$$\n"
          "\n"
          "### The lambda-matrix\n"
          "\n"
          "With $x_{n+k} \\mapsto \\lambda^k$ (each row shifted so that its lowest power is $\\lambda^0$):\n"
          "\n"
          "$$\n"
          "\\left(\\begin{array}{c}\n"
          "\\lambda - 1 \\\\\n"
          "\\end{array}\\right)\n"
          "$$\n"
          "\n"
          "### Characteristic polynomial\n"
          "\n"
          "p(lambda) = det of the lambda-matrix (fraction-free), lambda^1 (roots at 0) divided out:\n"
          "\n"
          "$$p(\\lambda) = \\lambda^{2} - \\tfrac{1}{2}$$\n"
          "\n"
          "degree 2, content 3.\n"
          "\n"
          "### Routh array of q(z)\n"
          "\n"
          "| row | 1 | 2 |\n"
          "|---|---|---|\n"
          "| $z^{2}$ | $2$ | $1$ |\n"
          "| $z^{1}$ | $w$ |  |\n"
          "| $z^{0}$ | $1$ |  |\n"
          "\n"
          "*Singular step (zero row):* row z^1 replaced\n"
          "\n"
          "Verdict: **stable** — 2 roots inside, 0 on, 0 outside the unit circle.\n"
          "\n");
}

static void test_scheme_latex(void **state)
{
    (void) state;
    check(doc_scheme, LATEX,
          "\\section*{Demo\\_1}\n"
          "Assumptions: $w > 0$.\n"
          "\n"
          "\\subsection*{Difference equations}\n"
          "\\begin{align*}\n"
          "y_{n} &= 2\\,x_{n} && \\text{(let)} \\\\\n"
          "x_{n+1} - x_{n} &= 0\n"
          "\\end{align*}\n"
          "\\subsection*{The $\\lambda$-matrix}\n"
          "With $x_{n+k} \\mapsto \\lambda^k$ (each row shifted so that its lowest power is $\\lambda^0$):\n"
          "{\\small\\[\\left(\\begin{array}{c}\n"
          "\\lambda - 1 \\\\\n"
          "\\end{array}\\right)\\]}\n"
          "\\subsection*{Characteristic polynomial}\n"
          "The determinant of the $\\lambda$-matrix, computed fraction-free, with the factor $\\lambda^{1}$ (roots at 0) divided out:\n"
          "\n"
          "$p(\\lambda) = \\lambda^{2} - \\tfrac{1}{2}$\n"
          "\n"
          "(degree 2, content 3).\n"
          "\n"
          "\\subsection*{Routh array of $q(z)$}\n"
          "\\[\\begin{array}{r|ll}\n"
          "z^{2} & 2 & 1 \\\\\n"
          "z^{1} & w &  \\\\\n"
          "z^{0} & 1 &  \\\\\n"
          "\\end{array}\\]\n"
          "\\emph{Singular step:} row z\\^{}1 replaced\n"
          "\n"
          "Verdict: \\textbf{stable}: 2 roots inside, 0 on, 0 outside the unit circle.\n"
          "\n");
}

/* Hurwitz with an OR of two branches and a dropped factor; a region of one
 * parameter with an algebraic upper end (root 1 of x^2 - 2, about 1.41). */
static const char *doc_branches =
    "{\"case\": \"h.case\", \"results\": ["
    "  {\"analysis\": \"hurwitz\", \"minors\": [\"a\", \"a*b\"],"
    "   \"branches\": [[\"a > 0\", \"b > 0\"], [\"a < 0\"]], \"conditions\": [],"
    "   \"dropped\": [{\"factor\": \"b^2+1\", \"from\": \"D_2\", \"reason\": \"positive\"}],"
    "   \"verdict\": \"conditional\"},"
    "  {\"analysis\": \"region\", \"param\": \"alpha\", \"intervals\": ["
    "    {\"status\": \"stable\", \"lo\": \"0\", \"lo_closed\": true,"
    "     \"hi\": {\"approx\": \"1.41\", \"root_index\": 1, \"minpoly\": \"x^2 - 2\"}, \"hi_closed\": false},"
    "    {\"status\": \"unstable\", \"lo\": {\"approx\": \"1.41\", \"root_index\": 1, \"minpoly\": \"x^2 - 2\"},"
    "     \"lo_closed\": true, \"hi\": null, \"hi_closed\": false}]}]}";

/* A generalised Routh step that skips a power: rows for z^4, z^3, z^1, z^0
 * ("powers" of the document).  Every format labels each row by its own power
 * (the Markdown and LaTeX tables used to count down from the number of rows:
 * z^3, z^2, z^1, z^0 here, as if no power were skipped). */
static void test_routh_powers(void **state)
{
    const char *doc =
        "{\"case\": \"g.case\", \"results\": ["
        "  {\"analysis\": \"routh\", \"rows\": [[\"1\", \"2\"], [\"1\"], [\"3\"], [\"1\"]],"
        "   \"powers\": [4, 3, 1, 0], \"status\": \"unstable\", \"inside\": 2, \"on\": 0, \"outside\": 2}]}";
    char *t = render(doc, TEXT), *m = render(doc, MARKDOWN), *l = render(doc, LATEX);
    (void) state;
    assert_non_null(strstr(t, "  z^4          1   2\n  z^3          1\n  z^1          3\n  z^0          1\n"));
    assert_non_null(strstr(m, "| $z^{4}$ | $1$ | $2$ |\n| $z^{3}$ | $1$ |  |\n| $z^{1}$ | $3$ |  |\n| $z^{0}$ | $1$ |  |\n"));
    assert_non_null(strstr(l, "z^{4} & 1 & 2 \\\\\nz^{3} & 1 &  \\\\\nz^{1} & 3 &  \\\\\nz^{0} & 1 &  \\\\\n"));
    free(t); free(m); free(l);
}

static void test_branches_text(void **state)
{
    (void) state;
    check(doc_branches, TEXT,
          "case h.case\n"
          "\n"
          "hurwitz\n"
          "  D_1          a\n"
          "  D_2          a*b\n"
          "  stable iff   a > 0\n"
          "  and          b > 0\n"
          "  or           a < 0\n"
          "  dropped      b^2+1 (in D_2): positive\n"
          "  verdict      conditional\n"
          "\n"
          "region\n"
          "  stable     alpha in [0, 1.41)\n"
          "  unstable   alpha in [1.41, inf)\n"
          "  where        1.41 is root 1 (from below, 0-based) of x^2 - 2\n");
}

static void test_branches_markdown(void **state)
{
    (void) state;
    check(doc_branches, MARKDOWN,
          "## h.case\n"
          "\n"
          "### Hurwitz minors and Lienard-Chipart conditions\n"
          "\n"
          "- $D_{1} = a$\n"
          "- $D_{2} = a\\,b$\n"
          "\n"
          "All |lambda| < 1 if and only if every condition of one branch holds (the sign of the leading coefficient of q is not fixed by the assumptions):\n"
          "\n"
          "- either: $a > 0$, $b > 0$\n"
          "- or: $a < 0$\n"
          "\n"
          "Dropped factor $b^{2}+1$ of D_2: positive.\n"
          "\n"
          "### Stability region in $\\alpha$\n"
          "\n"
          "- **stable**: $\\alpha \\in [0, 1.41)$ (upper end: a root of $x^{2} - 2$)\n"
          "- **unstable**: $\\alpha \\in [1.41, \\infty)$\n"
          "\n");
}

static void test_branches_latex(void **state)
{
    (void) state;
    check(doc_branches, LATEX,
          "\\section*{h.case}\n"
          "\\subsection*{Hurwitz minors and Li\\'enard--Chipart conditions}\n"
          "$D_{1} = a$\n"
          "\n"
          "$D_{2} = a\\,b$\n"
          "\n"
          "All $|\\lambda| < 1$ if and only if every condition of one branch holds (the sign of the leading coefficient of $q$ is not fixed by the assumptions):\n"
          "\\begin{itemize}\n"
          "\\item either: $a > 0$, $b > 0$\n"
          "\\item or: $a < 0$\n"
          "\\end{itemize}\n"
          "Factor $b^{2}+1$ of $D_2$ dropped: positive.\n"
          "\n"
          "\\subsection*{Stability region in $\\alpha$}\n"
          "\\begin{itemize}\n"
          "\\item stable: $\\alpha \\in [0, 1.41)$ (upper end: a root of $x^{2} - 2$)\n"
          "\\item unstable: $\\alpha \\in [1.41, \\infty)$\n"
          "\\end{itemize}\n");
}

/* sqrt(d) in a condition over Q(sqrt d) (an_qd_conds.c prints c0 + sqrt(d)*(c1))
 * is LaTeX's \sqrt{d}; any other name followed by '(' stays a name */
static void test_tex_sqrt(void **state)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    (void) state;
    rs_derivation_tex_poly(f, "3 + sqrt(2)*(a^2 - 1) + sqrtx(2) + sqrt(b)");
    fclose(f);
    assert_string_equal(buf, "3 + \\sqrt{2}\\,(a^{2} - 1) + \\mathit{sqrtx}(2) + \\mathit{sqrt}(b)");
    free(buf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scheme_text),
        cmocka_unit_test(test_scheme_markdown),
        cmocka_unit_test(test_scheme_latex),
        cmocka_unit_test(test_routh_powers),
        cmocka_unit_test(test_branches_text),
        cmocka_unit_test(test_branches_markdown),
        cmocka_unit_test(test_branches_latex),
        cmocka_unit_test(test_tex_sqrt),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
