/*
 * CSS colours as a fill is written: #rgb, #rrggbb, rgb(r, g, b) and the
 * basic names, so a quilt plan can choose patches by their fabric colour.
 * Names and hex digits are case-insensitive.
 */
#include <string.h>

#include "svg_internal.h"

static int lower(char c)
{
    return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

static int hex_digit(char c)
{
    c = (char)lower(c);
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

static int hex_color(const char *s, size_t n, uint32_t *rgb)
{
    uint32_t v = 0;
    size_t i;

    if (n != 3 && n != 6)
        return 0;
    for (i = 0; i < n; i++) {
        int d = hex_digit(s[i]);
        if (d < 0)
            return 0;
        v = (v << (n == 3 ? 8 : 4)) | (uint32_t)d * (n == 3 ? 17u : 1u);
    }
    *rgb = v;
    return 1;
}

/* rgb(r, g, b): three numbers 0..255 or three percentages. */
static int rgb_func(const char *s, size_t n, uint32_t *rgb)
{
    size_t i = 4, k;
    uint32_t v = 0;

    if (n < 5 || memcmp(s, "rgb(", 4) != 0 || s[n - 1] != ')')
        return 0;
    n--;
    for (k = 0; k < 3; k++) {
        double x;
        while (i < n && qc__is_space(s[i]))
            i++;
        if (!qc__scan_number(s, n, &i, &x))
            return 0;
        if (i < n && s[i] == '%') {
            x = x * 255 / 100;
            i++;
        }
        if (!(x >= 0) || x > 255)
            return 0;
        v = (v << 8) | (uint32_t)(x + 0.5);
        while (i < n && qc__is_space(s[i]))
            i++;
        if (k < 2 && (i >= n || s[i++] != ','))
            return 0;
    }
    if (i != n)
        return 0;
    *rgb = v;
    return 1;
}

int qc__svg_color(const char *s, size_t n, uint32_t *rgb)
{
    static const struct {
        const char *name;
        uint32_t rgb;
    } names[] = {{"black", 0x000000}, {"silver", 0xc0c0c0}, {"gray", 0x808080},
                 {"grey", 0x808080},  {"white", 0xffffff},  {"maroon", 0x800000},
                 {"red", 0xff0000},   {"purple", 0x800080}, {"fuchsia", 0xff00ff},
                 {"green", 0x008000}, {"lime", 0x00ff00},   {"olive", 0x808000},
                 {"yellow", 0xffff00}, {"navy", 0x000080},  {"blue", 0x0000ff},
                 {"teal", 0x008080},  {"aqua", 0x00ffff},   {"orange", 0xffa500}};
    char low[8];
    size_t i;

    while (n > 0 && qc__is_space(*s)) {
        s++;
        n--;
    }
    while (n > 0 && qc__is_space(s[n - 1]))
        n--;
    if (n > 0 && s[0] == '#')
        return hex_color(s + 1, n - 1, rgb);
    if (rgb_func(s, n, rgb))
        return 1;
    if (n >= sizeof low)
        return 0;
    for (i = 0; i < n; i++)
        low[i] = (char)lower(s[i]);
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strlen(names[i].name) == n && memcmp(low, names[i].name, n) == 0) {
            *rgb = names[i].rgb;
            return 1;
        }
    return 0;
}
