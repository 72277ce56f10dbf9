/*
 * wants_help.c — tf_wants_help (cli.h), shared by tissuefit and tissuefit-mpi.
 */
#include <string.h>

#include "cli/cli.h"

int tf_wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            return 1;
        }
        if (strcmp(argv[i], "--") == 0) {
            break;
        }
    }
    return 0;
}
