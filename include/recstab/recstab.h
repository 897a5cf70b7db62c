/* recstab.h -- the whole public API of librecstab in one include.
 * Stages (docs/architecture.md): util, lang, lower, algebra, stability,
 * numeric, analysis, render.  Only these headers are installed. */
#ifndef RECSTAB_RECSTAB_H
#define RECSTAB_RECSTAB_H

#include "recstab/error.h"
#include "recstab/budget.h"
#include "recstab/str.h"
#include "recstab/expr.h"
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"
#include "recstab/cond.h"
#include "recstab/semisimple.h"
#include "recstab/bilinear.h"
#include "recstab/routh.h"
#include "recstab/hurwitz.h"
#include "recstab/positivity.h"
#include "recstab/jury.h"
#include "recstab/rootcount.h"
#include "recstab/radius.h"
#include "recstab/cosim.h"
#include "recstab/ladder.h"
#include "recstab/sweep.h"
#include "recstab/analysis.h"
#include "recstab/report.h"
#include "recstab/derivation.h"
#include "recstab/api.h"

#endif
