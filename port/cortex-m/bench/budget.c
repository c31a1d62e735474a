/* SPDX-License-Identifier: MIT */
/* Instruction budgets of the Cortex-M benchmarks (budgets.txt), shared by
 * bench.c and bench_features.c. */
#include "budget.h"

#include <stdio.h>
#include <string.h>

int bench_check_budget(const char *bench_tag, const char *budgets, const char *scene_name, uint32_t total)
{
    char line[160], tag[40], name[40];
    unsigned long budget = 0, b;
    int found = 0;
    FILE *f = fopen(budgets, "r");
    if (f == NULL) {
        printf("BUDGET FAIL %s %s: cannot read %s\n", bench_tag, scene_name, budgets);
        return 1;
    }
    while (fgets(line, sizeof line, f) != NULL)
        if (sscanf(line, "%39s %39s %lu", tag, name, &b) == 3 && strcmp(tag, bench_tag) == 0 &&
            strcmp(name, scene_name) == 0) {
            budget = b;
            found = 1;
        }
    fclose(f);
    /* budget proposal: the measurement plus 3 %, rounded up to 1000 */
    printf("BUDGET_SUGGEST %s %s %lu\n", bench_tag, scene_name,
           (unsigned long)(((uint64_t)total * 103 / 100 + 999) / 1000 * 1000));
    if (!found) {
        printf("BUDGET FAIL %s %s: no budget in %s (measured %lu)\n", bench_tag, scene_name, budgets,
               (unsigned long)total);
        return 1;
    }
    if (total > budget) {
        printf("BUDGET FAIL %s %s: %lu instructions, budget %lu (+%.1f %%)\n", bench_tag, scene_name,
               (unsigned long)total, budget, 100.0 * ((double)total - (double)budget) / (double)budget);
        return 1;
    }
    printf("BUDGET ok %s %s: %lu <= %lu\n", bench_tag, scene_name, (unsigned long)total, budget);
    return 0;
}

