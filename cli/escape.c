/*
 * Text from files on the terminal: a file name, JSON key or library message
 * may hold ESC, BEL, a newline or a UTF-8 C1 control (U+009B is CSI), which
 * a terminal would obey and a newline would split the one-line error. Each
 * is written as an escape instead; other UTF-8 passes through, and bytes
 * that are not UTF-8 are written as \xHH.
 */
#include <string.h>

#include "cli.h"

/* Length of the valid UTF-8 sequence at s (2 to 4), or 0. */
static size_t utf8_len(const unsigned char *s, unsigned long *cp)
{
    size_t n, i;
    unsigned long c;

    if (s[0] >= 0xC2 && s[0] <= 0xDF)
        n = 2, c = s[0] & 0x1Fu;
    else if (s[0] >= 0xE0 && s[0] <= 0xEF)
        n = 3, c = s[0] & 0x0Fu;
    else if (s[0] >= 0xF0 && s[0] <= 0xF4)
        n = 4, c = s[0] & 0x07u;
    else
        return 0;
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 0;
        c = (c << 6) | (s[i] & 0x3Fu);
    }
    if ((n == 3 && c < 0x800) || (n == 4 && (c < 0x10000 || c > 0x10FFFF)) ||
        (c >= 0xD800 && c <= 0xDFFF))
        return 0;
    *cp = c;
    return n;
}

void cli_put_escaped(FILE *f, const char *text)
{
    const unsigned char *s = (const unsigned char *)text;

    while (*s) {
        unsigned long cp = 0;
        size_t n;

        if (*s == '\n' || *s == '\t' || *s == '\r') {
            fputc('\\', f);
            fputc(*s == '\n' ? 'n' : *s == '\t' ? 't' : 'r', f);
            s++;
        } else if (*s < 0x20 || *s == 0x7F) {
            fprintf(f, "\\x%02X", *s++);
        } else if (*s < 0x80) {
            fputc(*s++, f);
        } else if ((n = utf8_len(s, &cp)) == 0) {
            fprintf(f, "\\x%02X", *s++);
        } else if (cp <= 0x9F) {
            fprintf(f, "\\u%04lX", cp);
            s += n;
        } else {
            fwrite(s, 1, n, f);
            s += n;
        }
    }
}
