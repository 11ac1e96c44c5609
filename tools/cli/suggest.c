/* suggest.c - the known name nearest to a misspelled one (suggest.h). */
#include "suggest.h"

#include <stdio.h>
#include <string.h>

#define NEAR_MAX 2
#define LEN_MAX 255

int cli_edit_distance(const char *a, const char *b)
{
    const size_t n = strlen(a), m = strlen(b);
    if (n > LEN_MAX || m > LEN_MAX) return NEAR_MAX + 1;
    if ((n > m ? n - m : m - n) > NEAR_MAX) return NEAR_MAX + 1; /* too far apart already */
    /* three rows of the dynamic programme: i - 2, i - 1, i */
    int r2[LEN_MAX + 1], r1[LEN_MAX + 1], r0[LEN_MAX + 1];
    for (size_t j = 0; j <= m; j++) r1[j] = (int)j;
    for (size_t i = 1; i <= n; i++) {
        r0[0] = (int)i;
        for (size_t j = 1; j <= m; j++) {
            const int cost = a[i - 1] != b[j - 1];
            int d = r1[j - 1] + cost;                     /* substitute (or keep) */
            if (r1[j] + 1 < d) d = r1[j] + 1;             /* delete */
            if (r0[j - 1] + 1 < d) d = r0[j - 1] + 1;     /* insert */
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && r2[j - 2] + 1 < d)
                d = r2[j - 2] + 1;                        /* swap two adjacent */
            r0[j] = d;
        }
        memcpy(r2, r1, (m + 1) * sizeof r1[0]);
        memcpy(r1, r0, (m + 1) * sizeof r0[0]);
    }
    return r1[m];
}

void cli_near_init(struct cli_near *s, const char *word)
{
    s->word = word;
    s->best = NULL;
    s->dist = NEAR_MAX + 1;
}

void cli_near_add(struct cli_near *s, const char *name)
{
    if (!name || !name[0]) return;
    const int d = cli_edit_distance(s->word, name);
    /* close: at most 2 edits and fewer than half the word's characters */
    if (d < s->dist && d <= NEAR_MAX && 2 * (size_t)d < strlen(s->word)) {
        s->best = name;
        s->dist = d;
    }
}

const char *cli_suggest(const char *word, const char *const *names)
{
    struct cli_near s;
    cli_near_init(&s, word);
    for (; names && *names; names++) cli_near_add(&s, *names);
    return s.best;
}

void cli_did_you_mean(const char *best, char *buf, size_t n)
{
    if (best) snprintf(buf, n, "; did you mean '%s'?", best);
    else if (n) buf[0] = 0;
}
