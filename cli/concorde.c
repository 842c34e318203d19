/*
 * Runs concorde (Applegate, Bixby, Chvátal, Cook) on a TSPLIB file of the
 * points in micrometres and reads its tour back. Concorde is not in Debian;
 * without it on PATH we say how to get it.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "concorde.h"

static int on_path(const char *prog)
{
    const char *path = getenv("PATH");
    char buf[4096];

    while (path != NULL && *path != '\0') {
        const char *end = strchr(path, ':');
        size_t n = end ? (size_t)(end - path) : strlen(path);
        struct stat st;

        if (n + strlen(prog) + 2 < sizeof buf) {
            memcpy(buf, path, n);
            buf[n] = '/';
            strcpy(buf + n + 1, prog);
            if (stat(buf, &st) == 0 && (st.st_mode & S_IXUSR))
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

static int run_concorde(const char *dir, const char *tsp, const char *sol)
{
    pid_t pid = fork();
    int status;

    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (chdir(dir) == 0 && freopen("/dev/null", "w", stdout) != NULL)
            execlp("concorde", "concorde", "-x", "-o", sol, tsp, (char *)NULL);
        _exit(127);
    }
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return 0;
}

/* The solution file: the count, then the 0-based tour, which must visit
 * every point once (a solver's file is not trusted: a tour repeating one
 * point would have length 0). */
static int read_tour(qc_ctx *ctx, const char *path, size_t n, qc_order *out)
{
    FILE *f = fopen(path, "r");
    unsigned long count, v;
    unsigned char *seen = calloc(n ? n : 1, 1);
    size_t i;
    int rc = -1;

    if (f == NULL || seen == NULL || fscanf(f, "%lu", &count) != 1 || count != n)
        goto out;
    for (i = 0; i < n; i++) {
        if (fscanf(f, "%lu", &v) != 1 || v >= n || seen[v]++ ||
            qc_order_push(ctx, out, (uint32_t)v) < 0)
            goto out;
    }
    rc = 0;
out:
    free(seen);
    if (f != NULL)
        fclose(f);
    return rc;
}

/* Empties and removes the temporary folder, whatever the solver left in it
 * (concorde writes in.mas, in.pul, Oin.sav, ... beside its files). */
static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[96];

    while (d != NULL && (e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, e->d_name) < sizeof path)
            remove(path);
    }
    if (d != NULL)
        closedir(d);
    rmdir(dir);
}

int cli_concorde_skeleton(qc_ctx *ctx, const qc_params *params, const qc_region *region,
                          const qc_points *given, qc_result *res)
{
    char dir[] = "/tmp/quiltc-concorde-XXXXXX", tsp[64], sol[64];
    qc_params p = *params;
    qc_order tour = {0};
    size_t i, at = 0;
    int rc = CLI_RUNTIME;

    if (!on_path("concorde")) {
        cli_error("--tsp concorde: no 'concorde' program on PATH (build it from "
                  "https://www.math.uwaterloo.ca/tsp/concorde.html, or use --tsp oropt)");
        return CLI_RUNTIME;
    }
    qc_params_set(ctx, &p, "skeleton", QC_SKELETON_MST); /* for the points and root */
    if (qc_generate(ctx, region, &p, given, NULL, res) < 0)
        return cli_fail(ctx, "skeleton", ctx->status);
    if (mkdtemp(dir) == NULL) {
        cli_error("cannot make a temporary directory: %s", strerror(errno));
        return CLI_RUNTIME;
    }
    snprintf(tsp, sizeof tsp, "%s/in.tsp", dir);
    snprintf(sol, sizeof sol, "%s/out.sol", dir);
    if (write_tsplib(tsp, &res->points) != 0 || run_concorde(dir, "in.tsp", "out.sol") != 0 ||
        read_tour(ctx, sol, res->points.n, &tour) != 0) {
        cli_error("--tsp concorde: concorde failed on %lu points (or its tour does not visit "
                  "each point once)",
                  (unsigned long)res->points.n);
        goto out;
    }
    for (i = 0; i < tour.n; i++) /* start at the root, as the built-in tour does */
        if (tour.i[i] == res->order.i[0])
            at = i;
    res->order.n = 0;
    qc_edges_free(ctx, &res->edges);
    for (i = 0; i < tour.n; i++)
        if (qc_order_push(ctx, &res->order, tour.i[(at + i) % tour.n]) < 0)
            goto out;
    rc = CLI_OK;
out:
    qc_order_free(ctx, &tour);
    remove_dir(dir);
    return rc;
}
