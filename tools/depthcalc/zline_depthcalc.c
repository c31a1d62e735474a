/* SPDX-License-Identifier: MIT */
/*
 * zline-depthcalc: how far apart two surfaces must be for a depth buffer to
 * tell them apart.
 *
 *   zline-depthcalc [--near N] [--far F] [--bits B] [--plot FILE.ppm]
 *                   [--rule-z Z] [--rule-dz DZ]
 *
 * For eye distances z from near to far it prints the smallest eye-depth
 * difference dz that changes the stored depth by one step:
 *   pseudodepth (zline's perspective mapping, z_w = A + B/z):
 *       dz = k z^2 / (1 - k z),  k = (f - n) / ((2^bits - 1) f n)
 *     from the formula, and from the core's integer zl_depth_resolution()
 *     as a cross-check;
 *   linear depth (z_w = (z - n) / (f - n), e.g. a w-buffer):
 *       dz = (f - n) / (2^bits - 1), the same everywhere.
 * The plot (log-log, dz against z, pseudodepth red, linear blue, decade
 * grid lines grey) goes to a binary PPM. Then it derives its rule of thumb
 * from the same numbers: the smallest near plane (and so the largest
 * far/near ratio for a few far planes) at which `bits` bits still separate
 * surfaces DZ apart at distance Z (default 1 cm at 10 m, units = metres).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_pnm.h"
#include "zline/zline.h"

static double dz_pseudo(double n, double f, double z, int bits)
{
    double k = (f - n) / ((pow(2.0, bits) - 1) * f * n);
    return k * z >= 1 ? INFINITY : k * z * z / (1 - k * z);
}

static double dz_linear(double n, double f, int bits)
{
    return (f - n) / (pow(2.0, bits) - 1);
}

static zl_fixed fx(double v)
{
    return (zl_fixed)floor(v * 65536.0 + 0.5);
}

/* Smallest near plane (bisection on the formula, checked by the core) that
 * separates dz at z with a far plane f. */
