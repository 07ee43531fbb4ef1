/* lab_tables.c - the main() of a lab that prints measurement tables. */
#include "lab_tables.h"

#include <string.h>

static void usage(FILE *out, const char *program, const char *summary, const lab_table *tables, int n)
{
    fprintf(out, "%s\nusage: %s --TABLE\n", summary, program);
    for (int k = 0; k < n; k++)
        fprintf(out, "  %-20s %s\n", tables[k].flag, tables[k].help);
}

int lab_tables_main(const char *summary, const lab_table *tables, int n, int argc, char **argv, FILE *out,
                    FILE *err)
{
    const char *program = argc > 0 ? argv[0] : "lab";
    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        usage(out, program, summary, tables, n);
        return 0;
    }
    for (int k = 0; argc == 2 && k < n; k++)
        if (strcmp(argv[1], tables[k].flag) == 0)
            return tables[k].print();
    if (argc != 2)
        fprintf(err, "%s: name one table\n", program);
    else
        fprintf(err, "%s: unknown table '%s'\n", program, argv[1]);
    usage(err, program, summary, tables, n);
    return 2;
}
