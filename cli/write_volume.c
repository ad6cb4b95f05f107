#define _DEFAULT_SOURCE /* mkstemps */

#include "write_volume.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "abaqus_sets.h"
#include "interrupt.h"
#include "write_vtu.h"

#ifdef CM_HAVE_GMSH
#include "gmsh_volume.h"
#endif

static const char *const extensions[] = {"msh", "vtk", "vtu", "inp", "bdf", "unv"};

static const char *extension_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash + 1) ? dot + 1 : NULL;
}

int volume_extension_known(const char *path)
{
    const char *extension = extension_of(path);
    for (size_t i = 0; extension && i < sizeof extensions / sizeof extensions[0]; i++)
        if (strcasecmp(extension, extensions[i]) == 0) return 0;
    return -1;
}

#ifndef CM_HAVE_GMSH

int volume_writer_available(void) { return 0; }

static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           double msh_version, cli_error *error)
{
    (void)temporary, (void)mesh, (void)msh_version;
    cli_error_set(error, "cannot write %s: this compatmesh was built without Gmsh "
                  "(libgmsh-dev, CMake option CM_WITH_GMSH); .vtu needs no Gmsh", path);
    return CLI_EXIT_INTERNAL;
}

#else

int volume_writer_available(void) { return 1; }

/* Writes mesh to temporary through Gmsh, the format by its extension. */
static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           double msh_version, cli_error *error)
{
    /* Gmsh may install its own signal handlers; ours leave no file. */
    gmsh_write_options options = {msh_version, 0, catch_interrupts};
    char message[512];
    int failed = gmsh_write_volume(temporary, mesh, &options, message, sizeof message);
    catch_interrupts();
    if (!failed) return CLI_EXIT_OK;
    cli_error_set(error, "cannot write %s: %s", path, message);
    return CLI_EXIT_INTERNAL;
}

#endif

/* "dir/name.EXT" -> "dir/.name.compatmesh-XXXXXX.ext", created empty (so
 * the name is ours) in the target's directory, so rename is atomic. */
static char *make_temporary(const char *path, cli_error *error)
{
    const char *slash = strrchr(path, '/');
    size_t dir_length = slash ? (size_t)(slash - path) + 1 : 0;
    const char *name = path + dir_length;
    const char *extension = extension_of(path);
    size_t stem_length = (size_t)(extension - 1 - name);
    size_t size = strlen(path) + 32;
    char *temporary = malloc(size);
    if (!temporary) {
        cli_error_set(error, "out of memory");
        return NULL;
    }
    int length = snprintf(temporary, size, "%.*s.%.*s.compatmesh-XXXXXX.%s",
                          (int)dir_length, path, (int)stem_length, name, extension);
    /* Gmsh knows the extensions in lower case only; the final name keeps
     * the user's spelling. */
    for (char *c = temporary + length - strlen(extension); *c; c++) *c = (char)tolower(*c);
    int fd = mkstemps(temporary, (int)strlen(extension) + 1);
    if (fd < 0) {
        cli_error_set(error, "cannot write %s: %s", path, strerror(errno));
        free(temporary);
        return NULL;
    }
    /* mkstemps makes the file private; give it the mode a new file gets. */
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
    return temporary;
}

/* The temporary file's text (malloc'd, NUL-terminated; *size its length),
 * or NULL. */
static char *read_text(const char *temporary, size_t *size)
{
    FILE *file = fopen(temporary, "rb");
    char *text = NULL;
    long length = -1;
    if (file && fseek(file, 0, SEEK_END) == 0) length = ftell(file);
    if (length >= 0 && fseek(file, 0, SEEK_SET) == 0 && (text = malloc((size_t)length + 1)) &&
        fread(text, 1, (size_t)length, file) == (size_t)length) {
        text[length] = '\0';
        *size = (size_t)length;
    } else {
        free(text);
        text = NULL;
    }
    if (file) fclose(file);
    return text;
}

