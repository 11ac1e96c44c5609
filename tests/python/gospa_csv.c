/* gospa_csv.c - trk-sim's GOSPA (tools/sim/gospa.c) on cases read from a
 * text file, for the Python GOSPA's agreement test (tests/python_binding.sh).
 *
 *   py-gospa CASES.txt
 * CASES.txt: a line "c p", then per case a line "n m" followed by n lines
 * "x y" (targets) and m lines "x y" (estimates). Prints per case
 * "gospa loc missed false n_assigned n_missed n_false" (%.17g), the base
 * distance being the Euclidean one. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gospa.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: py-gospa CASES.txt\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        perror(argv[1]);
        return 1;
    }
    double c, p;
    if (fscanf(f, "%lf %lf", &c, &p) != 2) return 1;
    size_t n, m;
    while (fscanf(f, "%zu %zu", &n, &m) == 2) {
        double *xy = malloc(2 * (n + m + 1) * sizeof *xy), *d = malloc((n * m + 1) * sizeof *d);
        if (!xy || !d) return 1;
        for (size_t i = 0; i < n + m; i++)
            if (fscanf(f, "%lf %lf", &xy[2 * i], &xy[2 * i + 1]) != 2) return 1;
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < m; j++)
                d[i * m + j] = hypot(xy[2 * i] - xy[2 * (n + j)], xy[2 * i + 1] - xy[2 * (n + j) + 1]);
        struct gospa_result r;
        if (gospa(d, n, m, c, p, NULL, &r) != 0) return 1;
        printf("%.17g %.17g %.17g %.17g %zu %zu %zu\n", r.gospa, r.loc, r.missed, r.false_, r.n_assigned,
               r.n_missed, r.n_false);
        free(xy);
        free(d);
    }
    fclose(f);
    return 0;
}
