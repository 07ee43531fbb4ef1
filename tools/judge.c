/* judge.c - the verdict of a graded test, from two transcripts (judge.h). */
#include "judge.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char kind[8];
    double v[3];
    int n;            /* numbers read */
    const char *what; /* the rest of an answer's line (up to its end) */
    int what_len;
} record;

/* The record on the line at *text; advances *text past it.  0 at the end. */
static int next_record(const char **text, record *r)
{
    const char *line = *text;
    if (!*line)
        return 0;
    const char *end = strchr(line, '\n');
    size_t len = end ? (size_t)(end - line) : strlen(line);
    *text = line + len + (end != NULL);
    char copy[600];
    if (len >= sizeof copy)
        len = sizeof copy - 1;
    memcpy(copy, line, len);
    copy[len] = '\0';
    memset(r, 0, sizeof *r);
    int used = 0;
    if (sscanf(copy, "%7s%n", r->kind, &used) != 1)
        snprintf(r->kind, sizeof r->kind, "?");
    const char *p = copy + used;
    int max = strcmp(r->kind, "answer") == 0 ? 2 : 3;
    while (r->n < max) {
        char *after;
        double x = strtod(p, &after);
        if (after == p)
            break;
        r->v[r->n++] = x;
        p = after;
    }
    if (strcmp(r->kind, "answer") == 0) {
        while (*p == ' ')
            p++;
        r->what = line + (p - copy);
        r->what_len = (int)(len - (size_t)(p - copy));
    }
    return 1;
}

static int arity(const char *kind)
{
    static const struct {
        const char *kind;
        int n;
    } kinds[] = {{"eps", 1}, {"close", 3}, {"int", 2}, {"true", 1}, {"fail", 0},
                 {"skip", 0}, {"answer", 2}, {"end", 1}};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        if (strcmp(kind, kinds[k].kind) == 0)
            return kinds[k].n;
    return -1;
}

static int within(double a, double e, double t) { return a == e || fabs(a - e) <= t || (isnan(a) && isnan(e)); }

judge_verdict judge(const char *reference, const char *student, char *note, size_t note_size)
{
    /* The reference's run: complete, passed, or skipped. */
    record r;
    double eps = 0;
    int ended = 0, skipped = 0, n_checks = 0;
    for (const char *p = reference; next_record(&p, &r);) {
        if (strcmp(r.kind, "eps") == 0 && r.n == 1)
            eps = r.v[0];
        skipped |= strcmp(r.kind, "skip") == 0;
        if (strcmp(r.kind, "end") == 0)
            ended = r.n == 1 && r.v[0] == 0 ? 1 : -1;
    }
    if (skipped)
        return JUDGE_SKIPPED;
    if (ended != 1 || eps <= 0) {
        snprintf(note, note_size,
                 "the reference does not pass this test here (a problem of the grader: tell the course staff)");
        return JUDGE_BROKEN;
    }
    const char *pr = reference, *ps = student;
    record s;
    for (;;) {
        int have_r = next_record(&pr, &r), have_s = next_record(&ps, &s);
        if (!have_r && !have_s)
            break;
        if (!have_s) {
            snprintf(note, note_size, "the test stopped before its check %d (a failed check, a crash or an exit)",
                     n_checks + 1);
            return JUDGE_FAILED;
        }
        if (!have_r || strcmp(r.kind, s.kind) != 0 || s.n != arity(s.kind)) {
            snprintf(note, note_size, "the test's checks went otherwise than the reference's from its check %d on",
                     n_checks + 1);
            return JUDGE_FAILED;
        }
        const char *kind = r.kind;
        int ok = 1;
        if (strcmp(kind, "close") == 0) {
            double t = r.v[2];
            ok = within(s.v[1], s.v[0], t) &&
                 (s.v[0] == r.v[0] || fabs(s.v[0] - r.v[0]) <= t + 4096 * eps * fabs(r.v[0]));
        } else if (strcmp(kind, "int") == 0) {
            ok = s.v[0] == s.v[1] && s.v[0] == r.v[0];
        } else if (strcmp(kind, "true") == 0) {
            ok = s.v[0] == 1;
        } else if (strcmp(kind, "answer") == 0) {
            ok = within(s.v[0], r.v[0], r.v[1]);
            if (!ok) {
                snprintf(note, note_size, "%.*s: yours %.17g, the reference's %.17g (within %.3g)",
                         r.what_len > 400 ? 400 : r.what_len, r.what, s.v[0], r.v[0], r.v[1]);
                return JUDGE_FAILED;
            }
        } else if (strcmp(kind, "eps") == 0) {
            ok = s.v[0] == r.v[0];
        } else if (strcmp(kind, "end") == 0) {
            ok = s.v[0] == 0;
        }
        if (strcmp(kind, "eps") != 0 && strcmp(kind, "end") != 0)
            n_checks++;
        if (!ok) {
            snprintf(note, note_size, "check %d of the test fails", n_checks);
            return JUDGE_FAILED;
        }
    }
    return JUDGE_PASSED;
}
