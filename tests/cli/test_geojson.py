"""Polygons as GeoJSON files (RFC 7946: a Polygon, a Feature, or a
FeatureCollection of one Feature), as QGIS, GDAL and shapely write them:
the run is byte-identical to the one on the same loops as .xy; a file that
is not one Polygon is a one-line error naming the file and the place (the
JSON line, or coordinates[ring][position]), and nothing is written."""
import json
import re

import pytest

from test_holes import DISC_WITH_HOLE, SQUARE_WITH_HOLE, check_output, xy_text


def polygon(loops, z=None):
    """A GeoJSON Polygon: every ring closed, as RFC 7946 wants."""
    return {"type": "Polygon",
            "coordinates": [[[x, y] if z is None else [x, y, z] for x, y in loop + loop[:1]] for loop in loops]}


def feature_collection(geometry):
    return {"type": "FeatureCollection",
            "features": [{"type": "Feature", "properties": {"name": "section"}, "geometry": geometry}]}


def test_same_run_as_xy(cm, tmp_path):
    (tmp_path / "a.geojson").write_text(json.dumps(polygon(SQUARE_WITH_HOLE)))
    (tmp_path / "b.json").write_text(json.dumps(feature_collection(polygon(DISC_WITH_HOLE)), indent=2))
    result = cm("triangulate", "a.geojson", "b.json", "--out-dir", "out")
    assert result.returncode == 0, result.stderr
    check_output(tmp_path / "out", ["a", "b"], [SQUARE_WITH_HOLE, DISC_WITH_HOLE], 1)
    (tmp_path / "a.xy").write_text(xy_text(SQUARE_WITH_HOLE))
    (tmp_path / "b.xy").write_text(xy_text(DISC_WITH_HOLE))
    plain = cm("triangulate", "a.xy", "b.xy", "--out-dir", "plain")
    assert plain.returncode == 0, plain.stderr
    for name in ("a.off", "b.off"):
        assert (tmp_path / "out" / name).read_bytes() == (tmp_path / "plain" / name).read_bytes()


def test_z_gives_the_sweep_heights(cm, tmp_path):
    """Positions [x, y, z] with z the same throughout place the section."""
    (tmp_path / "a.geojson").write_text(json.dumps(polygon(SQUARE_WITH_HOLE, z=1.5)))
    (tmp_path / "b.geojson").write_text(json.dumps(polygon(DISC_WITH_HOLE, z=4.0)))
    result = cm("sweep", "a.geojson", "b.geojson", "--out", "v.vtu")
    assert result.returncode == 0, result.stderr
    import meshio
    z = meshio.read(tmp_path / "v.vtu").points[:, 2]
    assert (z.min(), z.max()) == (1.5, 4.0)


ERRORS = {
    "not json": ('{"type": "Polygon",\n "coordinates": [[0, 0]\n', r"a\.geojson:3: "),
    "not geojson": ('[1, 2]', r"a\.geojson: not GeoJSON \(no \"type\" member\); expected a Polygon"),
    "multipolygon": (json.dumps({"type": "MultiPolygon", "coordinates": [polygon(SQUARE_WITH_HOLE)["coordinates"]]}),
                     r"a\.geojson: a GeoJSON MultiPolygon; expected a Polygon \(write each of its polygons"),
    "two features": (json.dumps({"type": "FeatureCollection", "features": [feature_collection(None)["features"][0]] * 2}),
                     r"a\.geojson: a FeatureCollection of 2 features; expected exactly one"),
    "feature without geometry": (json.dumps(feature_collection(None)), r"a\.geojson: a Feature without a geometry"),
    "position": (json.dumps({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, "1"], [0, 0]]]}),
                 r"a\.geojson: coordinates\[0\]\[2\]: expected a position \[x, y\] or \[x, y, z\]"),
    "four numbers": (json.dumps({"type": "Polygon", "coordinates": [[[0, 0, 0, 0], [1, 0], [1, 1], [0, 0]]]}),
                     r"a\.geojson: coordinates\[0\]\[0\]: expected a position"),
    "short ring": (json.dumps({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]], [[0.5, 0.2], [0.6, 0.3], [0.5, 0.2]]]}),
                   r"a\.geojson: coordinates\[1\]: a ring of 3 positions; GeoJSON rings have at least 4"),
    "z not constant": (json.dumps({"type": "Polygon", "coordinates": [[[0, 0, 2], [1, 0, 2], [1, 1, 5], [0, 1, 2]]]}),
                       r"a\.geojson: vertex 2: z = 5 differs from z = 2 of vertex 0"),
    "duplicate key": ('{"type": "Polygon", "type": "Point", "coordinates": []}', r"a\.geojson:1: duplicate object key"),
    "type with a newline": (json.dumps({"type": "Poly\ngon", "coordinates": []}),
                            r"a\.geojson: a GeoJSON Poly\\x0Agon; expected a Polygon$"),
    "raw newline after a backslash": ('{"type": "Poly\\\n', r"a\.geojson:\d+: .*\\x0A"),
    "self-intersecting": (json.dumps({"type": "Polygon", "coordinates": [[[0, 0], [1, 1], [1, 0], [0, 1], [0, 0]]]}),
                          r"a\.geojson: vertex \d: .*cross or touch"),
}


@pytest.mark.parametrize("name", ERRORS)
def test_errors(cm, tmp_path, name):
    text, pattern = ERRORS[name]
    (tmp_path / "a.geojson").write_text(text)
    (tmp_path / "b.xy").write_text("0 0\n1 0\n1 1\n0 1\n")
    result = cm("triangulate", "a.geojson", "b.xy", "--out-dir", "out")
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and re.search(pattern, lines[0]), result.stderr
    assert not (tmp_path / "out").exists()
