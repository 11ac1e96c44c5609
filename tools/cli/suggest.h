/* suggest.h - "did you mean ...?": the known name nearest to a misspelled
 * one (an unknown option, configuration key or subcommand).
 *
 * Distance: optimal string alignment (Levenshtein with the swap of two
 * adjacent characters counted as one edit). A name is suggested when its
 * distance to the word is at most 2 and less than half the word's length
 * ("gama" -> "gamma" at 1; "xy" gets nothing); of several, the nearest, the
 * first listed on a tie. Names compared are the whole spellings ("--scans",
 * "sensor.0.pd"). */
#ifndef TRK_TOOLS_SUGGEST_H
#define TRK_TOOLS_SUGGEST_H

#include <stddef.h>

/* Edits between a and b (optimal string alignment), or a value > 2 once it
 * is certain to exceed 2 (or either string is longer than 255 characters). */
int cli_edit_distance(const char *a, const char *b);

/* The nearest name so far, fed one candidate at a time. */
struct cli_near {
    const char *word;   /* the misspelled word */
    const char *best;   /* NULL: none close enough yet */
    int dist;
};
void cli_near_init(struct cli_near *s, const char *word);
void cli_near_add(struct cli_near *s, const char *name);

/* The nearest of names[0 .. NULL) to word, or NULL. */
const char *cli_suggest(const char *word, const char *const *names);

/* "; did you mean 'NAME'?" into buf when there is a suggestion, else "". */
void cli_did_you_mean(const char *best, char *buf, size_t n);

#endif
