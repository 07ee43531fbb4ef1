/* Fuzz target: the option parser (common/options.h).  The input is the
 * argument list, arguments separated by NUL bytes.  Contracts: what parses
 * is in range (a square sample count up to 65536, sides up to 16384, 1 to
 * 1024 threads, the scene one of the arguments); an error prints a message
 * and a success prints none; parsing the same arguments twice in one
 * process gives the same result (getopt's state is reset). */
#include <stdio.h>
#include <string.h>

#include "fuzz.h"
#include "options.h"

enum { MAX_ARGS = 32 };

static int choice, count;
static real amount;
static const char *const choices[] = {"robust", "textbook", "compare", NULL};
static const knob knobs[] = {
    {"sphere", KNOB_CHOICE, &choice, choices, "a choice"},
    {"depth", KNOB_INT, &count, NULL, "an integer"},
    {"epsilon", KNOB_REAL, &amount, NULL, "a real"},
};

static bool same(const render_options *a, const render_options *b)
{
    return a->scene_path == b->scene_path && a->output == b->output && a->width == b->width &&
           a->height == b->height && a->samples == b->samples && a->threads == b->threads && a->seed == b->seed &&
           a->quiet == b->quiet && a->nonfinite == b->nonfinite;
}

static options_result parse(int argc, char **argv, render_options *opt, char *messages, size_t messages_size)
{
    choice = count = 0;
    amount = 0;
    memset(messages, 0, messages_size);
    FILE *out = fmemopen(messages, messages_size - 1, "w");
    fuzz_check(out != NULL, "fmemopen");
    options_result result = options_parse(argc, argv, "fuzz", "fuzz.png", knobs, 3, opt, out, out);
    fclose(out);
    return result;
}

int fuzz_options(const uint8_t *data, size_t size)
{
    /* The arguments, each NUL-terminated, after argv[0]. */
    static char text[4096];
    if (size >= sizeof text)
        size = sizeof text - 1;
    memcpy(text, data, size);
    text[size] = '\0';
    char *argv[MAX_ARGS + 2] = {"render"};
    int argc = 1;
    for (char *s = text; s <= text + size && argc <= MAX_ARGS; s += strlen(s) + 1)
        argv[argc++] = s;
    argv[argc] = NULL;

    static char first_messages[8192], messages[8192];
    render_options first, opt;
    options_result r1 = parse(argc, argv, &first, first_messages, sizeof first_messages);
    int first_choice = choice, first_count = count;
    real first_amount = amount;
    options_result r2 = parse(argc, argv, &opt, messages, sizeof messages);
    fuzz_check(r1 == r2 && same(&first, &opt) && choice == first_choice && count == first_count &&
                   (amount == first_amount || (amount != amount && first_amount != first_amount)) &&
                   strcmp(first_messages, messages) == 0,
               "two parses of the same arguments differ");
    switch (r2) {
    case OPTIONS_OK: {
        fuzz_check(messages[0] == '\0', "a successful parse printed '%s'", messages);
        long root = 1;
        while (root * root < opt.samples)
            root++;
        fuzz_check(opt.samples == 0 || (opt.samples <= 65536 && root * root == opt.samples), "samples %d",
                   opt.samples);
        fuzz_check((opt.width == 0 && opt.height == 0) ||
                       (opt.width >= 1 && opt.width <= 16384 && opt.height >= 1 && opt.height <= 16384),
                   "size %d x %d", opt.width, opt.height);
        fuzz_check(opt.threads >= 0 && opt.threads <= 1024, "threads %d", opt.threads);
        fuzz_check(choice >= 0 && choice <= 2, "choice %d", choice);
        fuzz_check(opt.nonfinite == NONFINITE_DROP || opt.nonfinite == NONFINITE_SHOW ||
                       opt.nonfinite == NONFINITE_FAIL,
                   "nonfinite mode %d", (int)opt.nonfinite);
        fuzz_check(amount == amount, "a real knob is NaN");
        bool found = !opt.scene_path;
        for (int k = 1; k < argc && !found; k++)
            found = opt.scene_path == argv[k];
        fuzz_check(found, "the scene path is not one of the arguments");
        break;
    }
    case OPTIONS_EXIT:
        fuzz_check(strstr(messages, "usage: render") != NULL, "--help printed '%s'", messages);
        break;
    case OPTIONS_ERROR:
        fuzz_check(messages[0] != '\0', "an error printed no message");
        break;
    }
    return 0;
}

FUZZ_ENTRY(fuzz_options)
