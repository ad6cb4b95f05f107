#define _POSIX_C_SOURCE 200809L /* mkdtemp, strdup */

#include "outdir.h"
#include "interrupt.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

char *path_join(const char *dir, const char *name)
{
    size_t dir_length = strlen(dir), name_length = strlen(name);
    char *path = malloc(dir_length + name_length + 2);
    if (!path) return NULL;
    memcpy(path, dir, dir_length);
    path[dir_length] = '/';
    memcpy(path + dir_length + 1, name, name_length + 1);
    return path;
}

/* target without trailing slashes ("out///" -> "out", "/" stays "/"). */
static char *trim_trailing_slashes(const char *target)
{
    char *trimmed = strdup(target);
    if (!trimmed) return NULL;
    size_t length = strlen(trimmed);
    while (length > 1 && trimmed[length - 1] == '/') trimmed[--length] = '\0';
    return trimmed;
}

/* The directory holding `path` (already trimmed): "a/b" -> "a", "b" -> ".",
 * "/b" -> "/". The base name starts at *base_offset. */
static char *parent_directory(const char *path, size_t *base_offset)
{
    const char *slash = strrchr(path, '/');
    if (!slash) {
        *base_offset = 0;
        return strdup(".");
    }
    *base_offset = (size_t)(slash - path) + 1;
    if (slash == path) return strdup("/");
    char *parent = malloc((size_t)(slash - path) + 1);
    if (!parent) return NULL;
    memcpy(parent, path, (size_t)(slash - path));
    parent[slash - path] = '\0';
    return parent;
}

