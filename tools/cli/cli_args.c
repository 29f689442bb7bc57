/* SPDX-License-Identifier: Apache-2.0 */
/*
 * What every `symline` command parses the same way: getopt_long with the
 * messages of every host program (hostopts.h), the OUT / -o choice, and
 * input lists that may name folders.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "cli.h"
#include "hostopts.h"

int cli_getopt(int argc, char **argv, const char *shortopts, const struct option *longopts)
{
    char who[64], help[64];
    int c;
    snprintf(who, sizeof who, "symline: %s", argv[0]);
    snprintf(help, sizeof help, "symline %s", argv[0]);
    c = hostopts_next(argc, argv, shortopts, longopts, who, help);
    return c == HOSTOPTS_ERROR ? CLI_GETOPT_ERROR : c;
}

int cli_output_name(const char *cmd, const char *positional, const char *option, const char **out)
{
    if (positional != NULL && option != NULL) {
        return cli_error("%s: give OUT or -o OUT, not both", cmd);
    }
    *out = positional != NULL ? positional : option;
    if (*out == NULL) {
        return cli_error("%s: no output named (OUT or -o OUT; '-' is stdout)", cmd);
    }
    return 0;
}

static int has_ext(const char *name, const char *ext)
{
    size_t n = strlen(name), k = strlen(ext);
    return n > k && strcasecmp(name + n - k, ext) == 0;
}

static int is_frame_name(const char *name)
{
    if (name[0] == '.' || has_ext(name, ".mask.pgm") || has_ext(name, ".mask.png")) {
        return 0; /* hidden files and the evaluation's line masks are not frames */
    }
    return has_ext(name, ".pgm") || has_ext(name, ".png") || has_ext(name, ".jpg") || has_ext(name, ".jpeg");
}

static int add(cli_inputs *in, const char *dir, const char *name)
{
    size_t len = (dir != NULL ? strlen(dir) + 1u : 0u) + strlen(name) + 1u;
    char *p;
    if (in->count == in->cap) {
        size_t ncap = in->cap ? 2u * in->cap : 16u;
        char **np = realloc(in->paths, ncap * sizeof *np);
        if (np == NULL) {
            return -1;
        }
        in->paths = np;
        in->cap = ncap;
    }
    p = malloc(len);
    if (p == NULL) {
        return -1;
    }
    if (dir != NULL) {
        snprintf(p, len, "%s%s%s", dir, dir[strlen(dir) - 1] == '/' ? "" : "/", name);
    } else {
        snprintf(p, len, "%s", name);
    }
    in->paths[in->count++] = p;
    return 0;
}

static int cmp_path(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int cli_inputs_add(cli_inputs *in, const char *cmd, const char *arg)
{
    struct stat st;
    if (strcmp(arg, "-") != 0 && stat(arg, &st) == 0 && S_ISDIR(st.st_mode)) {
        const size_t first = in->count;
        struct dirent *e;
        DIR *d = opendir(arg);
        if (d == NULL) {
            return cli_error("%s: %s: %s", cmd, arg, strerror(errno));
        }
        while ((e = readdir(d)) != NULL) {
            if (is_frame_name(e->d_name) && add(in, arg, e->d_name) != 0) {
                closedir(d);
                return cli_error("%s: out of memory", cmd);
            }
        }
        closedir(d);
        if (in->count == first) {
            return cli_error("%s: %s: no .pgm, .png or .jpg images in this folder", cmd, arg);
        }
        qsort(in->paths + first, in->count - first, sizeof in->paths[0], cmp_path);
        in->from_folder = 1;
        return 0;
    }
    return add(in, NULL, arg) == 0 ? 0 : cli_error("%s: out of memory", cmd);
}

void cli_inputs_free(cli_inputs *in)
{
    size_t i;
    for (i = 0; i < in->count; i++) {
        free(in->paths[i]);
    }
    free(in->paths);
    memset(in, 0, sizeof *in);
}

int cli_image_write_failed(const char *err)
{
    if (errno == EPIPE) {
        return CLI_OK;
    }
    cli_error("%s", err);
    return CLI_FAIL;
}

int cli_write_failed(const char *what)
{
    if (errno == EPIPE) {
        return CLI_OK; /* the reader went away (`| head`): not an error */
    }
    cli_error("writing %s: %s", what, errno != 0 ? strerror(errno) : "write error");
    return CLI_FAIL;
}
