/*
 * The core's one decimal number reader (SVG, point files, shape specs):
 * [+-] digits [. digits] [(e|E) [+-] digits], no hex, no nan/inf, and no
 * locale: strtod would read "8.5" as 8 under a decimal-comma locale. The
 * value is correctly rounded: exactly in one operation when it has at most
 * 15 significant digits and |exponent| <= 22, else by strtod on a
 * "<digits>e<exponent>" string, which holds no decimal point for a locale
 * to misread.
 */
#include <stdlib.h>

#include "internal.h"

#define KEPT_DIGITS 128 /* significant digits kept; later ones only scale */

static const double pow10_exact[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* digits[0..nd) (no leading zero) times 10^exp10, correctly rounded. */
static double convert(char *digits, size_t nd, long exp10)
{
    if (nd == 0)
        return 0.0;
    if (nd <= 15 && exp10 >= -22 && exp10 <= 22) {
        uint64_t mant = 0;
        size_t i;

        for (i = 0; i < nd; i++)
            mant = mant * 10 + (uint64_t)(digits[i] - '0');
        return exp10 >= 0 ? (double)mant * pow10_exact[exp10]
                          : (double)mant / pow10_exact[-exp10];
    } else {
        long x = exp10 < 0 ? -exp10 : exp10;
        char tmp[16];
        size_t w = nd, k = 0;

        if (x > 999999)
            x = 999999;
        digits[w++] = 'e';
        if (exp10 < 0)
            digits[w++] = '-';
        do {
            tmp[k++] = (char)('0' + x % 10);
            x /= 10;
        } while (x > 0);
        while (k > 0)
            digits[w++] = tmp[--k];
        digits[w] = '\0';
        return strtod(digits, NULL);
    }
}

int qc__scan_number(const char *s, size_t n, size_t *pos, double *v)
{
    char digits[KEPT_DIGITS + 16];
    size_t i = *pos, nd = 0, seen = 0;
    long exp10 = 0;
    int neg = 0;
    double r;

    if (i < n && (s[i] == '+' || s[i] == '-'))
        neg = s[i++] == '-';
    for (; i < n && is_digit(s[i]); i++, seen++)
        if (nd > 0 || s[i] != '0') {
            if (nd < KEPT_DIGITS)
                digits[nd++] = s[i];
            else
                exp10++;
        }
    if (i < n && s[i] == '.' && (seen > 0 || (i + 1 < n && is_digit(s[i + 1])))) {
        for (i++; i < n && is_digit(s[i]); i++, seen++)
            if (nd > 0 || s[i] != '0') {
                if (nd < KEPT_DIGITS) {
                    digits[nd++] = s[i];
                    exp10--;
                }
            } else {
                exp10--;
            }
    }
    if (seen == 0)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        int eneg = 0;
        long e = 0;

        if (j < n && (s[j] == '+' || s[j] == '-'))
            eneg = s[j++] == '-';
        if (j < n && is_digit(s[j])) { /* else the 'e' is not part of the number */
            for (; j < n && is_digit(s[j]); j++)
                if (e < 100000)
                    e = e * 10 + (s[j] - '0');
            exp10 += eneg ? -e : e;
            i = j;
        }
    }
    r = convert(digits, nd, exp10);
    *v = neg ? -r : r;
    *pos = i;
    return 1;
}
