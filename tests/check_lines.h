/* check_lines.h: the tests' image programs answer one check per line of stdin
 * (`PROGRAM -`), so a test pays the image module's load once, not per picture. */
#ifndef SL_TEST_CHECK_LINES_H
#define SL_TEST_CHECK_LINES_H
#include <stdio.h>
#include <string.h>

/* Each line: the words of one command line, split at tabs (paths may hold spaces);
 * check() runs it as main would, and "NAME: exit N" follows its own output. More
 * than max_words - 1 words gives check() no words at all: its usage. */
static inline int sl_test_check_lines(const char *name, char *argv0, int max_words, int (*check)(int, char **)) {
    char line[4096];
    char *words[16];
    if (max_words > 16) max_words = 16;
    while (fgets(line, sizeof line, stdin)) {
        words[0] = argv0;
        int n = 1;
        for (char *w = strtok(line, "\t\r\n"); w; w = strtok(NULL, "\t\r\n")) {
            if (n == max_words) {
                n = 0; /* too many words: the usage */
                break;
            }
            words[n++] = w;
        }
        if (n == 1) continue;
        int rc = check(n ? n : 1, words);
        printf("%s: exit %d\n", name, rc);
        fflush(stdout);
        fflush(stderr);
    }
    return 0;
}
#endif
