/* analysis_numeric.c -- certified numeric analyses (radius, modes,
 * simulate). */
#include <string.h>
#include "recstab/analysis_impl.h"

const rs_analysis_entry_t rs_analysis_numeric[] = {
    {NULL, NULL}
};
