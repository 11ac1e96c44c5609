/* sim.c - shared option parsing for trk-sim experiments (sim.h). */
#include "sim.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

void sim_common_defaults(struct sim_common *c, const char *def_out)
{
    c->seed = 1;
    c->runs = 0;
    c->out = def_out;
    c->threads = 0;
    c->quiet = 0;
    c->no_plot = 0;
}

int sim_arg(int argc, char **argv, int *i, const char *name, const char **val)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (strncmp(a, name, n) != 0) return 0;
    if (a[n] == '=') {
        *val = a + n + 1;
        return 1;
    }
    if (a[n] != 0) return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "option %s needs a value\n", name);
        return -1;
    }
    *val = argv[++*i];
    return 1;
}

int sim_parse_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    double d = strtod(s, &end); /* accepts 1e6 */
    if (errno || end == s || *end || d != (double)(long)d) return -1;
    *v = (long)d;
    return 0;
}

int sim_parse_double(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return errno || end == s || *end ? -1 : 0;
}

int sim_parse_list(const char *s, double *v, int max)
{
    double a, b, st;
    char tail;
    if (sscanf(s, "%lf:%lf:%lf%c", &a, &b, &st, &tail) == 3) {
        if (!(st > 0) || b < a) return -1;
        int n = 0;
        for (double x = a; x <= b + 1e-9 * st && n < max; x = a + st * n) v[n++] = x;
        return n;
    }
    int n = 0;
    const char *p = s;
    while (*p && n < max) {
        char *end;
        v[n] = strtod(p, &end);
        if (end == p) return -1;
        n++;
        if (*end == ',') end++;
        else if (*end) return -1;
        p = end;
    }
    return n > 0 ? n : -1;
}

int sim_common_arg(int argc, char **argv, int *i, struct sim_common *c)
{
    const char *v;
    int r;
    long l;
    if (strcmp(argv[*i], "--quiet") == 0) {
        c->quiet = 1;
        return 1;
    }
    if (strcmp(argv[*i], "--no-plot") == 0) {
        c->no_plot = 1;
        return 1;
    }
    if ((r = sim_arg(argc, argv, i, "--seed", &v)) != 0) {
        char *end;
        if (r < 0) return -1;
        errno = 0;
        unsigned long long s = strtoull(v, &end, 0);
        if (errno || end == v || *end) {
            fprintf(stderr, "bad --seed %s\n", v);
            return -1;
        }
        c->seed = (uint64_t)s;
        return 1;
    }
    if ((r = sim_arg(argc, argv, i, "--runs", &v)) != 0) {
        if (r < 0 || sim_parse_long(v, &l) || l < 1) {
            fprintf(stderr, "bad --runs\n");
            return -1;
        }
        c->runs = l;
        return 1;
    }
    if ((r = sim_arg(argc, argv, i, "--threads", &v)) != 0) {
        if (r < 0 || sim_parse_long(v, &l) || l < 1 || l > 1024) {
            fprintf(stderr, "bad --threads\n");
            return -1;
        }
        c->threads = (int)l;
        return 1;
    }
    if ((r = sim_arg(argc, argv, i, "--out", &v)) != 0) {
        if (r < 0) return -1;
        c->out = v;
        return 1;
    }
    return 0;
}

int sim_threads(const struct sim_common *c)
{
#ifdef _OPENMP
    if (c->threads > 0) omp_set_num_threads(c->threads);
    return omp_get_max_threads();
#else
    (void)c;
    return 1;
#endif
}
