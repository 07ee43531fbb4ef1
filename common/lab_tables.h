/* lab_tables.h - the main() of a lab that prints measurement tables.
 *
 *     lab --TABLE
 *
 * A chapter's lab (chapters/NN_name/lab/) that renders nothing lists its
 * tables, each a flag, a line of help and the function that prints it on
 * standard output, and returns lab_tables_main(..., stdout, stderr).
 *
 * Returns the exit status: what the table's function returns (0 on
 * success), 0 for --help (the usage on `out`), 2 for anything else (a line
 * naming the problem and the usage on `err`).
 */
#ifndef RT_LAB_TABLES_H
#define RT_LAB_TABLES_H

#include <stdio.h>

typedef struct {
    const char *flag; /* "--acne-table" */
    const char *help; /* one line: what the table holds */
    int (*print)(void);
} lab_table;

int lab_tables_main(const char *summary, const lab_table *tables, int n, int argc, char **argv, FILE *out,
                    FILE *err);

#endif
