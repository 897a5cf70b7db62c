/* lower.c -- the lowering entry: syntax tree -> equations model.  The
 * builders and the recurrence terms append their unknowns and equations
 * (expression trees, marked generated) to the case; nothing is re-parsed. */
#include <string.h>
#include "recstab/scheme.h"
#include "lower/builder.h"
#include "lower/recurrence.h"

int rs_case_lower(rs_case_t c, rs_error_t err)
{
    int r = rs_builder_expand(c, err);
    if (r == RS_OK) r = rs_recurrence_expand(c, err);
    return r;
}

typedef struct { char *s; size_t len; } cat_t;

static void cat(cat_t *b, const char *a)
{
    size_t n = strlen(a);
    b->s = flint_realloc(b->s, b->len + n + 1);
    memcpy(b->s + b->len, a, n + 1);
    b->len += n;
}

char *rs_case_emit_equations(const rs_case_t c)
{
    cat_t b = {NULL, 0};
    slong i;
    int any = 0;
    if (rs_builder_is_exact(c))
        return rs_strdup("# exact (analytic) subsystem integration: a numeric matrix recurrence, built at "
                         "set values; only numeric analyses (radius) apply\n");
    cat(&b, "");
    for (i = 0; i < c->nunknowns; i++)
        if (c->unknowns[i].generated) {
            cat(&b, any ? " " : "unknown ");
            cat(&b, c->unknowns[i].name);
            any = 1;
        }
    if (any) cat(&b, "\n");
    for (i = 0; i < c->neqs; i++)
        if (c->eqs[i].generated) {
            cat(&b, "eq ");
            cat(&b, c->eqs[i].text);
            cat(&b, "\n");
            any = 1;
        }
    if (!any) { flint_free(b.s); return NULL; }
    return b.s;
}
