/*
 * quiltc check FILE.pat [--region R]: the dialect linter plus the geometry a
 * quilter cares about, one finding a line; exit 0 only when sewable.
 */
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

typedef struct check_opts {
    const char *file, *region, *units;
    unsigned long long max_jumps;
    double min_seg, max_seg; /* mm; max 0 = no limit */
    int no_crossing;
    double spi; /* for the stitch count; 12 unless --spi */
} check_opts;

typedef struct tally {
    size_t findings;
} tally;

static void finding(tally *t, const char *fmt, double a, double b)
{
    printf("finding: ");
    printf(fmt, a, b);
    putchar('\n');
    t->findings++;
}

static void print_dialect(void *ud, size_t line, const char *kind, const char *text)
{
    printf("line %lu: %s: ", (unsigned long)line, kind);
    cli_put_escaped(stdout, text); /* it may quote the file */
    putchar('\n');
    ((tally *)ud)->findings++;
}

static void usage(FILE *f)
{
    fputs("usage: quiltc check FILE [options]   (FILE: .pat, .qli, .dxf, .plt, .qcc, .iqp, .bqm, .gcode, .svg)\n"
          "Reports every dialect fault and geometric problem; exit 0 when sewable.\n"
          "  --max-jumps N       needle-up moves allowed after the start (default 0); jumps\n"
          "                      with a tie-off on both sides are thread cuts, not counted\n"
          "  --min-segment LEN   shorter stitches are faults (default 0.1mm)\n"
          "  --max-segment LEN   longer stitches are faults (default: no limit)\n"
          "  --no-crossing       self-crossings are faults (loop motifs cross by design)\n"
          "  --spi N             stitches per inch for the stitch count (default 12)\n"
          "  --region R          stitches outside R are faults; also the farthest fabric\n"
          "  --units in|mm|cm    units of R and of bare lengths (default in)\n",
          f);
}

static int parse_len(const char *opt, const char *s, double mm_per_unit, double *out)
{
    double v;
    size_t n = strlen(s);
    double scale = mm_per_unit;
    char buf[64];

    if (n > 2 && n < sizeof buf && strcmp(s + n - 2, "mm") == 0)
        scale = 1.0, n -= 2;
    else if (n > 2 && n < sizeof buf && strcmp(s + n - 2, "in") == 0)
        scale = 25.4, n -= 2;
    memcpy(buf, s, n < sizeof buf ? n : sizeof buf - 1);
    buf[n < sizeof buf ? n : sizeof buf - 1] = '\0';
    if (cli_parse_double(buf, &v) != 0 || v < 0) {
        cli_error("--%s: '%s' is not a length", opt, s);
        return CLI_USAGE;
    }
    *out = v * scale;
    return CLI_OK;
}