static int check_writable_directory(const char *dir, const char *target,
                                    cli_error *error)
{
    struct stat info;
    if (stat(dir, &info) != 0) {
        cli_error_set(error, "cannot create output directory %s: %s: %s", target,
                      dir, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    if (!S_ISDIR(info.st_mode)) {
        cli_error_set(error, "cannot create output directory %s: %s is not a directory",
                      target, dir);
        return CLI_EXIT_INTERNAL;
    }
    if (access(dir, W_OK | X_OK) != 0) {
        cli_error_set(error, "cannot write to %s: %s", dir, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

int staged_output_check(const char *target, cli_error *error)
{
    if (target[0] == '\0') {
        cli_error_set(error, "--out-dir: the directory name is empty");
        return CLI_EXIT_USAGE;
    }
    struct stat info;
    if (stat(target, &info) == 0) {
        if (!S_ISDIR(info.st_mode)) {
            cli_error_set(error, "--out-dir: %s exists and is not a directory", target);
            return CLI_EXIT_USAGE;
        }
        return check_writable_directory(target, target, error);
    }
    /* The target is created on commit, so its parent must take new entries. */
    char *trimmed = trim_trailing_slashes(target);
    size_t base_offset;
    char *parent = trimmed ? parent_directory(trimmed, &base_offset) : NULL;
    int code = CLI_EXIT_INTERNAL;
    if (parent) code = check_writable_directory(parent, target, error);
    else cli_error_set(error, "out of memory");
    free(parent);
    free(trimmed);
    return code;
}

/* ".", the name, ".compatmesh-XXXXXX": 19 characters besides the name. */
#define STAGING_BASE_MAX (NAME_MAX - 19)

int staged_output_begin(staged_output *out, const char *target, const char *const *inputs,
                        size_t input_count, cli_error *error)
{
    memset(out, 0, sizeof *out);
    char *trimmed = trim_trailing_slashes(target);
    size_t base_offset = 0;
    char *parent = trimmed ? parent_directory(trimmed, &base_offset) : NULL;
    char *staging = NULL;
    struct stat info;
    if (trimmed && stat(trimmed, &info) == 0 && S_ISDIR(info.st_mode)) {
        /* An existing target may be a mount point, on another file system
         * than its parent: stage inside it so the renames stay local. */
        free(parent);
        parent = NULL;
        size_t size = strlen(trimmed) + 32;
        staging = malloc(size);
        if (staging) snprintf(staging, size, "%s/.compatmesh-XXXXXX", trimmed);
    } else if (parent) {
        /* Hidden, and named after the target so a leftover is recognisable;
         * the target's name cut so the whole stays within NAME_MAX. */
        const char *base = trimmed + base_offset;
        int keep = (int)(strlen(base) < STAGING_BASE_MAX ? strlen(base) : STAGING_BASE_MAX);
        size_t size = strlen(parent) + (size_t)keep + 32;
        staging = malloc(size);
        if (staging) snprintf(staging, size, "%s/.%.*s.compatmesh-XXXXXX", parent, keep, base);
    }
    free(parent);
    if (!staging) {
        free(trimmed);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    writing_output = 1; /* the staging directory exists from here on */
    if (!mkdtemp(staging)) {
        writing_output = 0;
        cli_error_set(error, "cannot create a temporary directory in or beside %s: %s",
                      target, strerror(errno));
        free(staging);
        free(trimmed);
        return CLI_EXIT_INTERNAL;
    }
    out->target = trimmed;
    out->staging = staging;
    out->inputs = inputs;
    out->input_count = input_count;
    return CLI_EXIT_OK;
}

const char *staged_output_path(staged_output *out, const char *name)
{
    char **names = realloc(out->names, (out->count + 1) * sizeof *names);
    if (!names) return NULL;
    out->names = names;
    char **paths = realloc(out->paths, (out->count + 1) * sizeof *paths);
    if (!paths) return NULL;
    out->paths = paths;
    char *copy = strdup(name);
    char *path = path_join(out->staging, name);
    if (!copy || !path) {
        free(copy);
        free(path);
        return NULL;
    }
    names[out->count] = copy;
    paths[out->count] = path;
    out->count++;
    return path;
}

void staged_output_remove(staged_output *out, const char *const *names, size_t count)
{
    out->removed = names, out->removed_count = count;
}

/* Removes out->removed from target (a directory of that name is not ours
 * and stays); after the manifest is gone, before the new files move in. */
static int remove_old(const staged_output *out, cli_error *error)
{
    for (size_t i = 0; i < out->removed_count; i++) {
        char *old = path_join(out->target, out->removed[i]);
        if (!old) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        struct stat info;
        int failed = lstat(old, &info) == 0 && !S_ISDIR(info.st_mode) && unlink(old) != 0;
        if (failed) cli_error_set(error, "cannot remove the old %s: %s", old, strerror(errno));
        free(old);
        if (failed) return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

/* A new target: the whole temporary directory becomes it in one rename.
 * mkdtemp made it private (0700); give it the mode mkdir would have. */
static int commit_as_new_directory(staged_output *out, cli_error *error)
{
    mode_t mask = umask(0);
    umask(mask);
    if (chmod(out->staging, 0777 & ~mask) != 0 || rename(out->staging, out->target) != 0) {
        cli_error_set(error, "cannot create %s: %s", out->target, strerror(errno));
        return CLI_EXIT_INTERNAL;
    }
    free(out->staging);
    out->staging = NULL;
    return CLI_EXIT_OK;
}

#define MANIFEST "report.json"

static int move_in(const staged_output *out, size_t i, const char *final, cli_error *error)
{
    if (rename(out->paths[i], final) == 0) return CLI_EXIT_OK;
    cli_error_set(error, "cannot move %s into %s: %s", out->names[i], out->target, strerror(errno));
    return CLI_EXIT_INTERNAL;
}

/* An existing target: move the files in one by one. Any obstacle that can be
 * seen in advance (a directory where a file goes) is checked before the first
 * move, so a failure leaves the target untouched. */
static int commit_into_existing_directory(staged_output *out, cli_error *error)
{
    int code = CLI_EXIT_OK;
    char **finals = calloc(out->count ? out->count : 1, sizeof *finals);
    if (!finals) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t i = 0; i < out->count && code == CLI_EXIT_OK; i++) {
        struct stat info;
        finals[i] = path_join(out->target, out->names[i]);
        if (!finals[i]) {
            cli_error_set(error, "out of memory");
            code = CLI_EXIT_INTERNAL;
        } else if (stat(finals[i], &info) == 0 && S_ISDIR(info.st_mode)) {
            cli_error_set(error, "cannot replace %s: it is a directory", finals[i]);
            code = CLI_EXIT_INTERNAL;
        }
    }
    for (size_t i = 0; i < out->count && code == CLI_EXIT_OK; i++)
        code = refuse_input_as_output(finals[i], out->inputs, out->input_count, error);
    for (size_t i = 0; i < out->removed_count && code == CLI_EXIT_OK; i++) {
        char *old = path_join(out->target, out->removed[i]);
        code = old ? refuse_input_as_output(old, out->inputs, out->input_count, error) : CLI_EXIT_INTERNAL;
        if (!old) cli_error_set(error, "out of memory");
        free(old);
    }
    /* The manifest goes first and comes back last. */
    size_t manifest = out->count;
    for (size_t i = 0; i < out->count; i++)
        if (strcmp(out->names[i], MANIFEST) == 0) manifest = i;
    if (code == CLI_EXIT_OK && manifest < out->count && unlink(finals[manifest]) != 0 && errno != ENOENT) {
        cli_error_set(error, "cannot replace %s: %s", finals[manifest], strerror(errno));
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) code = remove_old(out, error);
    for (size_t i = 0; i < out->count && code == CLI_EXIT_OK; i++)
        if (i != manifest) code = move_in(out, i, finals[i], error);
    if (code == CLI_EXIT_OK && manifest < out->count) code = move_in(out, manifest, finals[manifest], error);
    for (size_t i = 0; i < out->count; i++) free(finals[i]);
    free(finals);
    return code;
}

int staged_output_commit(staged_output *out, cli_error *error)
{
    if (interrupted) { /* a signal while the files were written: none is moved */
        cli_error_set(error, "interrupted; nothing written");
        return CLI_EXIT_INTERRUPTED;
    }
    struct stat info;
    if (stat(out->target, &info) != 0) {
        if (errno != ENOENT) {
            cli_error_set(error, "cannot use %s: %s", out->target, strerror(errno));
            return CLI_EXIT_INTERNAL;
        }
        return commit_as_new_directory(out, error);
    }
    if (!S_ISDIR(info.st_mode)) {
        cli_error_set(error, "--out-dir: %s exists and is not a directory", out->target);
        return CLI_EXIT_INTERNAL;
    }
    return commit_into_existing_directory(out, error);
}

void staged_output_discard(staged_output *out)
{
    if (out->staging) {
        /* Only files this run asked for can be in there. */
        for (size_t i = 0; i < out->count; i++) unlink(out->paths[i]);
        rmdir(out->staging);
    }
    for (size_t i = 0; i < out->count; i++) {
        free(out->names[i]);
        free(out->paths[i]);
    }
    free(out->names);
    free(out->paths);
    free(out->staging);
    free(out->target);
    memset(out, 0, sizeof *out);
    writing_output = 0;
}

FILE *output_open(const char *path, cli_error *error)
{
    FILE *file = fopen(path, "w");
    if (!file) cli_error_set(error, "cannot create %s: %s", path, strerror(errno));
    return file;
}

int output_close(FILE *file, const char *path, cli_error *error)
{
    int failed = ferror(file);
    int saved_errno = errno;
    if (fclose(file) != 0 && !failed) {
        failed = 1;
        saved_errno = errno;
    }
    if (failed) {
        cli_error_set(error, "cannot write %s: %s", path,
                      strerror(saved_errno ? saved_errno : EIO));
        return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_OK;
}

int refuse_input_as_output(const char *path, const char *const *inputs, size_t count,
                           cli_error *error)
{
    struct stat out_info, in_info;
    if (stat(path, &out_info) != 0) return CLI_EXIT_OK;
    for (size_t i = 0; i < count; i++)
        if (stat(inputs[i], &in_info) == 0 && in_info.st_dev == out_info.st_dev &&
            in_info.st_ino == out_info.st_ino) {
            cli_error_set(error, "%s would replace the input %s; choose another output", path,
                          inputs[i]);
            return CLI_EXIT_USAGE;
        }
    return CLI_EXIT_OK;
}
