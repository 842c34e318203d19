/*
 * Outputs written whole or not at all: each under a temporary name beside
 * its file, renamed into place when every output of the command is done,
 * else removed; devices and FIFOs written in place, "-" as stdout.
 */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

static void output_abort(cli_output *out)
{
    if (out->f != NULL && out->f != stdout)
        fclose(out->f);
    if (out->tmp != NULL)
        remove(out->tmp);
    free(out->path);
    free(out->tmp);
    memset(out, 0, sizeof *out);
}

/* Where the temporary file goes: beside the file a symbolic link names, so
 * the rename replaces that file and keeps the link. NULL (and an error) for
 * a link to nothing. */
static char *publish_path(const char *path)
{
    struct stat st;
    char *p;

    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        p = realpath(path, NULL);
        if (p == NULL)
            cli_error("cannot write '%s': symbolic link to a missing file (%s)", path,
                      strerror(errno));
        return p;
    }
    p = malloc(strlen(path) + 1);
    if (p == NULL)
        cli_error("out of memory");
    else
        strcpy(p, path);
    return p;
}

/* Temporary names differ per output, so two names for one file
 * ("x.pat", "./x.pat") never share a temporary. */
static unsigned temp_seq;

static int output_open(cli_output *out, const char *path)
{
    struct stat st;

    memset(out, 0, sizeof *out);
    if (strcmp(path, "-") == 0) {
        out->f = stdout;
        return 0;
    }
    out->path = publish_path(path);
    if (out->path == NULL)
        return -1;
    /* A device, FIFO or socket is written in place: renaming a file over
     * /dev/null or a pipe would replace it. */
    if (stat(out->path, &st) == 0 && !S_ISREG(st.st_mode)) {
        out->f = fopen(out->path, "wb");
    } else {
        out->tmp = malloc(strlen(out->path) + 32);
        if (out->tmp == NULL) {
            cli_error("out of memory");
            output_abort(out);
            return -1;
        }
        sprintf(out->tmp, "%s.tmp.%ld.%u", out->path, (long)getpid(), ++temp_seq);
        out->f = fopen(out->tmp, "wb");
    }
    if (out->f == NULL) {
        cli_error("cannot write '%s': %s", path, strerror(errno));
        output_abort(out);
        return -1;
    }
    return 0;
}

int cli_output_write(void *ud, const void *data, size_t len)
{
    cli_output *out = ud;

    if (out->failed || fwrite(data, 1, len, out->f) != len) {
        out->failed = 1;
        return -1;
    }
    return 0;
}

/* Flushes, syncs and closes; the file is still under its temporary name. */
static int output_close(cli_output *out)
{
    const char *name = out->path != NULL ? out->path : "stdout";
    int err = out->failed || fflush(out->f) != 0;

    if (out->f == stdout) {
        if (err)
            cli_error("cannot write to stdout: %s", strerror(errno));
        return err ? -1 : 0;
    }
    if (!err && fsync(fileno(out->f)) != 0 && errno != EINVAL)
        err = 1;
    if (fclose(out->f) != 0)
        err = 1;
    out->f = NULL;
    if (err)
        cli_error("cannot write '%s': %s", name, strerror(errno ? errno : EIO));
    return err ? -1 : 0;
}

/* Renames a closed output into place. */
static int output_publish(cli_output *out)
{
    int err = out->tmp != NULL && rename(out->tmp, out->path) != 0;

    if (err) {
        cli_error("cannot write '%s': %s", out->path, strerror(errno));
        output_abort(out);
        return -1;
    }
    free(out->path);
    free(out->tmp);
    memset(out, 0, sizeof *out);
    return 0;
}

int cli_write_plan(qc_ctx *ctx, const char *path, int format, const qc_plan *plan,
                   const qc_io_opts *opts)
{
    return cli_write_plans(ctx, &path, &format, 1, plan, opts);
}

int cli_outputs_distinct(const char *const *paths, size_t n)
{
    size_t i, j;

    for (i = 0; i < n; i++)
        for (j = 0; j < i; j++) {
            struct stat a, b;
            int same = strcmp(paths[i], paths[j]) == 0 ||
                       (stat(paths[i], &a) == 0 && stat(paths[j], &b) == 0 &&
                        a.st_dev == b.st_dev && a.st_ino == b.st_ino && S_ISREG(a.st_mode));
            if (same) {
                cli_error("output '%s' is given twice", paths[i]);
                return CLI_USAGE;
            }
        }
    return CLI_OK;
}

/* Closes out[0..n) and renames them all into place when rc is CLI_OK and
 * every one closed cleanly; else removes them all. */
static int outputs_finish(cli_output *out, size_t n, int rc)
{
    size_t i;

    for (i = 0; i < n && rc == CLI_OK; i++) /* every one closed under its temporary name */
        if (out[i].f != NULL && output_close(&out[i]) != 0)
            rc = CLI_RUNTIME;
    for (i = 0; i < n; i++) { /* ... then all renamed into place, or none */
        if (rc == CLI_OK)
            rc = output_publish(&out[i]) == 0 ? CLI_OK : CLI_RUNTIME;
        else
            output_abort(&out[i]);
    }
    return rc;
}

int cli_write_outputs(const char *const *paths, size_t n, cli_write_one write, void *ud)
{
    cli_output out[CLI_MAX_OUTPUTS];
    size_t i, opened = 0;
    int rc = CLI_OK;

    if (n > CLI_MAX_OUTPUTS) {
        cli_error("at most %d outputs", CLI_MAX_OUTPUTS);
        return CLI_USAGE;
    }
    if (cli_outputs_distinct(paths, n) != CLI_OK)
        return CLI_USAGE;
    for (i = 0; i < n && rc == CLI_OK; i++) {
        if (output_open(&out[i], paths[i]) != 0) {
            rc = CLI_RUNTIME;
            break;
        }
        opened++;
        rc = write(ud, i, &out[i]);
    }
    return outputs_finish(out, opened, rc);
}

typedef struct plan_job {
    qc_ctx *ctx;
    const char *const *paths;
    const int *formats;
    const qc_plan *plan;
    const qc_io_opts *opts;
} plan_job;

static int write_plan_one(void *ud, size_t i, cli_output *out)
{
    const plan_job *j = ud;
    int st = qc_io_write(j->ctx, j->formats[i], j->plan, j->opts, cli_output_write, out);

    if (st == QC_EIO)
        cli_error("cannot write '%s': %s", j->paths[i], strerror(errno ? errno : EIO));
    else if (st < 0)
        cli_error("%s: %s", j->paths[i], qc_errmsg(j->ctx));
    return st < 0 ? CLI_RUNTIME : CLI_OK;
}

int cli_write_plans(qc_ctx *ctx, const char *const *paths, const int *formats, size_t n,
                    const qc_plan *plan, const qc_io_opts *opts)
{
    plan_job j;

    j.ctx = ctx;
    j.paths = paths;
    j.formats = formats;
    j.plan = plan;
    j.opts = opts;
    return cli_write_outputs(paths, n, write_plan_one, &j);
}
