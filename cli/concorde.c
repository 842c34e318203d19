/*
 * Runs concorde (Applegate, Bixby, Chvátal, Cook) on a TSPLIB file of the
 * points in micrometres and reads its tour back. Concorde is not in Debian;
 * without it on PATH we say how to get it. It runs in a private temporary
 * folder (it writes half a dozen files named after its input in the current
 * one), in its own process group under a time limit (on a crash it sleeps an
 * hour for a debugger; SIGTERM ends it at once), and without -x (which makes
 * it exit 255 after a good solve). Its tour is used only when it exited 0
 * and the tour is a permutation of the points.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "concorde.h"

#define LIMIT_MS 600000.0 /* without --tsp-time: ten minutes */
#define GRACE_MS 1000.0   /* after SIGTERM, before SIGKILL */

/* A signal that asked quiltc to stop while concorde ran: concorde, in a
 * group of its own, does not get the terminal's Ctrl-C, so we stop it,
 * remove its folder, then die of the signal. */
static volatile sig_atomic_t stop_signal;

static void on_stop(int sig)
{
    stop_signal = sig;
}

/* The program's path found along PATH into buf, made absolute (concorde
 * runs in another folder): 1, or 0 when none is there. */
static int on_path(const char *prog, char *buf, size_t size)
{
    const char *path = getenv("PATH");

    while (path != NULL && *path != '\0') {
        const char *end = strchr(path, ':');
        size_t n = end ? (size_t)(end - path) : strlen(path), at = 0;
        struct stat st;

        if (path[0] != '/' && (getcwd(buf, size) == NULL || (at = strlen(buf) + 1) >= size))
            return 0;
        if (at > 0)
            buf[at - 1] = '/';
        if (at + n + strlen(prog) + 2 < size) {
            memcpy(buf + at, n > 0 ? path : ".", n > 0 ? n : 1);
            at += n > 0 ? n : 1;
            buf[at] = '/';
            strcpy(buf + at + 1, prog);
            if (stat(buf, &st) == 0 && S_ISREG(st.st_mode) && (st.st_mode & S_IXUSR))
                return 1;
        }
        path = end ? end + 1 : NULL;
    }
    return 0;
}

static int write_tsplib(const char *path, const qc_points *pts)
{
    FILE *f = fopen(path, "w");
    size_t i;

    if (f == NULL)
        return -1;
    fprintf(f, "NAME: quiltc\nTYPE: TSP\nDIMENSION: %lu\nEDGE_WEIGHT_TYPE: EUC_2D\n"
               "NODE_COORD_SECTION\n", (unsigned long)pts->n);
    for (i = 0; i < pts->n; i++) /* micrometres: EUC_2D rounds distances to integers */
        fprintf(f, "%lu %.0f %.0f\n", (unsigned long)i + 1, pts->v[i].x * 1000,
                pts->v[i].y * 1000);
    fputs("EOF\n", f);
    return fclose(f) == 0 ? 0 : -1;
}

static double now_ms(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static void nap_ms(double ms)
{
    struct timespec ts;

    ts.tv_sec = (time_t)(ms / 1e3);
    ts.tv_nsec = (long)((ms - (double)ts.tv_sec * 1e3) * 1e6);
    nanosleep(&ts, NULL);
}

/* Waits until pid exits or the deadline (ms, now_ms clock) passes: 1 when
 * it exited, 0 at the deadline. The exited child is not reaped, so its
 * process group stays its own until the caller has signalled it. */
static int wait_until(pid_t pid, double deadline)
{
    double nap = 2;

    for (;;) {
        siginfo_t si;

        memset(&si, 0, sizeof si);
        if (waitid(P_PID, (id_t)pid, &si, WEXITED | WNOHANG | WNOWAIT) < 0 && errno != EINTR)
            return 1;
        if (si.si_pid == pid)
            return 1;
        if (now_ms() >= deadline || stop_signal != 0)
            return 0;
        nap_ms(nap);
        nap = nap < 50 ? nap * 2 : 50;
    }
}

/* concorde -s 1 -o out.sol in.tsp in dir, its output to dir/log: 0 when it
 * exited 0 within limit_ms; else -1, with *timed_out set when it was killed. */
static int run_concorde(const char *prog, const char *dir, double limit_ms, int *timed_out)
{
    pid_t pid;
    int status = 0;

    *timed_out = 0;
    fflush(NULL);
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int in, log;

        setpgid(0, 0); /* its own group: the timeout ends whatever it started */
        in = open("/dev/null", O_RDONLY);
        if (chdir(dir) == 0 && in >= 0 &&
            (log = open("log", O_WRONLY | O_CREAT | O_TRUNC, 0600)) >= 0 && dup2(in, 0) >= 0 &&
            dup2(log, 1) >= 0 && dup2(log, 2) >= 0)
            execl(prog, "concorde", "-s", "1", "-o", "out.sol", "in.tsp", (char *)NULL);
        _exit(127);
    }
    setpgid(pid, pid); /* also here: no race with the child's own call */
    if (!wait_until(pid, now_ms() + limit_ms)) {
        *timed_out = 1;
        kill(-pid, SIGTERM);
        wait_until(pid, now_ms() + GRACE_MS);
    }
    if (*timed_out)
        kill(-pid, SIGKILL); /* the group and all it started; pid is not reaped yet */
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    return !*timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

/* run_concorde with SIGINT, SIGTERM and SIGHUP caught meanwhile. */
static int run_guarded(const char *prog, const char *dir, double limit_ms, int *timed_out)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction sa, old[3];
    int i, rc;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    stop_signal = 0;
    for (i = 0; i < 3; i++)
        if (sigaction(sigs[i], &sa, &old[i]) == 0 && old[i].sa_handler == SIG_IGN)
            sigaction(sigs[i], &old[i], NULL); /* ignored stays ignored */
    rc = run_concorde(prog, dir, limit_ms, timed_out);
    for (i = 0; i < 3; i++)
        sigaction(sigs[i], &old[i], NULL);
    return rc;
}

