/* SPDX-License-Identifier: MIT */
/* Compare a measured instruction count with its budget in budgets.txt. */
#ifndef ZLINE_BENCH_BUDGET_H
#define ZLINE_BENCH_BUDGET_H

#include <stdint.h>

/* Reads `budgets` (lines "tag name budget") through semihosting, prints
 * BUDGET ok/FAIL and a BUDGET_SUGGEST line (measurement + 3 %), and returns 1
 * when total is over the budget of (bench_tag, name) or has none. */
int bench_check_budget(const char *bench_tag, const char *budgets, const char *name, uint32_t total);

#endif