static double min_near(double f, double z, double dz, int bits)
{
    double lo = 1e-6, hi = z;
    int i;
    if (dz_pseudo(hi, f, z, bits) > dz)
        return -1;
    for (i = 0; i < 200; i++) {
        double mid = sqrt(lo * hi);
        if (dz_pseudo(mid, f, z, bits) <= dz)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

#define PW 640
#define PH 400
#define MARGIN 40

static uint8_t img[PH][PW][3];

static void put(int x, int y, uint8_t r, uint8_t g, uint8_t b)
{
    if (x < 0 || y < 0 || x >= PW || y >= PH)
        return;
    img[y][x][0] = r;
    img[y][x][1] = g;
    img[y][x][2] = b;
}

static int plot(const char *path, double n, double f, int bits)
{
    double x0 = log10(n), x1 = log10(f), ylo, yhi, z;
    double ymin = dz_pseudo(n, f, n, bits), ymax = dz_pseudo(n, f, f, bits);
    char msg[256];
    int px, d;
    if (dz_linear(n, f, bits) < ymin)
        ymin = dz_linear(n, f, bits);
    if (dz_linear(n, f, bits) > ymax)
        ymax = dz_linear(n, f, bits);
    ylo = floor(log10(ymin));
    yhi = ceil(log10(ymax));
    memset(img, 255, sizeof img);
    /* decade grid */
    for (d = (int)floor(x0); d <= (int)ceil(x1); d++) {
        int x = MARGIN + (int)((d - x0) / (x1 - x0) * (PW - 2 * MARGIN));
        int y;
        if (x >= MARGIN && x <= PW - MARGIN)
            for (y = MARGIN; y <= PH - MARGIN; y++)
                put(x, y, 200, 200, 200);
    }
    for (d = (int)ylo; d <= (int)yhi; d++) {
        int y = PH - MARGIN - (int)((d - ylo) / (yhi - ylo) * (PH - 2 * MARGIN)), x;
        for (x = MARGIN; x <= PW - MARGIN; x++)
            put(x, y, 200, 200, 200);
    }
    for (px = MARGIN; px <= PW - MARGIN; px++) {
        int k;
        z = pow(10, x0 + (x1 - x0) * (px - MARGIN) / (PW - 2 * MARGIN));
        for (k = 0; k < 2; k++) {
            double v = k == 0 ? dz_pseudo(n, f, z, bits) : dz_linear(n, f, bits);
            int y = PH - MARGIN - (int)((log10(v) - ylo) / (yhi - ylo) * (PH - 2 * MARGIN)), t;
            for (t = -1; t <= 1; t++)
                put(px, y + t, k == 0 ? 220 : 30, 30, k == 0 ? 30 : 220);
        }
    }
    for (px = MARGIN; px <= PW - MARGIN; px++) {
        put(px, PH - MARGIN, 0, 0, 0);
        put(px, MARGIN, 0, 0, 0);
    }
    for (px = MARGIN; px <= PH - MARGIN; px++) {
        put(MARGIN, px, 0, 0, 0);
        put(PW - MARGIN, px, 0, 0, 0);
    }
    if (zl_pnm_write_ppm(path, img, PW * 3, ZL_FORMAT_RGB888, PW, PH, msg, sizeof msg) != ZL_PNM_OK) {
        fprintf(stderr, "%s\n", msg);
        return 1;
    }
    printf("\nplot: %s (%dx%d; x: eye distance %g .. %g, y: dz 1e%d .. 1e%d, both log10, one grey line per "
           "decade; red pseudodepth, blue linear)\n", path, PW, PH, n, f, (int)ylo, (int)yhi);
    return 0;
}

int main(int argc, char **argv)
{
    double n = 0.1, f = 100, rz = 10, rdz = 0.01;
    int bits = 16, i, worst = 0;
    const char *plot_path = NULL;
    static const double fars[] = {10, 100, 1000, 10000};
    for (i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--near") == 0)
            n = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--far") == 0)
            f = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--bits") == 0)
            bits = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--plot") == 0)
            plot_path = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--rule-z") == 0)
            rz = atof(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--rule-dz") == 0)
            rdz = atof(argv[++i]);
        else {
            fprintf(stderr, "usage: %s [--near N] [--far F] [--bits B] [--plot FILE.ppm] [--rule-z Z] [--rule-dz DZ]\n",
                    argv[0]);
            return 2;
        }
    }
    if (!(n > 0 && f > n && f <= 32767 && bits >= 1 && bits <= 16)) {
        fprintf(stderr, "need 0 < near < far <= 32767 and 1 <= bits <= 16\n");
        return 2;
    }
    printf("Depth precision: near %g, far %g, %d-bit depth (far/near = %g)\n\n", n, f, bits, f / n);
    printf("| eye distance z | pseudodepth dz (formula) | pseudodepth dz (core, Q16.16) | dz / z | linear dz |\n");
    printf("|---:|---:|---:|---:|---:|\n");
    for (i = 0; i <= 12; i++) {
        double z = n * pow(f / n, i / 12.0), a = dz_pseudo(n, f, z, bits);
        zl_fixed c = zl_depth_resolution(fx(n), fx(f), fx(z), (unsigned)bits);
        double cd = c == ZL_FX_MAX ? INFINITY : c / 65536.0;
        printf("| %.4g | %.4g | %.4g | %.2g | %.4g |\n", z, a, cd, a / z, dz_linear(n, f, bits));
        /* The core takes Q16.16 inputs and rounds up to 1/65536: against the formula at
         * those same (rounded) inputs it must be at or above, by less than one unit. */
        {
            double aq = dz_pseudo(fx(n) / 65536.0, fx(f) / 65536.0, fx(z) / 65536.0, bits);
            if (isfinite(aq) && aq < 32767 && (cd < aq - 1e-12 || cd >= aq + 1.0 / 65536 + aq * 1e-9)) {
                fprintf(stderr, "z %g: core %.9g, formula at the Q16.16 inputs %.9g\n", z, cd, aq);
                worst = 1;
            }
        }
    }
    if (worst) {
        fprintf(stderr, "core zl_depth_resolution disagrees with the formula\n");
        return 1;
    }
    printf("\nRule of thumb for %d bits, separating %g at distance %g (units as near/far):\n\n", bits, rdz, rz);
    printf("| far plane | smallest near plane | largest far/near |\n|---:|---:|---:|\n");
    for (i = 0; i < (int)(sizeof fars / sizeof fars[0]); i++) {
        double mn = min_near(fars[i], rz, rdz, bits);
        if (fars[i] < rz || mn < 0)
            continue;
        printf("| %g | %.4g | %.0f |\n", fars[i], mn, fars[i] / mn);
    }
    {
        double limit = rz * (rz + rdz) / (rdz * (pow(2.0, bits) - 1));
        printf("\n=> pseudodepth: what decides is the near plane, not the far/near ratio: the near plane must be at\n"
               "   least z (z + dz) / (dz (2^bits - 1)) = %.4g; the far plane then hardly matters (the smallest\n"
               "   near plane above approaches this as far grows, so the allowed far/near ratio grows with far).\n",
               limit);
        printf("=> linear depth separates %g everywhere as long as far - near <= %g.\n", rdz,
               rdz * (pow(2.0, bits) - 1));
    }
    if (plot_path != NULL)
        return plot(plot_path, n, f, bits);
    return 0;
}
