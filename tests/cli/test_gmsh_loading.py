"""Gmsh (about seventy shared libraries: OpenCascade, FLTK, GL) is loaded
only when `sweep` writes a format Gmsh writes: triangulate, morph and a
.vtu sweep never map it. Without it, such a sweep fails with one line and
leaves no file."""
import os
import re
import subprocess

import pytest

from polygons import leftovers, twisted_pair, write_xy

# Makes the dynamic loader look for Gmsh's library where it is not, so
# dlopen fails as it does on a system without it, with the loader's own
# message.
NO_GMSH_SHIM = r"""
#define _GNU_SOURCE
#include <dlfcn.h>
#include <string.h>

void *dlopen(const char *file, int mode)
{
    void *(*real)(const char *, int) = (void *(*)(const char *, int))dlsym(RTLD_NEXT, "dlopen");
    if (file && strstr(file, "libgmsh")) file = "/nonexistent/libgmsh.so";
    return real(file, mode);
}
"""


def run(compatmesh_path, tmp_path, *args, env=None):
    return subprocess.run([compatmesh_path, *map(str, args)], cwd=tmp_path, capture_output=True,
                          timeout=120, encoding="utf-8", errors="replace",
                          env={**os.environ, **(env or {})})


@pytest.fixture
def pair(tmp_path):
    a, b = twisted_pair()
    write_xy(tmp_path / "a.xy", a)
    write_xy(tmp_path / "b.xy", b)
    return ["a.xy", "b.xy"]


COMMANDS = {
    "triangulate": (["triangulate", "-o", "tri"], False),
    "morph": (["morph", "-o", "frames", "-n", "3"], False),
    "sweep_vtu": (["sweep", "-o", "out.vtu", "--sections", "3"], False),
    "sweep_msh": (["sweep", "-o", "out.msh", "--sections", "3"], True),
}


@pytest.mark.parametrize("name", COMMANDS)
def test_gmsh_loaded_only_to_write_its_formats(compatmesh_path, tmp_path, pair, name):
    words, loads_gmsh = COMMANDS[name]
    # LD_DEBUG=files: the loader reports every library it maps, on stderr.
    result = run(compatmesh_path, tmp_path, words[0], *pair, *words[1:], env={"LD_DEBUG": "files"})
    assert result.returncode == 0, result.stderr[-2000:]
    mapped = set(re.findall(r"file=(\S+) \[0\];  generating link map", result.stderr))
    assert mapped, "LD_DEBUG=files printed no library"
    assert any("libgmsh" in library for library in mapped) == loads_gmsh, sorted(mapped)
    # Nor any of Gmsh's own dependencies before it is needed.
    if not loads_gmsh:
        heavy = [library for library in mapped if re.match(r"libTK|libfltk|libGL|libOpenGL|libocc", library)]
        assert heavy == [], heavy


def test_missing_gmsh_is_one_line_and_no_file(compatmesh_path, tmp_path, pair):
    shim_source = tmp_path / "no_gmsh.c"
    shim_source.write_text(NO_GMSH_SHIM)
    shim = tmp_path / "no_gmsh.so"
    subprocess.run(["cc", "-shared", "-fPIC", "-o", str(shim), str(shim_source), "-ldl"], check=True)
    env = {"LD_PRELOAD": str(shim)}
    result = run(compatmesh_path, tmp_path, "sweep", *pair, "-o", "out.msh", "--sections", "3", env=env)
    assert result.returncode == 1
    assert re.fullmatch(r"compatmesh: cannot write out\.msh: Gmsh could not be loaded "
                        r"\(/nonexistent/libgmsh\.so: cannot open shared object file: No such file or directory\)\n",
                        result.stderr), result.stderr
    assert result.stdout == ""
    assert not (tmp_path / "out.msh").exists()
    assert leftovers(tmp_path) == []
    # The formats of the tool's own need no Gmsh.
    result = run(compatmesh_path, tmp_path, "sweep", *pair, "-o", "out.vtu", "--sections", "3", env=env)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "out.vtu").stat().st_size > 0
