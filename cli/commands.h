/* commands.h - the table of the command line's commands (commands.c): each row names the
 * command, its positional arguments and how many it takes, the line `ssgraph help` lists
 * it with and the text `ssgraph help COMMAND` prints above its options (options.c prints
 * those from the option table). Read-only data; safe from any thread. */
#ifndef SSG_CLI_COMMANDS_H
#define SSG_CLI_COMMANDS_H

#include "options.h"

struct ssg_cli_command_info {
    enum ssg_cli_command command; /* its bit */
    const char *name;             /* "run" */
    const char *args;             /* its positional arguments in the synopsis ("FILE") */
    int min_args, max_args;       /* how many positional arguments it takes */
    const char *summary;          /* `ssgraph help`'s line; each '\n' starts an indented
                                     line */
    const char *help;             /* `ssgraph help COMMAND`: what it does, what it writes
                                     and prints, in lines of at most 88 characters */
};

/* Every command, in the order `ssgraph help` lists them. */
extern const struct ssg_cli_command_info ssg_cli_commands[];
extern const int ssg_cli_command_count;

#endif
