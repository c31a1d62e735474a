/* SPDX-License-Identifier: MIT */
/*
 * The C names zline-obj2c and zline-img2c give their arrays
 * (tools/common/c_symbol.c): a --name must be a C identifier (a letter or
 * '_' first, then letters, digits, '_'; at most ZT_SYMBOL_MAX characters);
 * a name made from the input's file name keeps its base name up to the
 * first '.', turns every other character into '_' and is led by the given
 * character when it would start with a digit or another non-letter. The
 * expected names are written out here by hand.
 */
#include <stdio.h>
#include <string.h>

#include "c_symbol.h"

static int failures;

static void expect_given(const char *given, int ok)
{
    zt_symbol s;
    int rc = zt_symbol_make(&s, given, "in.obj", 'm');
    if ((rc == 0) != ok) {
        printf("FAIL: --name \"%s\" %s, expected %s\n", given, rc == 0 ? "accepted" : "refused",
               ok ? "accepted" : "refused");
        failures++;
    } else if (ok && strcmp(s.name, given) != 0) {
        printf("FAIL: --name \"%s\" became \"%s\"\n", given, s.name);
        failures++;
    }
}

static void expect_made(const char *path, char lead, const char *name, const char *upper)
{
    zt_symbol s;
    if (zt_symbol_make(&s, NULL, path, lead) != 0 || strcmp(s.name, name) != 0 || strcmp(s.upper, upper) != 0) {
        printf("FAIL: \"%s\" (lead %c) gave \"%s\" / \"%s\", expected \"%s\" / \"%s\"\n", path, lead, s.name,
               s.upper, name, upper);
        failures++;
    }
}

int main(void)
{
    char longest[ZT_SYMBOL_MAX + 2];
    expect_given("bunny", 1);
    expect_given("_x9", 1);
    expect_given("Tex_2", 1);
    expect_given("9lives", 0);
    expect_given("", 0);
    expect_given("a-b", 0);
    expect_given("a b", 0);
    expect_given("a.b", 0);
    memset(longest, 'a', ZT_SYMBOL_MAX);
    longest[ZT_SYMBOL_MAX] = '\0';
    expect_given(longest, 1);
    longest[ZT_SYMBOL_MAX] = 'a';
    longest[ZT_SYMBOL_MAX + 1] = '\0';
    expect_given(longest, 0);
    expect_made("models/bunny.obj", 'm', "bunny", "BUNNY");
    expect_made("a/b\\my-tex.v2.ppm", 't', "my_tex", "MY_TEX");
    expect_made("3d.obj", 'm', "m3d", "M3D");
    expect_made("dir.x/-x.png", 't', "t_x", "T_X");
    expect_made("_ok1.obj", 'm', "_ok1", "_OK1");
    printf("%d failure(s)\n", failures);
    return failures;
}
