"""Two cross-sections drawn in CAD (Gmsh's OpenCASCADE kernel), their
boundaries meshed by Gmsh, paired by compatmesh and swept into a prism mesh
that Gmsh reads back with its boundary's named surfaces, then solved by
CalculiX with second-order prisms and a pressure on the top: the path
from CAD sections to a finite-element analysis.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/cad_sections.py [DIR]

writes DIR/bracket.msh and DIR/bracket.inp (without DIR, to a temporary
folder removed at the end). Sections from a STEP or IGES file go the same
way: gmsh.open() the file in place of drawing them, one surface per
section."""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import gmsh
import numpy as np

import compatmesh


def section(name, width, height, radius, hole, hole_radius, size, folder):
    """A rounded plate with a bolt hole, its boundary meshed at `size`."""
    gmsh.model.add(name)
    plate = gmsh.model.occ.addRectangle(0, 0, 0, width, height, roundedRadius=radius)
    bolt = gmsh.model.occ.addDisk(hole[0], hole[1], 0, hole_radius, hole_radius)
    gmsh.model.occ.cut([(2, plate)], [(2, bolt)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.model.mesh.generate(1)
    path = Path(folder) / f"{name}.msh"
    gmsh.write(str(path))
    return compatmesh.read_polygon(path)  # outer loop first, then the hole


def loop_area(loop):
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


gmsh.initialize(["-noenv"])
gmsh.option.setNumber("General.Terminal", 0)
with tempfile.TemporaryDirectory() as folder:
    bottom = section("bottom", 40, 20, 4, (12, 10), 5, 2.0, folder)
    top = section("top", 30, 26, 8, (17, 13), 4, 1.6, folder)
    gmsh.finalize()
    print("loops:", [len(loop) for loop in bottom], "and", [len(loop) for loop in top], "vertices")

    # Different vertex counts: compatmesh chooses the correspondence.
    volume = compatmesh.sweep([bottom, top], heights=[0, 60], sections=13)
    print(volume.stats["correspondence_choice"], "correspondence,", volume.stats["steiner"], "Steiner vertices,",
          "smallest angle %.1f degrees" % min(q["min_angle_deg"] for q in volume.stats["quality"]))
    out = Path(sys.argv[1] if len(sys.argv) > 1 else folder) / "bracket.msh"
    volume.write(out)

    # Read back by Gmsh: the Jacobian determinant at every prism's corners.
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(str(out))
    corners = [0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1]
    _, determinants, _ = gmsh.model.mesh.getJacobians(6, corners)
    # The boundary's named surfaces, where boundary conditions go.
    faces = {}
    for dim, tag in gmsh.model.getPhysicalGroups(2):
        (entity,) = gmsh.model.getEntitiesForPhysicalGroup(dim, tag)
        faces[gmsh.model.getPhysicalName(dim, tag)] = sum(len(t) for t in gmsh.model.mesh.getElements(dim, entity)[1])
    gmsh.finalize()
    print(len(determinants) // 6, "prisms in", out.name, "smallest Jacobian determinant %.3g" % min(determinants))
    print("boundary:", ", ".join(f"{name} {count} faces" for name, count in faces.items()))

    # A static analysis by CalculiX (Abaqus input): second-order prisms
    # (C3D15), steel in mm and N, the bottom fixed (the node set "bottom"),
    # the top pressed by 100 MPa (the element-face surface "top"); the
    # bottom's reaction against the pressure times the top's area.
    deck = out.with_suffix(".inp")
    volume.write(deck, order=2)
    job = out.with_name("bracket_job.inp")
    job.write_text(f"*INCLUDE, INPUT={deck.name}\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n"
                   "*SOLID SECTION, ELSET=sweep, MATERIAL=STEEL\n*STEP\n*STATIC\n*BOUNDARY\nbottom, 1, 3\n"
                   "*DSLOAD\ntop, P, 100\n*NODE PRINT, NSET=bottom, TOTALS=ONLY\nRF\n*END STEP\n")
    subprocess.run(["ccx", "-i", job.stem], cwd=job.parent, check=True, capture_output=True)
    totals = re.search(r"total force \(fx,fy,fz\) for set BOTTOM.*\n\s*\n\s*(\S+)\s+(\S+)\s+(\S+)",
                       job.with_suffix(".dat").read_text())
    area = loop_area(top[0]) - sum(loop_area(hole) for hole in top[1:])
    print("CalculiX: the bottom holds %.6g kN against 100 MPa on %.6g mm2" % (float(totals[3]) / 1000, area))