/* The solution file: the count, then a permutation of 0..n-1, nothing else. */
static int read_tour(qc_ctx *ctx, const char *path, size_t n, qc_order *out)
{
    FILE *f = fopen(path, "r");
    unsigned char *seen = calloc(n ? n : 1, 1);
    unsigned long count, v;
    size_t i;
    int rc = -1;
    char c;

    if (f == NULL || seen == NULL || fscanf(f, "%lu", &count) != 1 || count != n)
        goto out;
    for (i = 0; i < n; i++) {
        if (fscanf(f, "%lu", &v) != 1 || v >= n || seen[v] ||
            qc_order_push(ctx, out, (uint32_t)v) < 0)
            goto out;
        seen[v] = 1;
    }
    rc = fscanf(f, " %c", &c) == EOF ? 0 : -1;
out:
    if (f != NULL)
        fclose(f);
    free(seen);
    return rc;
}

/* Empties and removes the folder concorde ran in (only files are there). */
static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *ent;
    char path[4096 + 260];

    while (d != NULL && (ent = readdir(d)) != NULL) {
        if (strcmp(ent->d_name, ".") == 0 || strcmp(ent->d_name, "..") == 0)
            continue;
        if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, ent->d_name) < sizeof path)
            remove(path);
    }
    if (d != NULL)
        closedir(d);
    rmdir(dir);
}

/* Concorde's optimal tour of pts in *tour, started at root; limit_ms of
 * its time (0: LIMIT_MS). CLI_* status, after one line on failure. */
static int concorde_tour(qc_ctx *ctx, const qc_points *pts, uint32_t root, double limit_ms,
                         qc_order *tour)
{
    const char *tmp = getenv("TMPDIR");
    char dir[4000], tsp[4096], sol[4096], prog[4096];
    qc_order raw = {0};
    size_t i, at = 0, n = pts->n;
    int timed_out = 0, rc = CLI_RUNTIME;

    tour->n = 0;
    if (n <= 3) { /* every order is optimal; concorde refuses fewer than 3 */
        for (i = 0; i < n; i++)
            if (qc_order_push(ctx, tour, (uint32_t)((root + i) % n)) < 0)
                return cli_fail(ctx, "--tsp concorde", ctx->status);
        return CLI_OK;
    }
    if (tmp == NULL || *tmp == '\0' || strlen(tmp) > 3900)
        tmp = "/tmp";
    snprintf(dir, sizeof dir, "%s/quiltc-concorde-XXXXXX", tmp);
    if (mkdtemp(dir) == NULL) {
        cli_error("--tsp concorde: cannot make a temporary folder in %s: %s", tmp,
                  strerror(errno));
        return CLI_RUNTIME;
    }
    snprintf(tsp, sizeof tsp, "%s/in.tsp", dir);
    snprintf(sol, sizeof sol, "%s/out.sol", dir);
    if (limit_ms <= 0)
        limit_ms = LIMIT_MS;
    if (write_tsplib(tsp, pts) != 0) {
        cli_error("--tsp concorde: cannot write %s: %s", tsp, strerror(errno));
    } else if (!on_path("concorde", prog, sizeof prog) ||
               run_guarded(prog, dir, limit_ms, &timed_out) != 0) {
        if (stop_signal == 0 && timed_out) /* (stopped by a signal: dying of it below) */
            cli_error("--tsp concorde: no tour from concorde within %g s on %lu points "
                      "(stopped; --tsp-time sets its limit)",
                      limit_ms / 1e3, (unsigned long)n);
        else if (stop_signal == 0)
            cli_error("--tsp concorde: concorde failed on %lu points", (unsigned long)n);
    } else if (read_tour(ctx, sol, n, &raw) != 0) {
        cli_error("--tsp concorde: concorde's tour is not a permutation of the %lu points",
                  (unsigned long)n);
    } else {
        for (i = 0; i < n; i++) /* start at the root, as the built-in tour does */
            if (raw.i[i] == root)
                at = i;
        rc = CLI_OK;
        for (i = 0; i < n && rc == CLI_OK; i++)
            if (qc_order_push(ctx, tour, raw.i[(at + i) % n]) < 0)
                rc = cli_fail(ctx, "--tsp concorde", ctx->status);
    }
    qc_order_free(ctx, &raw);
    remove_dir(dir);
    if (stop_signal != 0) /* nothing was written: outputs come after */
        raise(stop_signal);
    return rc;
}

