/* generate's placement, stitch and estimate options (machine_opts.h). */
#include <math.h>
#include <string.h>

#include "machine_opts.h"

#define RAW(m, id) ((m)->raw[(id) - CLI_MACH_BASE])
#define YARD_MM 914.4

int cli_machine_take(cli_machine_opts *m, int opt, const char *arg)
{
    if (opt == CLI_MACH_CLIP) {
        m->clip = 1;
        return 1;
    }
    if (opt == CLI_MACH_SPLIT) {
        m->split = 1;
        return 1;
    }
    if (opt < CLI_MACH_BASE || opt > CLI_MACH_PEN_DOWN)
        return 0;
    RAW(m, opt) = arg;
    return 1;
}

/* A length option within [lo, hi] mm; the message speaks the user's units. */
static int length_in(const char *opt, const char *s, double mpu, double lo, double hi,
                     double *mm)
{
    int rc = cli_parse_length(s, mpu, mm);

    if (rc != 0) {
        cli_error("--%s: '%s' is not a length (a number, optionally with mm, cm or in)", opt, s);
        return CLI_USAGE;
    }
    if (!(*mm >= lo && *mm <= hi)) {
        char name[32];
        snprintf(name, sizeof name, "--%s", opt);
        cli_length_range(name, *mm, lo, hi, mpu);
        return CLI_USAGE;
    }
    return CLI_OK;
}

static int number_in(const char *opt, const char *s, double lo, double hi, const char *unit,
                     double *v)
{
    if (cli_parse_double(s, v) != 0 || !(*v >= lo && *v <= hi)) {
        cli_error("--%s: '%s' is not a number in [%g, %g]%s%s", opt, s, lo, hi,
                  unit[0] ? " " : "", unit);
        return CLI_USAGE;
    }
    return CLI_OK;
}

/* --at X,Y: two lengths. */
static int take_at(cli_machine_opts *m, const char *s, double mpu)
{
    const char *comma = strchr(s, ',');
    char x[64];
    double at[2];

    if (comma == NULL || (size_t)(comma - s) >= sizeof x) {
        cli_error("--at: '%s' is not X,Y (e.g. --at 2,3.5)", s);
        return CLI_USAGE;
    }
    memcpy(x, s, (size_t)(comma - s));
    x[comma - s] = '\0';
    if (length_in("at", x, mpu, -1e5, 1e5, &at[0]) != CLI_OK ||
        length_in("at", comma + 1, mpu, -1e5, 1e5, &at[1]) != CLI_OK)
        return CLI_USAGE;
    m->place.at.x = at[0];
    m->place.at.y = at[1];
    return CLI_OK;
}

static int take_place(cli_machine_opts *m, double mpu)
{
    const char *mir = RAW(m, CLI_MACH_MIRROR);

    if (RAW(m, CLI_MACH_ROTATE) != NULL &&
        number_in("rotate", RAW(m, CLI_MACH_ROTATE), -360, 360, "degrees",
                  &m->place.rotate_deg) != CLI_OK)
        return CLI_USAGE;
    if (mir != NULL) {
        if (strcmp(mir, "x") == 0)
            m->place.mirror = QC_MIRROR_X;
        else if (strcmp(mir, "y") == 0)
            m->place.mirror = QC_MIRROR_Y;
        else if (strcmp(mir, "xy") == 0)
            m->place.mirror = QC_MIRROR_X | QC_MIRROR_Y;
        else {
            cli_error("--mirror: '%s' is not x (left-right), y (upside down) or xy", mir);
            return CLI_USAGE;
        }
    }
    if (RAW(m, CLI_MACH_AT) != NULL && take_at(m, RAW(m, CLI_MACH_AT), mpu) != CLI_OK)
        return CLI_USAGE;
    m->placed = RAW(m, CLI_MACH_ROTATE) != NULL || mir != NULL || RAW(m, CLI_MACH_AT) != NULL;
    return CLI_OK;
}

/* A pen command: one line of printable text (it goes into the G-code as is). */
static int pen_command(const char *opt, const char *s)
{
    size_t i, n = strlen(s);

    for (i = 0; i < n; i++)
        if ((unsigned char)s[i] < 0x20 || (unsigned char)s[i] > 0x7e)
            break;
    if (i < n || n > 64) {
        cli_error("--%s: expected one line of at most 64 printable ASCII characters", opt);
        return CLI_USAGE;
    }
    return CLI_OK;
}

