/* testutil.h -- shared helpers for the cmocka suites. */
#ifndef RECSTAB_TESTUTIL_H
#define RECSTAB_TESTUTIL_H
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#ifndef RS_SOURCE_DIR
#define RS_SOURCE_DIR "."
#endif
#endif