static int parse(int argc, char **argv, check_opts *o)
{
    static const struct option opts[] = {
        {"max-jumps", required_argument, NULL, 'j'}, {"min-segment", required_argument, NULL, 's'},
        {"max-segment", required_argument, NULL, 'S'}, {"no-crossing", no_argument, NULL, 'x'},
        {"region", required_argument, NULL, 'r'}, {"units", required_argument, NULL, 'u'},
        {"spi", required_argument, NULL, 'p'},
        {"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
    const char *min_s = "0.1mm", *max_s = "0";
    int c;

    o->units = "in";
    o->spi = 12;
    optind = 1;
    opterr = 0;
    while ((c = cli_getopt(argc, argv, ":h", opts)) != -1) {
        switch (c) {
        case 'j':
            if (cli_parse_u64(optarg, &o->max_jumps) != 0) {
                cli_error("--max-jumps: '%s' is not a count", optarg);
                return CLI_USAGE;
            }
            break;
        case 's': min_s = optarg; break;
        case 'S': max_s = optarg; break;
        case 'x': o->no_crossing = 1; break;
        case 'p':
            if (cli_parse_double(optarg, &o->spi) != 0 || !(o->spi >= 1 && o->spi <= 100)) {
                cli_error("--spi: '%s' is not a number in [1, 100] stitches per inch", optarg);
                return CLI_USAGE;
            }
            break;
        case CLI_GETOPT_REPORTED: return CLI_USAGE;
        case 'r': o->region = optarg; break;
        case 'u': o->units = optarg; break;
        case 'h': usage(stdout); return -1;
        default: cli_bad_option("check", argv[optind - 1], c); return CLI_USAGE;
        }
    }
    if (cli_units_mm(o->units) == 0) {
        cli_error("--units: unknown unit '%s' (in, mm or cm)", o->units);
        return CLI_USAGE;
    }
    if (parse_len("min-segment", min_s, cli_units_mm(o->units), &o->min_seg) != CLI_OK ||
        parse_len("max-segment", max_s, cli_units_mm(o->units), &o->max_seg) != CLI_OK)
        return CLI_USAGE;
    if (optind != argc - 1) {
        cli_error("check: expected one FILE (see 'quiltc check --help')");
        return CLI_USAGE;
    }
    o->file = argv[optind];
    return CLI_OK;
}

/* Two points the same within two PAT units (each point is rounded on its
 * own, to 0.001 in in the coarsest format). */
static int same_point(qc_vec2 a, qc_vec2 b)
{
    return hypot(a.x - b.x, a.y - b.y) <= 0.06;
}

/* A tie-off: the needle goes back and forth over the same stitch, so a
 * piece [s, e) starts tied when its third point is its first again and
 * ends tied when its last point is the one two before it. quiltc's --tie 2
 * and more make both; a stray jump from a foreign file has neither. */
static int starts_tied(const qc_plan *p, size_t s, size_t e)
{
    return e - s >= 3 && !same_point(p->p[s], p->p[s + 1]) && same_point(p->p[s], p->p[s + 2]);
}

static int ends_tied(const qc_plan *p, size_t s, size_t e)
{
    return e - s >= 3 && !same_point(p->p[e - 1], p->p[e - 2]) &&
           same_point(p->p[e - 1], p->p[e - 3]);
}

/* Jumps with a tie-off on both sides: thread cuts by design, not faults. */
static size_t tied_jumps(const qc_plan *p)
{
    size_t i, s = 0, prev_s = 0, tied = 0;

    for (i = 1; i <= p->n; i++) {
        if (i < p->n && !(p->flags[i] & QC_ST_JUMP))
            continue;
        /* piece [s, i) ends here; the jump into it came after [prev_s, s) */
        if (s > 0 && ends_tied(p, prev_s, s) && starts_tied(p, s, i))
            tied++;
        prev_s = s;
        s = i;
    }
    return tied;
}

/* Jumps, length, box and segment lengths of the sewn pieces. */
static void measure(const check_opts *o, const qc_plan *p, tally *t)
{
    size_t i, jumps = 0, segs = 0, tied;
    double len = 0, shortest = HUGE_VAL, longest = 0;
    qc_plan_estimate est;
    qc_bbox b;

    b.min = b.max = p->p[0];
    for (i = 0; i < p->n; i++) {
        b.min.x = fmin(b.min.x, p->p[i].x);
        b.min.y = fmin(b.min.y, p->p[i].y);
        b.max.x = fmax(b.max.x, p->p[i].x);
        b.max.y = fmax(b.max.y, p->p[i].y);
        if (i == 0)
            continue;
        if (p->flags[i] & QC_ST_JUMP) {
            jumps++;
        } else {
            double s = hypot(p->p[i].x - p->p[i - 1].x, p->p[i].y - p->p[i - 1].y);
            len += s;
            segs++;
            shortest = fmin(shortest, s);
            longest = fmax(longest, s);
            if (s < o->min_seg)
                finding(t, "segment of %.3f mm shorter than %.3f mm", s, o->min_seg);
            if (o->max_seg > 0 && s > o->max_seg)
                finding(t, "segment of %.3f mm longer than %.3f mm", s, o->max_seg);
        }
    }
    /* stitches as --stats counts them: the sewn length at spi */
    qc_plan_estimate_get(p, o->spi, 0, &est);
    printf("points: %lu, segments: %lu, jumps: %lu\n", (unsigned long)p->n, (unsigned long)segs,
           (unsigned long)jumps);
    printf("stitches: %lu at %g spi\n", (unsigned long)est.stitches, o->spi);
    printf("length: %.1f mm (%.2f in)\n", len, len / 25.4);
    printf("bbox: %.3f %.3f %.3f %.3f in\n", b.min.x / 25.4, b.min.y / 25.4, b.max.x / 25.4,
           b.max.y / 25.4);
    if (segs > 0)
        printf("segment lengths: %.3f .. %.3f mm\n", shortest, longest);
    tied = tied_jumps(p);
    if (tied > 0)
        printf("thread cuts (jumps with a tie-off on both sides): %lu\n", (unsigned long)tied);
    if (jumps - tied > o->max_jumps)
        finding(t, "%.0f jumps (needle-up moves) without a tie-off on both sides, more than %.0f "
                "allowed", (double)(jumps - tied), (double)o->max_jumps);
}

static int crossings(qc_ctx *ctx, const check_opts *o, const qc_plan *p, tally *t)
{
    size_t n = 0;

    if (qc_path_self_crossings(ctx, p->p, p->n, 0, &n) < 0)
        return cli_fail(ctx, o->file, ctx->status);
    printf("self-crossings: %lu\n", (unsigned long)n);
    if (o->no_crossing && n > 0)
        finding(t, "%.0f self-crossings (--no-crossing)", (double)n, 0);
    return CLI_OK;
}

/* How a line names a patch: its id, else its element number and line. */
static void patch_name(const qc_patch *p, size_t i, char *buf, size_t size)
{
    if (p->id[0] != '\0')
        snprintf(buf, size, "patch %lu (id \"%s\")", (unsigned long)i + 1, p->id);
    else
        snprintf(buf, size, "patch %lu (line %lu)", (unsigned long)i + 1, p->line);
}

/* A top's figures patch by patch: the farthest any of its fabric lies
 * from a stitch (whichever patch's) and its largest unquilted gap. */
static int per_patch(qc_ctx *ctx, const check_opts *o, const qc_plan *p, const qc_order *ends,
                     const qc_patches *ps, double mpu)
{
    size_t i;
    char name[160];

    for (i = 0; i < ps->n; i++) {
        qc_fabric f;
        double gap;
        int rc = qc_fabric_measure(ctx, &ps->p[i].region, p->p, p->n, ends->i, ends->n, 0.5, 0,
                                   NULL, &f);

        if (rc < 0)
            return rc;
        gap = qc_largest_gap(ctx, &ps->p[i].region, p->p, p->n, 0.5, NULL);
        if (gap < 0)
            return (int)gap;
        patch_name(&ps->p[i], i, name, sizeof name);
        printf("%s: farthest fabric %.1f mm (%.3f %s), largest gap %.1f mm radius\n", name,
               f.farthest_mm, f.farthest_mm / mpu, o->units, gap);
    }
    return QC_OK;
}

/* Outside (segments sampled along their length, 0.02 in tolerance), the
 * farthest fabric from a stitch and the largest empty circle; for a top
 * of several patches, each patch's too. */
static int against_region(qc_ctx *ctx, const check_opts *o, const qc_plan *p, tally *t)
{
    qc_region r;
    qc_patches ps;
    qc_order ends = {0};
    qc_fabric f;
    size_t i, outside = 0;
    double gap = 0, worst = 0, mpu = cli_units_mm(o->units);
    int rc = cli_load_top_patches(ctx, o->region, mpu, &r, &ps);

    if (rc != CLI_OK)
        return rc;
    for (i = 1; i <= p->n && rc == QC_OK; i++) /* a jump starts a new sewn piece */
        if (i == p->n || (p->flags[i] & QC_ST_JUMP))
            rc = qc_order_push(ctx, &ends, (uint32_t)i);
    if (rc == QC_OK)
        rc = qc_path_outside(ctx, &r, p->p, p->n, ends.i, ends.n, 0.02 * 25.4, 0, &outside,
                             &worst, NULL);
    if (rc == QC_OK)
        rc = qc_fabric_measure(ctx, &r, p->p, p->n, ends.i, ends.n, 0.5, 0, NULL, &f);
    if (rc == QC_OK)
        gap = qc_largest_gap(ctx, &r, p->p, p->n, 0.5, NULL);
    if (rc == QC_OK && gap < 0)
        rc = (int)gap;
    if (rc == QC_OK) {
        if (outside > 0)
            finding(t, "%.0f segments outside the region, up to %.3f mm beyond it (0.02 in "
                    "allowed)", (double)outside, worst);
        printf("farthest fabric from a stitch: %.1f mm (%.3f %s)\n", f.farthest_mm,
               f.farthest_mm / mpu, o->units);
        printf("seam farther than 1/4 in from a stitch: %.1f%%\n", 100.0 * f.seam_bare);
        printf("largest unquilted gap: %.1f mm radius\n", gap);
        if (ps.n > 1)
            rc = per_patch(ctx, o, p, &ends, &ps, mpu);
    }
    qc_region_free(ctx, &r);
    qc_patches_free(ctx, &ps);
    qc_order_free(ctx, &ends);
    if (rc < 0)
        return cli_fail(ctx, o->file, rc);
    return CLI_OK;
}

/* A .pat gets the dialect linter (every fault, then the points it could
 * read); any other format quiltc writes is read strictly (its first fault
 * is the one finding); an unknown extension is refused. */
static int read_pattern(qc_ctx *ctx, const check_opts *o, const char *buf, size_t len,
                        tally *t, qc_plan *plan, size_t *dialect)
{
    int fmt = qc_format_from_name(o->file);

    if (fmt == QC_FORMAT_PAT)
        return qc_io_check_pat(ctx, buf, len, print_dialect, t, plan, dialect) < 0
                   ? cli_fail(ctx, o->file, ctx->status)
                   : CLI_OK;
    if (qc_io_read(ctx, fmt, buf, len, plan) < 0) {
        if (ctx->status == QC_EFORMAT || ctx->status == QC_ERANGE || ctx->status == QC_EEMPTY) {
            printf("%s\n", qc_errmsg(ctx));
            t->findings++;
            return CLI_OK;
        }
        return cli_fail(ctx, o->file, ctx->status);
    }
    return CLI_OK;
}

int cmd_check(int argc, char **argv)
{
    check_opts o;
    qc_ctx ctx;
    qc_plan plan = {0};
    tally t = {0};
    char *buf;
    size_t len, dialect = 0;
    int rc;

    memset(&o, 0, sizeof o);
    rc = parse(argc, argv, &o);
    if (rc != CLI_OK)
        return rc < 0 ? CLI_OK : rc;
    if (cli_read_file(o.file, (size_t)256 << 20, &buf, &len) != 0)
        return CLI_RUNTIME;
    if (qc_format_from_name(o.file) < 0) {
        free(buf);
        cli_error("check: '%s': cannot read this format (pat, qli, dxf, plt, qcc, iqp, bqm, "
                  "gcode, svg)", o.file);
        return CLI_USAGE;
    }
    qc_ctx_init(&ctx, NULL, NULL);
    rc = read_pattern(&ctx, &o, buf, len, &t, &plan, &dialect);
    free(buf);
    if (rc == CLI_OK && plan.n > 0) {
        measure(&o, &plan, &t);
        rc = crossings(&ctx, &o, &plan, &t);
        if (rc == CLI_OK && o.region != NULL)
            rc = against_region(&ctx, &o, &plan, &t);
    } else if (rc == CLI_OK) {
        finding(&t, "no stitches in the file", 0, 0);
    }
    qc_plan_free(&ctx, &plan);
    if (rc != CLI_OK)
        return rc;
    if (dialect > t.findings)
        t.findings = dialect;
    cli_put_escaped(stdout, o.file);
    printf(": %lu finding%s: %s\n", (unsigned long)t.findings,
           t.findings == 1 ? "" : "s", t.findings ? "not sewable" : "sewable");
    return t.findings == 0 ? CLI_OK : CLI_RUNTIME;
}
