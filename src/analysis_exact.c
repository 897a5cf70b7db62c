/* analysis_exact.c -- exact stability analyses (bilinear, routh, hurwitz,
 * jury, stability, region, limit, claim). */
#include <string.h>
#include "recstab/analysis_impl.h"

const rs_analysis_entry_t rs_analysis_extra[] = {
    {NULL, NULL}
};