/* Rewrites the temporary file with text[at, at + drop) replaced by insert. */
static int splice(const char *temporary, const char *path, size_t at, size_t drop, const char *insert,
                  cli_error *error)
{
    size_t size = 0;
    char *text = read_text(temporary, &size);
    int code = CLI_EXIT_INTERNAL;
    if (text && at + drop <= size) {
        FILE *file = fopen(temporary, "wb");
        if (file && fwrite(text, 1, at, file) == at && fputs(insert, file) >= 0 &&
            fwrite(text + at + drop, 1, size - at - drop, file) == size - at - drop)
            code = CLI_EXIT_OK;
        if (file && fclose(file) != 0) code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) cli_error_set(error, "cannot write %s: %s", path, strerror(errno ? errno : EIO));
    free(text);
    return code;
}

/* Gmsh writes Nastran bulk data without the BEGIN BULK line that readers
 * (meshio among them) look for: inserted after the leading comments. */
static int add_begin_bulk(const char *temporary, const char *path, cli_error *error)
{
    size_t size = 0, head = 0; /* the "$" comment lines */
    char *text = read_text(temporary, &size);
    while (text && text[head] == '$') {
        const char *end = strchr(text + head, '\n');
        head = end ? (size_t)(end - text) + 1 : size;
    }
    free(text);
    return splice(temporary, path, head, 0, "BEGIN BULK\n", error);
}

/* Gmsh titles an Abaqus deck with the name of the file it wrote, here
 * the temporary one: the title becomes the output's own name, so that
 * the same sweep gives the same deck. */
static int name_heading(const char *temporary, const char *path, cli_error *error)
{
    static const char heading[] = "*Heading\n";
    size_t size = 0, length = 0;
    char *text = read_text(temporary, &size);
    const char *end = text && strncmp(text, heading, sizeof heading - 1) == 0 ? strchr(text + sizeof heading - 1, '\n')
                                                                               : NULL;
    if (end) length = (size_t)(end - text) + 1 - (sizeof heading - 1);
    free(text);
    if (!end) return CLI_EXIT_OK; /* no title to fix */
    const char *slash = strrchr(path, '/');
    const char *name = slash ? slash + 1 : path;
    char *title = malloc(strlen(name) + 3);
    if (!title) {
        cli_error_set(error, "cannot write %s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    sprintf(title, " %s\n", name);
    int code = splice(temporary, path, sizeof heading - 1, length, title, error);
    free(title);
    return code;
}

/* The boundary groups appended to an Abaqus deck (abaqus_sets.h). */
static int add_boundary_sets(const char *temporary, const char *path, const volume_mesh *mesh, cli_error *error)
{
    FILE *file = fopen(temporary, "ab");
    int ok = file && abaqus_write_sets(file, mesh) == 0;
    if (file && fclose(file) != 0) ok = 0;
    if (!ok) cli_error_set(error, "cannot write %s: %s", path, strerror(errno ? errno : EIO));
    return ok ? CLI_EXIT_OK : CLI_EXIT_INTERNAL;
}

int write_volume(const char *path, const volume_mesh *mesh, double msh_version,
                 cli_error *error)
{
    writing_output = 1; /* the temporary file exists until the rename */
    char *temporary = make_temporary(path, error);
    if (!temporary) {
        writing_output = 0;
        return CLI_EXIT_INTERNAL;
    }
    const char *extension = extension_of(path);
    int code = strcasecmp(extension, "vtu") == 0 ? write_vtu(temporary, path, mesh, error)
                                                 : write_with_gmsh(temporary, path, mesh, msh_version, error);
    if (code == CLI_EXIT_OK && strcasecmp(extension, "bdf") == 0) code = add_begin_bulk(temporary, path, error);
    if (code == CLI_EXIT_OK && strcasecmp(extension, "inp") == 0) code = name_heading(temporary, path, error);
    if (code == CLI_EXIT_OK && strcasecmp(extension, "inp") == 0 && mesh->num_faces)
        code = add_boundary_sets(temporary, path, mesh, error);
    if (code == CLI_EXIT_OK && interrupted) {
        cli_error_set(error, "interrupted; nothing written");
        code = CLI_EXIT_INTERRUPTED;
    }
    if (code == CLI_EXIT_OK && rename(temporary, path) != 0) {
        cli_error_set(error, "cannot write %s: %s", path, strerror(errno));
        code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) unlink(temporary);
    writing_output = 0;
    free(temporary);
    return code;
}