static int have_concorde(void)
{
    char prog[4096];

    if (on_path("concorde", prog, sizeof prog))
        return 1;
    cli_error("--tsp concorde: no 'concorde' program on PATH (build it from "
              "https://www.math.uwaterloo.ca/tsp/concorde.html, or use --tsp or3opt)");
    return 0;
}

/* ctx->tour for qc_generate: concorde's tour; its own line on failure. */
typedef struct concorde_hook {
    qc_ctx *ctx;
    int rc; /* CLI status of the last run */
} concorde_hook;

static int hook_tour(void *ud, const qc_vec2 *pts, size_t n, double budget_ms, qc_order *order)
{
    concorde_hook *h = (concorde_hook *)ud;
    qc_points view;

    view.v = (qc_vec2 *)pts; /* read only: written out as TSPLIB */
    view.n = view.cap = n;
    h->rc = concorde_tour(h->ctx, &view, 0, budget_ms, order);
    return h->rc == CLI_OK ? QC_OK : QC_EUNSUPPORTED;
}

/* qc_generate with concorde as the tour (the family decorates once, kept
 * inside and measured as every other run). */
static int generate_with_concorde(qc_ctx *ctx, const qc_params *p, const qc_region *region,
                                  const qc_points *given, const qc_motif_set *motifs,
                                  qc_result *res, const char *what)
{
    concorde_hook h;
    int rc;

    h.ctx = ctx;
    h.rc = CLI_OK;
    ctx->tour = hook_tour;
    ctx->tour_ud = &h;
    rc = qc_generate(ctx, region, p, given, motifs, res);
    ctx->tour = NULL;
    ctx->tour_ud = NULL;
    if (rc >= 0)
        return CLI_OK;
    return h.rc != CLI_OK ? h.rc : cli_fail(ctx, what, ctx->status);
}

int cli_concorde_skeleton(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, qc_result *res)
{
    qc_params p = *params;

    if (!have_concorde())
        return CLI_RUNTIME;
    qc_params_set(ctx, &p, "skeleton", QC_SKELETON_TSP);
    return generate_with_concorde(ctx, &p, region, given, NULL, res, "skeleton");
}

int cli_concorde_generate(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, const qc_motif_set *motifs, qc_result *res)
{
    const qc_family_desc *fam;
    qc_params r;

    if (qc_params_resolve(ctx, params, &r) < 0)
        return cli_fail(ctx, "generate", ctx->status);
    fam = qc_family_info((size_t)r.family - 1);
    if (fam == NULL || !(fam->needs & QC_FAMILY_NEEDS_POINTS)) {
        cli_error("--tsp concorde: the %s family has no points to tour", qc_family_name(r.family));
        return CLI_USAGE;
    }
    if (r.skeleton != QC_SKELETON_TSP) {
        cli_error("--tsp concorde: the %s family walks a tree, not a tour (add --skeleton tsp)",
                  qc_family_name(r.family));
        return CLI_USAGE;
    }
    if (!have_concorde())
        return CLI_RUNTIME;
    return generate_with_concorde(ctx, params, region, given, motifs, res, "generate");
}