int cli_machine_finish(cli_machine_opts *m, double mpu)
{
    const char *spi = RAW(m, CLI_MACH_SPI), *len = RAW(m, CLI_MACH_STITCH_LEN);
    double v;

    m->spi = 12;
    m->speed_mm_s = 25.4;
    if (take_place(m, mpu) != CLI_OK)
        return CLI_USAGE;
    if (spi != NULL && len != NULL) {
        cli_error("--spi and --stitch-length say the same thing: give one");
        return CLI_USAGE;
    }
    if (spi != NULL && number_in("spi", spi, 1, 100, "stitches per inch", &m->spi) != CLI_OK)
        return CLI_USAGE;
    if (len != NULL) {
        if (length_in("stitch-length", len, mpu, 0.254, 25.4, &v) != CLI_OK)
            return CLI_USAGE;
        m->spi = 25.4 / v;
    }
    if (RAW(m, CLI_MACH_SPEED) != NULL) { /* a length per second */
        const char *u = cli_units_name(mpu);
        if (cli_parse_length(RAW(m, CLI_MACH_SPEED), mpu, &v) != 0 || !(v >= 1 && v <= 2000)) {
            cli_error("--speed: '%s' is not a sewing speed in [%g, %g] %s/s",
                      RAW(m, CLI_MACH_SPEED), 1 / mpu, 2000 / mpu, u);
            return CLI_USAGE;
        }
        m->speed_mm_s = v;
    }
    if (RAW(m, CLI_MACH_TIE_LEN) != NULL &&
        length_in("tie-length", RAW(m, CLI_MACH_TIE_LEN), mpu, 0.01, 100,
                  &m->tie_length_mm) != CLI_OK)
        return CLI_USAGE;
    if (RAW(m, CLI_MACH_BOBBIN) != NULL) {
        if (number_in("bobbin-yards", RAW(m, CLI_MACH_BOBBIN), 1, 10000, "yd", &v) != CLI_OK)
            return CLI_USAGE;
        m->bobbin_mm = v * YARD_MM;
    }
    if ((RAW(m, CLI_MACH_PEN_UP) != NULL && pen_command("pen-up", RAW(m, CLI_MACH_PEN_UP))) ||
        (RAW(m, CLI_MACH_PEN_DOWN) != NULL &&
         pen_command("pen-down", RAW(m, CLI_MACH_PEN_DOWN))))
        return CLI_USAGE;
    return CLI_OK;
}

void cli_machine_stitch_params(const cli_machine_opts *m, qc_stitch_params *sp)
{
    memset(sp, 0, sizeof *sp);
    sp->tie_length = m->tie_length_mm;
    sp->clip = m->clip;
    if (m->split) {
        sp->max_segment = 25.4 / m->spi;
        /* the default merge (0.02 in) stays below one stitch up to 50 spi */
        sp->min_segment = fmin(0.508, sp->max_segment / 2);
    }
}

void cli_machine_help(FILE *f)
{
    fputs("Placing the block (after generating; lengths in --units):\n"
          "  --mirror x|y|xy          mirror image: x left-right, y upside down\n"
          "  --rotate DEG             turn counter-clockwise, after the mirror\n"
          "  --at X,Y                 put the outline's lower-left corner at X,Y (default 0,0)\n"
          "  --clip                   crop the pattern at the outline (the seam)\n"
          "Stitches and estimates:\n"
          "  --spi N                  stitches per inch for the stitch count (default 12)\n"
          "  --stitch-length LEN      the same as a length (--spi 12 = 0.0833in)\n"
          "  --split-stitches         no stitch longer than that: long lines split into\n"
          "                           equal stitches (machines without a stitch regulator)\n"
          "  --speed LEN              sewing speed, per second (default 1in)\n"
          "  --tie-length LEN         length of one tie-off stitch (default 0.5mm)\n"
          "  --bobbin-yards N         bobbin capacity: adds the bobbins needed\n"
          "G-code for pen plotters (jumps lift the pen):\n"
          "  --pen-up CMD             before each jump (default 'G0 Z5'; '' for none)\n"
          "  --pen-down CMD           after each jump (default 'G1 Z0'; '' for none)\n",
          f);
}
