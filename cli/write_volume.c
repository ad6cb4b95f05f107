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

#include "interrupt.h"
#include "write_vtu.h"

#ifdef CM_HAVE_GMSH
#include "gmsh_volume.h"
#endif

static const char *const extensions[] = {"msh", "vtk", "vtu", "inp", "bdf", "unv"};

const char *volume_extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash + 1) ? dot + 1 : NULL;
}

int volume_extension_known(const char *path)
{
    const char *extension = volume_extension(path);
    for (size_t i = 0; extension && i < sizeof extensions / sizeof extensions[0]; i++)
        if (strcasecmp(extension, extensions[i]) == 0) return 0;
    return -1;
}

#ifndef CM_HAVE_GMSH

int volume_writer_available(void) { return 0; }

static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           const volume_format *format, cli_error *error)
{
    (void)temporary, (void)mesh, (void)format;
    cli_error_set(error, "cannot write %s: this compatmesh was built without Gmsh "
                  "(libgmsh-dev, CMake option CM_WITH_GMSH); .vtu needs no Gmsh", path);
    return CLI_EXIT_INTERNAL;
}

#else

int volume_writer_available(void) { return 1; }

/* Writes mesh to temporary through Gmsh, the format by its extension, an
 * Abaqus deck titled with path's own name. */
static int write_with_gmsh(const char *temporary, const char *path, const volume_mesh *mesh,
                           const volume_format *format, cli_error *error)
{
    const char *slash = strrchr(path, '/');
    /* Gmsh may install its own signal handlers; ours leave no file. */
    gmsh_write_options options = {format->msh_version, 0, catch_interrupts, format->order, slash ? slash + 1 : path};
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
    const char *extension = volume_extension(path);
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

int write_volume(const char *path, const volume_mesh *mesh, const volume_format *format, cli_error *error)
{
    const char *extension = volume_extension(path);
    writing_output = 1; /* the temporary file exists until the rename */
    char *temporary = make_temporary(path, error);
    if (!temporary) {
        writing_output = 0;
        return CLI_EXIT_INTERNAL;
    }
    output_temporary = temporary;
    int code = strcasecmp(extension, "vtu") == 0 ? write_vtu(temporary, path, mesh, error)
                                                 : write_with_gmsh(temporary, path, mesh, format, error);
    output_temporary = NULL;
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
