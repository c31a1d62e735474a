/*
 * zline-img2c: turn an image into a C source of a const texture for
 * firmware, plus its header. The image is read and converted by the host
 * port's port/host/zl_image.h, the same code zline-render --texture uses, so
 * the texels are identical on the host and on the target:
 *
 *   #define NAME_WIDTH, NAME_HEIGHT   the size (any 1 .. 4096)
 *   #define NAME_FORMAT               ZL_TEXEL_RGB565 or ZL_TEXEL_RGBA4444
 *   #define NAME_POW2                 1 when both sides are powers of two
 *                                     (the fast texture loop)
 *   const uint16_t   NAME_texels[NAME_WIDTH * NAME_HEIGHT];  row by row
 *   const zl_texture NAME_texture;    views them (stride = width), wrap
 *                                     repeat (or --clamp) on both axes
 *
 * All const, so on a microcontroller they stay in flash.
 *
 *   zline-img2c [--format rgb565|rgba4444] [--alpha MASK.pgm] [--clamp]
 *               [--name NAME] IN.ppm|IN.pgm|IN.png OUT.c OUT.h
 *
 * --format    texel format; default rgb565 (an image's alpha is then
 *             dropped, with a note on stderr when it had any)
 * --alpha     a PGM of the same size as the image's alpha (pngtopnm -alpha)
 * --name      prefix of the symbols, a C identifier (default: the image's
 *             file name without extension, non-identifier characters as _)
 * A bad image gives "zline-img2c: FILE: what is wrong" and writes nothing.
 * Exit status 0 on success, 1 on a bad image or output error, 2 on usage.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_image.h"

static void usage(void)
{
    fprintf(stderr, "usage: zline-img2c [--format rgb565|rgba4444] [--alpha MASK.pgm] [--clamp] [--name NAME] "
                    "IN.ppm|IN.pgm|IN.png OUT.c OUT.h\n");
    exit(2);
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    const char *b = strrchr(path, '\\');
    if (b != NULL && (s == NULL || b > s))
        s = b;
    return s ? s + 1 : path;
}

static void name_from_path(const char *path, char *out, size_t size)
{
    const char *b = base_name(path);
    size_t i = 0;
    if (!isalpha((unsigned char)*b) && *b != '_' && i + 1 < size)
        out[i++] = 't';
    for (; *b != '\0' && *b != '.' && i + 1 < size; b++)
        out[i++] = (isalnum((unsigned char)*b) || *b == '_') ? *b : '_';
    out[i] = '\0';
}

static int is_identifier(const char *s)
{
    if (!isalpha((unsigned char)*s) && *s != '_')
        return 0;
    for (; *s != '\0'; s++)
        if (!isalnum((unsigned char)*s) && *s != '_')
            return 0;
    return 1;
}

static int pow2(uint32_t n)
{
    return n != 0 && (n & (n - 1u)) == 0;
}

int main(int argc, char **argv)
{
    zl_image img;
    zl_texel_format format = ZL_TEXEL_RGB565;
    char msg[1024], name[128], upper[128];
    const char *in, *out_c, *out_h, *given_name = NULL, *alpha = NULL, *wrap = "ZL_WRAP_REPEAT";
    uint16_t *texels;
    size_t k, n;
    int i, ok;
    FILE *fc, *fh;

    for (i = 1; i < argc && argv[i][0] == '-' && argv[i][1] == '-'; i++) {
        if (strcmp(argv[i], "--format") == 0 && i + 1 < argc) {
            i++;
            if (strcmp(argv[i], "rgb565") == 0)
                format = ZL_TEXEL_RGB565;
            else if (strcmp(argv[i], "rgba4444") == 0)
                format = ZL_TEXEL_RGBA4444;
            else
                usage();
        } else if (strcmp(argv[i], "--alpha") == 0 && i + 1 < argc) {
            alpha = argv[++i];
        } else if (strcmp(argv[i], "--clamp") == 0) {
            wrap = "ZL_WRAP_CLAMP";
        } else if (strcmp(argv[i], "--name") == 0 && i + 1 < argc) {
            given_name = argv[++i];
        } else {
            usage();
        }
    }
    if (argc - i != 3)
        usage();
    in = argv[i];
    out_c = argv[i + 1];
    out_h = argv[i + 2];
    if (given_name != NULL) {
        if (strlen(given_name) >= sizeof name - 32 || !is_identifier(given_name)) {
            fprintf(stderr, "zline-img2c: --name '%s' is not a C identifier (or too long)\n", given_name);
            return 2;
        }
        strcpy(name, given_name);
    } else {
        name_from_path(in, name, sizeof name - 32);
    }
    for (k = 0; name[k] != '\0'; k++)
        upper[k] = (char)toupper((unsigned char)name[k]);
    upper[k] = '\0';

    /* Everything is read and converted before a file is opened for writing. */
    if (zl_image_load(&img, in, alpha, msg, sizeof msg) != 0) {
        fprintf(stderr, "zline-img2c: %s\n", msg);
        return 1;
    }
    if (img.has_alpha && format == ZL_TEXEL_RGB565)
        fprintf(stderr, "zline-img2c: note: %s has alpha, which rgb565 drops (--format rgba4444 keeps it)\n", in);
    n = (size_t)img.width * img.height;
    texels = (uint16_t *)malloc(n * sizeof *texels);
    if (texels == NULL) {
        fprintf(stderr, "zline-img2c: %s: out of memory\n", in);
        zl_image_free(&img);
        return 1;
    }
    zl_image_texels(&img, format, texels);

    fh = fopen(out_h, "w");
    fc = fh != NULL ? fopen(out_c, "w") : NULL;
    if (fh == NULL || fc == NULL) {
        fprintf(stderr, "zline-img2c: cannot write %s\n", fh == NULL ? out_h : out_c);
        if (fh != NULL) {
            fclose(fh);
            remove(out_h);
        }
        free(texels);
        zl_image_free(&img);
        return 1;
    }
    fprintf(fh, "/* Generated by zline-img2c from %s: do not edit. */\n", base_name(in));
    fprintf(fh, "#ifndef %s_TEXTURE_H\n#define %s_TEXTURE_H\n\n#include <stdint.h>\n\n#include \"zline/zline.h\"\n\n",
            upper, upper);
    fprintf(fh, "#define %s_WIDTH %luu\n#define %s_HEIGHT %luu\n", upper, (unsigned long)img.width, upper,
            (unsigned long)img.height);
    fprintf(fh, "#define %s_FORMAT %s\n", upper, format == ZL_TEXEL_RGBA4444 ? "ZL_TEXEL_RGBA4444" : "ZL_TEXEL_RGB565");
    fprintf(fh, "#define %s_POW2 %d\n\n", upper, pow2(img.width) && pow2(img.height));
    fprintf(fh, "/* %s texels, row by row, top row first */\n",
            format == ZL_TEXEL_RGBA4444 ? "RGBA4444 (r in bits 15..12, alpha in 3..0)" : "RGB565");
    fprintf(fh, "extern const uint16_t %s_texels[%s_WIDTH * %s_HEIGHT];\n", name, upper, upper);
    fprintf(fh, "/* The texture viewing them (%s on both axes). */\n", wrap);
    fprintf(fh, "extern const zl_texture %s_texture;\n\n#endif\n", name);

    fprintf(fc, "/* Generated by zline-img2c from %s: %lux%lu. Do not edit. */\n", base_name(in),
            (unsigned long)img.width, (unsigned long)img.height);
    fprintf(fc, "#include \"%s\"\n\n", base_name(out_h));
    fprintf(fc, "const uint16_t %s_texels[%s_WIDTH * %s_HEIGHT] = {\n", name, upper, upper);
    for (k = 0; k < n; k++)
        fprintf(fc, "%s0x%04X,%s", k % 12 == 0 ? "    " : "", (unsigned)texels[k],
                (k % 12 == 11 || k + 1 == n) ? "\n" : " ");
    fputs("};\n", fc);
    fprintf(fc,
            "\nconst zl_texture %s_texture = {\n    .texels = %s_texels,\n    .width = %s_WIDTH,\n"
            "    .height = %s_HEIGHT,\n    .stride = %s_WIDTH,\n    .wrap_s = %s,\n    .wrap_t = %s,\n"
            "    .format = %s_FORMAT,\n};\n",
            name, name, upper, upper, upper, wrap, wrap, upper);
    ok = !ferror(fc) && !ferror(fh);
    ok = (fclose(fc) == 0) && ok;
    ok = (fclose(fh) == 0) && ok;
    free(texels);
    zl_image_free(&img);
    if (!ok) {
        fprintf(stderr, "zline-img2c: error writing %s or %s\n", out_c, out_h);
        remove(out_c);
        remove(out_h);
        return 1;
    }
    return 0;
}
