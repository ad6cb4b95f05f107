"""Polygons as GeoJSON (RFC 7946): shapely geometries (through
__geo_interface__), plain dicts and Features. Each expects the run an array
input of the same rings gives: the rings without their closing repeat,
bit-identical, the exterior first, the same triangles."""
import json

import numpy as np
import pytest
import shapely.affinity
import shapely.geometry

import compatmesh

PLATE = shapely.geometry.Polygon([(0, 0), (4, 0), (4, 3), (0, 3)],
                                 [[(1, 1), (1, 2), (2, 2), (2, 1)], [(3, 1.5), (3.5, 1), (3.5, 2)]])
BENT = shapely.affinity.skew(shapely.affinity.rotate(PLATE, 25, origin=(0, 0)), xs=10)


def rings(polygon):
    """The loops as the array input takes them: no closing repeat."""
    return [np.asarray(polygon.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in polygon.interiors]


def test_shapely_polygons_with_holes():
    result = compatmesh.triangulate([PLATE, BENT])
    plain = compatmesh.triangulate([rings(PLATE), rings(BENT)])
    assert result.stats["holes"] == 2 and result.stats["n"] == 11
    assert np.array_equal(result.faces, plain.faces)
    for g, polygon in enumerate((PLATE, BENT)):
        loops = np.vstack(rings(polygon))
        assert np.array_equal(result.vertices[g][:len(loops)], loops)
        assert np.array_equal(result.vertices[g], plain.vertices[g])
    # the format is this test's subject; the remesher reaches 13.3 degrees here
    assert min(q["min_angle_deg"] for q in result.quality) >= 10


def test_dicts_features_and_open_rings():
    """A dict and a Feature read as the shapely object; a ring left open
    (RFC 7946 wants it closed) is taken as it is."""
    feature = {"type": "Feature", "properties": {}, "geometry": PLATE.__geo_interface__}
    opened = {"type": "Polygon", "coordinates": [r.tolist() for r in rings(BENT)]}
    result = compatmesh.triangulate([feature, opened])
    reference = compatmesh.triangulate([PLATE, BENT])
    assert np.array_equal(result.faces, reference.faces)
    assert np.array_equal(result.vertices[1], reference.vertices[1])


def test_polygon_in_3d_keeps_z():
    a = shapely.geometry.Polygon([(0, 0, 2), (4, 0, 2), (4, 3, 2), (1, 4, 2), (0, 3, 2)])
    b = shapely.affinity.scale(a, 1.5, 0.8)
    result = compatmesh.triangulate([a, b])
    assert result.vertices[0].shape[1] == 3
    assert np.array_equal(result.vertices[0][:5], np.asarray(a.exterior.coords)[:-1])
    assert np.all(result.vertices[1][:, 2] == 2)


@pytest.mark.parametrize("bad, message", [
    (shapely.geometry.MultiPolygon([PLATE]), "polygon 0: a GeoJSON MultiPolygon; expected a Polygon (give a"),
    (shapely.geometry.LineString([(0, 0), (1, 1)]), "polygon 0: a GeoJSON LineString; expected a Polygon"),
    (shapely.geometry.Polygon(), "polygon 0: an empty GeoJSON Polygon"),
    ({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 0]]]}, "too few vertices"),
    ({"type": "Feature", "geometry": None, "properties": {}}, 'polygon 0: a Feature without a geometry'),
    ({"type": "Polygon"}, 'polygon 0: a GeoJSON object without "coordinates"'),
])
def test_other_geometries_refused(bad, message):
    with pytest.raises(ValueError) as info:
        compatmesh.triangulate([bad, bad])
    assert message in str(info.value) or message == getattr(info.value, "status", None)


def test_read_polygon_reads_geojson_files(tmp_path):
    """read_polygon takes .geojson and .json files as the command line does:
    a Polygon, or a FeatureCollection of one Feature; its rings as the
    array input takes them."""
    (tmp_path / "plate.geojson").write_text(json.dumps(shapely.geometry.mapping(PLATE)))
    collection = {"type": "FeatureCollection",
                  "features": [{"type": "Feature", "properties": {}, "geometry": shapely.geometry.mapping(BENT)}]}
    (tmp_path / "bent.json").write_text(json.dumps(collection))
    plate, bent = compatmesh.read_polygon(tmp_path / "plate.geojson"), compatmesh.read_polygon(tmp_path / "bent.json")
    for read, polygon in ((plate, PLATE), (bent, BENT)):
        assert len(read) == 3 and all(np.array_equal(a, b) for a, b in zip(read, rings(polygon)))
    assert np.array_equal(compatmesh.triangulate([plate, bent]).faces, compatmesh.triangulate([PLATE, BENT]).faces)


@pytest.mark.parametrize("text, message", [
    ('{"type": "Polygon",\n "coordinates": [[0, 0]\n', r"read_polygon: .*a\.geojson: .*line 3"),
    ('{"type": "FeatureCollection", "features": []}', r"a\.geojson: a FeatureCollection of 0 features"),
    ('{"type": "MultiPolygon", "coordinates": []}', r"a\.geojson: a GeoJSON MultiPolygon; expected a Polygon"),
])
def test_read_polygon_geojson_errors(tmp_path, text, message):
    (tmp_path / "a.geojson").write_text(text)
    with pytest.raises(ValueError, match=message):
        compatmesh.read_polygon(tmp_path / "a.geojson")
