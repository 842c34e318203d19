/*
 * Outputs written whole or not at all: each under a temporary name beside
 * its file, renamed into place when every output of the command is done,
 * else removed; devices and FIFOs written in place, "-" as stdout.
 * Temporary files are made exclusively under an unpredictable name
 * (mkstemp: a planted link is never followed), take the permission bits of
 * the file they replace, and are removed on SIGINT, SIGTERM and SIGHUP.
 */
#define _XOPEN_SOURCE 700 /* realpath, mkstemp, sigaction */
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* Bytes of each output file's stdio buffer. */
#define OUTPUT_BUF ((size_t)1 << 20)

/* The temporary files a signal removes: set and cleared with the signals
 * blocked, read by the handler, which only unlinks and re-raises. */
static char *volatile pending[CLI_MAX_OUTPUTS];

static void on_signal(int sig)
{
    size_t i;

    for (i = 0; i < CLI_MAX_OUTPUTS; i++)
        if (pending[i] != NULL)
            unlink(pending[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void block_signals(sigset_t *old)
{
    sigset_t set;

    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    sigprocmask(SIG_BLOCK, &set, old);
}

static void catch_signals(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    static int done;
    struct sigaction sa, was;
    size_t i;

    if (done++)
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (i = 0; i < sizeof sigs / sizeof sigs[0]; i++)
        if (sigaction(sigs[i], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
            sigaction(sigs[i], &sa, NULL); /* nohup's ignored SIGHUP stays ignored */
}

/* Puts tmp on (or, when NULL, takes old off) the list a signal removes. */
static void track(char *tmp, const char *old)
{
    size_t i;

    for (i = 0; i < CLI_MAX_OUTPUTS; i++)
        if (tmp != NULL ? pending[i] == NULL : pending[i] == old) {
            pending[i] = tmp;
            return;
        }
}

static void output_abort(cli_output *out)
{
    sigset_t old;

    if (out->f != NULL && out->f != stdout)
        fclose(out->f);
    free(out->buf); /* after the close, which flushes into it */
    block_signals(&old);
    if (out->tmp != NULL) {
        remove(out->tmp);
        track(NULL, out->tmp);
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
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

/* The mode a new file gets: 0666 less the umask, as fopen would make it. */
static mode_t new_file_mode(void)
{
    mode_t m = umask(022);

    umask(m);
    return 0666 & ~m;
}

/* Opens out->tmp, "PATH.tmp.XXXXXX" made by mkstemp (O_CREAT | O_EXCL, so
 * never through a link), with the mode of the file it replaces. */
static FILE *open_temp(cli_output *out)
{
    struct stat st;
    sigset_t old;
    mode_t mode = stat(out->path, &st) == 0 ? st.st_mode & 07777 : new_file_mode();
    FILE *f = NULL;
    int fd;

    out->tmp = malloc(strlen(out->path) + 16);
    if (out->tmp == NULL) {
        errno = ENOMEM;
        return NULL;
    }
    sprintf(out->tmp, "%s.tmp.XXXXXX", out->path);
    catch_signals();
    block_signals(&old);
    fd = mkstemp(out->tmp);
    if (fd >= 0)
        track(out->tmp, NULL);
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (fd < 0) {
        free(out->tmp);
        out->tmp = NULL;
        return NULL;
    }
    if (fchmod(fd, mode) != 0 || (f = fdopen(fd, "wb")) == NULL) {
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

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
    } else
        out->f = open_temp(out);
    if (out->f == NULL) {
        cli_error("cannot write '%s': %s", path, strerror(errno));
        output_abort(out);
        return -1;
    }
    /* a system call per MiB, not per 4 KiB block: 200 000 of them for the
     * 812 MB .pat of 10^6 points (stdio's own buffer if there is no room:
     * glibc takes no size without a buffer) */
    out->buf = malloc(OUTPUT_BUF);
    if (out->buf != NULL && setvbuf(out->f, out->buf, _IOFBF, OUTPUT_BUF) != 0) {
        free(out->buf);
        out->buf = NULL;
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
    free(out->buf);
    out->buf = NULL;
    if (err)
        cli_error("cannot write '%s': %s", name, strerror(errno ? errno : EIO));
    return err ? -1 : 0;
}

/* Renames a closed output into place. */
static int output_publish(cli_output *out)
{
    sigset_t old;
    int err;

    block_signals(&old);
    err = out->tmp != NULL && rename(out->tmp, out->path) != 0;
    if (!err && out->tmp != NULL)
        track(NULL, out->tmp);
    sigprocmask(SIG_SETMASK, &old, NULL);
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
