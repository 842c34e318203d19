/*
 * A main for the fuzz targets without libFuzzer: runs
 * LLVMFuzzerTestOneInput once on every file named (directories: every file
 * in them, sorted), so tests/check_fuzz_regress.sh replays the corpus and
 * the regression inputs through the plain (or ASan) build. Prints one line
 * per file before running it, so a crash names its input; exits 0 when all
 * ran.
 */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b = NULL;
    size_t n = 0, cap = 0, got;

    if (f == NULL) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    do {
        if (n == cap) {
            unsigned char *nb = realloc(b, cap = cap ? 2 * cap : 4096);
            if (nb == NULL) {
                free(b);
                fclose(f);
                return 1;
            }
            b = nb;
        }
        got = fread(b + n, 1, cap - n, f);
        n += got;
    } while (got > 0);
    fclose(f);
    printf("replay %s (%lu bytes)\n", path, (unsigned long)n);
    fflush(stdout);
    {
        /* an exact-size copy, as libFuzzer gives */
        unsigned char *exact = malloc(n ? n : 1);
        if (exact == NULL) {
            free(b);
            return 1;
        }
        if (n)
            memcpy(exact, b, n);
        free(b);
        LLVMFuzzerTestOneInput(exact, n);
        free(exact);
    }
    return 0;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int run_dir(const char *dir, size_t *count)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **names = NULL;
    size_t n = 0, cap = 0, i;
    int bad = 0;

    if (d == NULL)
        return 1;
    while ((e = readdir(d)) != NULL) {
        char *p;
        if (e->d_name[0] == '.')
            continue;
        if (n == cap) {
            char **nn = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *names);
            if (nn == NULL) {
                bad = 1;
                break;
            }
            names = nn;
        }
        p = malloc(strlen(dir) + strlen(e->d_name) + 2);
        if (p == NULL) {
            bad = 1;
            break;
        }
        sprintf(p, "%s/%s", dir, e->d_name);
        names[n++] = p;
    }
    closedir(d);
    qsort(names, n, sizeof *names, by_name);
    for (i = 0; i < n; i++) {
        struct stat st;
        if (!bad && stat(names[i], &st) == 0 && S_ISREG(st.st_mode)) {
            bad |= run_file(names[i]);
            (*count)++;
        }
        free(names[i]);
    }
    free(names);
    return bad;
}

int main(int argc, char **argv)
{
    size_t count = 0;
    int i, bad = 0;

    for (i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0)
            continue; /* a target without regression inputs yet */
        if (S_ISDIR(st.st_mode))
            bad |= run_dir(argv[i], &count);
        else {
            bad |= run_file(argv[i]);
            count++;
        }
    }
    printf("replayed %lu inputs\n", (unsigned long)count);
    return bad;
}
