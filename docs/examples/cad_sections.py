"""Two cross-sections drawn in CAD (Gmsh's OpenCASCADE kernel), their
boundaries meshed by Gmsh, paired by compatmesh and swept into a prism mesh
that Gmsh reads back: the path from CAD sections to a finite-element volume.

    PYTHONPATH=build/python /usr/bin/python3 docs/examples/cad_sections.py [DIR]

writes DIR/bracket.msh (without DIR, to a temporary folder removed at the
end). Sections from a STEP or IGES file go the same way: gmsh.open() the
file in place of drawing them, one surface per section."""
import sys
import tempfile
from pathlib import Path

import gmsh
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
    gmsh.finalize()
    print(len(determinants) // 6, "prisms in", out.name, "smallest Jacobian determinant %.3g" % min(determinants))
