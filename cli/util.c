/* CLI helpers: errors, whole-file reads, strict numbers, the clock. */
#define _XOPEN_SOURCE 700 /* fdopen, fcntl */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"

/* The whole message is formatted first, then written with its control
 * characters escaped (escape.c): names and keys come from files. */
void cli_error(const char *fmt, ...)
{
    char small[1024], *msg = small;
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n >= (int)sizeof small && (msg = malloc((size_t)n + 1)) != NULL) {
        va_start(ap, fmt);
        vsnprintf(msg, (size_t)n + 1, fmt, ap);
        va_end(ap);
    }
    fputs("quiltc: ", stderr);
    cli_put_escaped(stderr, msg != NULL ? msg : small);
    fputc('\n', stderr);
    if (msg != small)
        free(msg);
}

void cli_warn_file(void *ud, const char *text)
{
    cli_error("%s: warning: %s", (const char *)ud, text);
}

void cli_svg_opts(qc_svg_opts *opts, const char *path, size_t max_bytes)
{
    memset(opts, 0, sizeof *opts);
    opts->max_bytes = max_bytes;
    opts->warn = cli_warn_file;
    opts->warn_ud = (void *)(uintptr_t)path; /* only read back as const char * */
}

int cli_fail(const qc_ctx *ctx, const char *what, int status)
{
    const char *msg = qc_errmsg(ctx);

    cli_error("%s: %s", what, msg[0] != '\0' ? msg : qc_strerror(status));
    return status == QC_ERANGE || status == QC_EINVAL ? CLI_USAGE : CLI_RUNTIME;
}

void cli_bad_option(const char *command, const char *arg, int c)
{
    cli_error("%s: %s '%s' (see 'quiltc %s --help')", command,
              c == ':' ? "missing value for" : "unknown option", arg, command);
}

/* Opens a regular file of at most max bytes for reading. A FIFO would
 * block forever and a device never end, so both are refused before any
 * read (O_NONBLOCK: opening a FIFO with no writer does not wait); the size
 * is checked before reading, so a 2 GB sparse file costs nothing. */
static FILE *open_regular(const char *path, size_t max)
{
    struct stat st;
    FILE *f;
    int fd = open(path, O_RDONLY | O_NONBLOCK);

    if (fd < 0) {
        cli_error("cannot open '%s': %s", path, strerror(errno));
        return NULL;
    }
    if (fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
        cli_error("cannot read '%s': %s", path, S_ISDIR(st.st_mode) ? strerror(EISDIR)
                                                                   : strerror(errno));
        close(fd);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        cli_error("'%s' is not a regular file (a FIFO or device is not read)", path);
        close(fd);
        return NULL;
    }
    if ((unsigned long long)st.st_size > (unsigned long long)max) {
        cli_error("'%s' is larger than %lu bytes", path, (unsigned long)max);
        close(fd);
        return NULL;
    }
    if (fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) != 0 ||
        (f = fdopen(fd, "rb")) == NULL) {
        cli_error("cannot open '%s': %s", path, strerror(errno));
        close(fd);
        return NULL;
    }
    return f;
}

int cli_read_file(const char *path, size_t max, char **buf, size_t *len)
{
    FILE *f = open_regular(path, max);
    char *b = NULL;
    size_t n = 0, cap = 0;

    if (f == NULL)
        return -1;
    for (;;) {
        size_t got;

        if (n + 1 >= cap) {
            char *nb;

            cap = cap ? cap * 2 : 65536;
            nb = realloc(b, cap);
            if (nb == NULL) {
                cli_error("out of memory reading '%s'", path);
                goto fail;
            }
            b = nb;
        }
        got = fread(b + n, 1, cap - n - 1, f);
        n += got;
        if (n > max) {
            cli_error("'%s' is larger than %lu bytes", path, (unsigned long)max);
            goto fail;
        }
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        cli_error("cannot read '%s': %s", path, strerror(errno));
        goto fail;
    }
    fclose(f);
    b[n] = '\0';
    *buf = b;
    *len = n;
    return 0;
fail:
    free(b);
    fclose(f);
    return -1;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    double v;

    if (s == NULL || *s == '\0')
        return -1;
    errno = 0;
    v = strtod(s, &end);
    if (*end != '\0' || errno == ERANGE || !isfinite(v))
        return -1;
    /* strtod also takes "nan", "inf" and hex floats: only plain decimals here */
    if (strpbrk(s, "nNiIxXpP") != NULL)
        return -1;
    *out = v;
    return 0;
}

int cli_parse_u64(const char *s, unsigned long long *out)
{
    char *end;
    unsigned long long v;

    if (s == NULL || *s < '0' || *s > '9')
        return -1;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (*end != '\0' || errno == ERANGE)
        return -1;
    *out = v;
    return 0;
}

const char *cli_units_name(double mm_per_unit)
{
    return mm_per_unit == 25.4 ? "in" : mm_per_unit == 10.0 ? "cm" : "mm";
}

double cli_units_mm(const char *units)
{
    if (strcmp(units, "in") == 0 || strcmp(units, "inch") == 0 || strcmp(units, "inches") == 0)
        return 25.4;
    if (strcmp(units, "mm") == 0)
        return 1.0;
    if (strcmp(units, "cm") == 0)
        return 10.0;
    return 0.0;
}

double cli_now_ms(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}
