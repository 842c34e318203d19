/*
 * Whether a file a job names stays inside the job's folder: no absolute
 * name, no ".." climbing out, and no symbolic link leading out (the name is
 * resolved, or for an output not there yet, its folder). A downloaded job
 * may so read and write only beside itself, as TeX's openout_any = p and
 * GNU tar's member names do.
 */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "job.h"

static int has_dotdot(const char *s)
{
    while (*s) {
        size_t n = strcspn(s, "/");
        if (n == 2 && s[0] == '.' && s[1] == '.')
            return 1;
        s += n + (s[n] == '/');
    }
    return 0;
}

/* The resolved name of path, or of its folder when it does not exist yet
 * (an output); NULL when neither resolves (the reader or writer then says
 * why). */
static char *resolve(const char *path)
{
    struct stat st;
    char *r, *copy, *slash;

    if (lstat(path, &st) == 0)
        return realpath(path, NULL); /* NULL for a link to nothing: the writer refuses it */
    copy = malloc(strlen(path) + 1);
    if (copy == NULL)
        return NULL;
    strcpy(copy, path);
    slash = strrchr(copy, '/');
    if (slash == NULL)
        r = realpath(".", NULL);
    else if (slash == copy)
        r = realpath("/", NULL);
    else {
        *slash = '\0';
        r = realpath(copy, NULL);
    }
    free(copy);
    return r;
}

int cli_path_inside(const char *root, const char *name, const char *path, const char *what)
{
    char *r;
    size_t n = strlen(root);
    int inside;

    if (name[0] == '/') {
        cli_error("%s: '%s' is outside the job's folder (an absolute name; run with "
                  "--allow-outside to allow it)", what, name);
        return CLI_USAGE;
    }
    if (has_dotdot(name)) {
        cli_error("%s: '%s' climbs out of the job's folder with '..' (run with "
                  "--allow-outside to allow it)", what, name);
        return CLI_USAGE;
    }
    r = resolve(path);
    if (r == NULL)
        return CLI_OK;
    inside = strncmp(r, root, n) == 0 && (r[n] == '/' || r[n] == '\0' || strcmp(root, "/") == 0);
    free(r);
    if (!inside) {
        cli_error("%s: '%s' leads outside the job's folder through a symbolic link (run "
                  "with --allow-outside to allow it)", what, name);
        return CLI_USAGE;
    }
    return CLI_OK;
}
