/* analysis_sweep.c -- 1-D sweeps and 2-D stability maps (see issue: sweeps,
 * maps and plots).  Not yet implemented: the table is empty. */
#include "recstab/analysis_impl.h"

const rs_analysis_entry_t rs_analysis_sweep[] = {
    {NULL, NULL}
};
